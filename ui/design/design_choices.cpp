#include "design/design_choices.h"

#include <QList>
#include <QSettings>
#include <cmath>

namespace linkage::ui {

namespace {
const QString kLo = QStringLiteral("design/bandLo");
const QString kHi = QStringLiteral("design/bandHi");

// Every window's choices: the band is the user's, not a document's, so a change in one window
// shows in all (as it would after a restart, from QSettings).
QList<DesignChoices*>& everyChoices() {
  static QList<DesignChoices*> all;
  return all;
}

bool validBand(const TransmissionBand& b) {
  return std::isfinite(b.lo) && std::isfinite(b.hi) && b.lo >= 0 && b.lo < b.hi && b.hi <= 180;
}
}  // namespace

DesignChoices::DesignChoices(QObject* parent) : QObject(parent) {
  QSettings s;
  const TransmissionBand b{s.value(kLo, band_.lo).toDouble(), s.value(kHi, band_.hi).toDouble()};
  if (validBand(b)) band_ = b;
  everyChoices().append(this);
}

DesignChoices::~DesignChoices() {
  everyChoices().removeOne(this);
}

bool DesignChoices::setBand(const TransmissionBand& b) {
  if (!validBand(b)) return false;
  if (b.lo == band_.lo && b.hi == band_.hi) return true;
  QSettings s;
  s.setValue(kLo, b.lo);
  s.setValue(kHi, b.hi);
  for (DesignChoices* c : everyChoices()) {
    if (c->band_.lo == b.lo && c->band_.hi == b.hi) continue;
    c->band_ = b;
    emit c->bandChanged();
  }
  return true;
}

void DesignChoices::setSubject(const LimitSubject& s) {
  if (s == subject_) return;
  subject_ = s;
  emit subjectChanged();
}

std::optional<LimitMeasure> DesignChoices::measure(const Mechanism& m) const {
  if (!subject_.point.isEmpty()) {
    if (std::optional<PointId> p = m.findPoint(subject_.point.toStdString())) {
      const Vec2 d = subject_.direction.value_or(defaultDirection(m, *p));
      if (!d.allFinite() || d.norm() == 0) return std::nullopt;
      return LimitMeasure::along(*p, d);  // findLimits makes it a unit vector
    }
  } else if (!subject_.body.isEmpty()) {
    if (const Body* b = m.bodyNamed(subject_.body.toStdString()))
      return LimitMeasure::angleOf(b->id);
  }
  if (m.outputs.empty() || !m.contains(m.outputs.front())) return std::nullopt;
  return LimitMeasure::along(m.outputs.front(), defaultDirection(m, m.outputs.front()));
}

QString DesignChoices::describe(const Mechanism& m) const {
  const std::optional<LimitMeasure> what = measure(m);
  if (!what) return tr("no point chosen");
  if (what->body) return tr("%1 angle").arg(QString::fromStdString(m.body(what->body)->name));
  return tr("%1 along (%2, %3)")
      .arg(QString::fromStdString(m.pointLabel(what->point)))
      .arg(what->direction.x(), 0, 'g', 4)
      .arg(what->direction.y(), 0, 'g', 4);
}

}  // namespace linkage::ui
