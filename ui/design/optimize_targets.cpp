#include "design/optimize_targets.h"

#include <QComboBox>
#include <QHeaderView>
#include <cmath>

#include "document/document.h"
#include "linkage/force_sensitivity.h"
#include "linkage/limits.h"
#include "linkage/optimize_text.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/transmission.h"

namespace linkage::ui {

namespace {

using K = OptTarget::Kind;

// In OptTarget::Kind's order (a kind is its index here).
const char* const kKinds[] = {"stroke",  "position",  "path",   "transmission",
                              "shaking", "clearance", "window", "reaction"};

// A watched clearance by its two parts as the file's "between" names them ("hook.K –
// needlebar.N-B").
QString clearanceName(const Mechanism& m, const ClearanceWatch& w) {
  return QString::fromStdString(m.pointLabel(w.point)) + QStringLiteral(" – ") +
         QString::fromStdString(m.partLabel(w.other));
}

QString number(double v) {
  return QString::number(v, 'g', 10);
}

// A reaction target's choices: each joint's force, and on a machine in space each joint in a
// plane's load out of it (its normal force :fn, its tilts :tilt: a bearing's, the solver says
// which: a body's bearing, as k solves the design), named as linkage-cli optimize names them.
struct ReactionChoice {
  size_t joint;
  OptTarget::Reaction part;
};
std::vector<ReactionChoice> reactionChoices(const Mechanism& m, const Kinematics& k) {
  std::vector<ReactionChoice> out;
  for (size_t j = 0; j < m.joints.size(); ++j) out.push_back({j, OptTarget::Reaction::InPlane});
  if (!isSpatial(m)) return out;
  for (size_t j = 0; j < m.joints.size(); ++j)
    if (bearsOutOfPlane(k, m.joints[j].id))
      for (OptTarget::Reaction part : {OptTarget::Reaction::Normal, OptTarget::Reaction::Tilt})
        out.push_back({j, part});
  return out;
}

QString reactionName(const Mechanism& m, size_t joint, OptTarget::Reaction part) {
  OptTarget t;
  t.kind = K::Force;
  t.index = joint;
  t.reaction = part;
  return QString::fromStdString(optTargetName(m, t));
}

// What a target of this kind can be of, as the list shows it (index i is the i-th dyad,
// clearance, or window end: start, end of the first window, then the second's ...).
QStringList choices(const Mechanism& m, K kind, const Kinematics& k) {
  QStringList out;
  if (kind == K::Transmission) {
    for (const TransmissionJoint& j : transmissionJoints(m)) out << QString::fromStdString(j.label);
  } else if (kind == K::Shaking) {
    // fz a machine in space's (its moment |M| then about the world's origin).
    out << QStringLiteral("fx") << QStringLiteral("fy") << QStringLiteral("force");
    if (isSpatial(m)) out << QStringLiteral("fz");
    out << QStringLiteral("moment");
  } else if (kind == K::Clearance) {
    for (const ClearanceWatch& w : m.timing.clearances) out << clearanceName(m, w);
  } else if (kind == K::Window) {
    for (const TimingWindow& w : m.timing.windows)
      out << QString::fromStdString(w.name + ".start") << QString::fromStdString(w.name + ".end");
  } else if (kind == K::Force) {  // each joint, as linkage-cli dynamics names its columns
    for (const ReactionChoice& c : reactionChoices(m, k)) out << reactionName(m, c.joint, c.part);
  } else {
    for (const Point& p : m.points)
      if (!m.body(p.body)->ground) out << QString::fromStdString(m.pointLabel(p.id));
  }
  return out;
}

bool readNumber(const QTableWidgetItem* i, double& out) {
  bool ok = false;
  out = i ? i->text().trimmed().toDouble(&ok) : NAN;
  return ok && std::isfinite(out);
}

// What each kind's value is, for the message when it is not.
QString valueUsage(K kind) {
  switch (kind) {
    case K::Stroke:
      return QObject::tr(
          "the stroke is a number >= 0 (mm), along the point's own direction (its ground "
          "slot's, else y) or along one given after @: x, y, z or DX, DY[, DZ] (\"30 @ z\")");
    case K::Position:
      return QObject::tr(
          "the position is two numbers x, y (mm) at a crank angle (on a machine "
          "in space x, y or x, y, z in the world)");
    case K::Path:
      return QObject::tr(
          "the path is a CSV file of points x,y (mm; on a machine in space x,y or x,y,z in the "
          "world)");
    case K::Transmission:
      return QObject::tr("the transmission angle's limit is degrees, 0 up to 90");
    case K::Shaking:
      return QObject::tr("the shaking force's limit is a number >= 0 (N; N m for the moment)");
    case K::Clearance:
      return QObject::tr("the clearance's gap is a number >= 0 (mm)");
    case K::Window:
      return QObject::tr("the window's end is a crank angle (degrees)");
    case K::Force:
      return QObject::tr("the reaction's limit is a number >= 0 (N; N m for the tilts)");
  }
  return {};
}

// Only a position is at a crank angle (a window's end is its value): the cell is empty and
// closed for the others.
void showCrank(QTableWidgetItem* cell, K kind, const QString& deg) {
  const bool at = kind == K::Position;
  cell->setText(at ? deg : QString());
  cell->setFlags(at ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable
                    : Qt::ItemIsEnabled | Qt::ItemIsSelectable);
}

// The kinds that name something of the design by its index in their list (choices()) and take
// one number: false when the number is not the kind's.
bool readOther(const Mechanism& m, const Kinematics& k, K kind, int of, bool isNumber, double v,
               OptTarget& t) {
  switch (kind) {
    case K::Transmission: {
      if (!isNumber || !(v >= 0 && v < 90)) return false;
      const std::vector<TransmissionJoint> js = transmissionJoints(m);
      t.joint = static_cast<size_t>(of);
      t.limitDeg = v;
      t.point = m.joint(js.at(t.joint).joint)->a;
      return true;
    }
    case K::Shaking:
      if (!isNumber || !(v >= 0)) return false;
      t.measure = of == 0                   ? BalanceMeasure::Fx
                  : of == 1                 ? BalanceMeasure::Fy
                  : of == 3 && isSpatial(m) ? BalanceMeasure::Fz
                                            : BalanceMeasure::Force;
      t.moment = of == (isSpatial(m) ? 4 : 3);
      t.limitN = v;
      return true;
    case K::Clearance:
      if (!isNumber || !(v >= 0)) return false;
      t.index = static_cast<size_t>(of);
      t.gapMm = v;
      return true;
    case K::Window:
      if (!isNumber) return false;
      t.window = m.timing.windows.at(static_cast<size_t>(of / 2)).name;
      t.windowEnd = of % 2 == 1;
      t.crankDeg = v;
      return true;
    case K::Force: {
      const std::vector<ReactionChoice> all = reactionChoices(m, k);
      if (!isNumber || !(v >= 0) || of < 0 || static_cast<size_t>(of) >= all.size()) return false;
      const ReactionChoice c = all[static_cast<size_t>(of)];
      t.index = c.joint;
      t.reaction = c.part;
      t.measure = BalanceMeasure::Force;
      t.limitN = v;
      return true;
    }
    default:
      return false;
  }
}

}  // namespace

OptimizeTargets::OptimizeTargets(Document* doc, QWidget* parent)
    : QTableWidget(0, 5, parent), doc_(doc) {
  setObjectName(QStringLiteral("optTargets"));
  setHorizontalHeaderLabels({tr("Kind"), tr("Of"), tr("Value"), tr("At crank (°)"), tr("Weight")});
  horizontalHeader()->setSectionResizeMode(Of, QHeaderView::Stretch);
  verticalHeader()->setVisible(false);
}

OptTarget::Kind OptimizeTargets::kindOf(int row) const {
  const auto* c = qobject_cast<QComboBox*>(cellWidget(row, Kind));
  return static_cast<K>(c ? c->currentIndex() : 0);
}

bool OptimizeTargets::addRow(OptTarget::Kind kind, const QString& of, const QString& value,
                             double crankDeg, double weight) {
  const QStringList list = choices(doc_->design(), kind, doc_->kinematics());
  if (!of.isEmpty() && !list.contains(of)) return false;
  const int r = rowCount();
  insertRow(r);
  auto* kinds = new QComboBox;
  for (const char* k : kKinds) kinds->addItem(tr(k));
  kinds->setCurrentIndex(static_cast<int>(kind));
  setCellWidget(r, Kind, kinds);
  auto* what = new QComboBox;
  what->addItems(list);
  if (!of.isEmpty()) what->setCurrentText(of);
  setCellWidget(r, Of, what);
  setItem(r, Value, new QTableWidgetItem(value));
  setItem(r, Crank, new QTableWidgetItem);
  showCrank(item(r, Crank), kind, number(crankDeg));
  setItem(r, Weight, new QTableWidgetItem(number(weight)));
  item(r, Value)->setToolTip(valueUsage(kind));
  connect(kinds, &QComboBox::currentIndexChanged, this, [this, kinds](int k) {
    for (int row = 0; row < rowCount(); ++row)
      if (cellWidget(row, Kind) == kinds) setKind(row, static_cast<K>(k));
  });
  return true;
}

QString OptimizeTargets::defaultValue(OptTarget::Kind kind, const QString& of) const {
  const Mechanism& m = doc_->design();
  const std::optional<PointId> p = m.findPoint(of.toStdString());
  if (kind == K::Stroke && p && doc_->solved())
    return number(
        findLimits(doc_->kinematics(), LimitMeasure::alongInSpace(*p, strokeDirection(m, *p)))
            .stroke);
  if (kind == K::Position && p && doc_->solved() && isSpatial(m)) {  // the world's x, y, z
    const Vec3 at = doc_->kinematics().motionInSpace(*p).position;
    return QStringLiteral("%1, %2, %3").arg(number(at.x()), number(at.y()), number(at.z()));
  }
  if (kind == K::Position && p && doc_->solved()) {
    const Vec2 at = doc_->kinematics().position(*p);
    return QStringLiteral("%1, %2").arg(number(at.x()), number(at.y()));
  }
  if (kind == K::Transmission) return QStringLiteral("40");
  if (kind == K::Clearance) return QStringLiteral("1");
  return QStringLiteral("0");
}

void OptimizeTargets::setKind(int row, OptTarget::Kind kind) {
  auto* kinds = qobject_cast<QComboBox*>(cellWidget(row, Kind));
  auto* what = qobject_cast<QComboBox*>(cellWidget(row, Of));
  if (!kinds || !what) return;
  const QSignalBlocker block(kinds);
  kinds->setCurrentIndex(static_cast<int>(kind));
  const QString was = what->currentText();
  what->clear();
  what->addItems(choices(doc_->design(), kind, doc_->kinematics()));
  if (what->findText(was) >= 0) what->setCurrentText(was);
  item(row, Value)->setText(defaultValue(kind, what->currentText()));
  item(row, Value)->setToolTip(valueUsage(kind));
  showCrank(item(row, Crank), kind, number(doc_->crankDeg()));
}

void OptimizeTargets::refreshChoices() {
  for (int r = 0; r < rowCount(); ++r)
    if (auto* what = qobject_cast<QComboBox*>(cellWidget(r, Of))) {
      const QString was = what->currentText();
      what->clear();
      what->addItems(choices(doc_->design(), kindOf(r), doc_->kinematics()));
      if (what->findText(was) >= 0) what->setCurrentText(was);
    }
}

bool OptimizeTargets::readRow(int r, OptTarget& t, QString* why) const {
  const Mechanism& m = doc_->design();
  const K kind = kindOf(r);
  const auto* what = qobject_cast<QComboBox*>(cellWidget(r, Of));
  const int of = what ? what->currentIndex() : -1;
  const QString kindName = tr(kKinds[static_cast<int>(kind)]);
  auto fail = [&](const QString& fault) {
    *why = tr("target %1 (%2): %3").arg(r + 1).arg(kindName, fault);
    return false;
  };
  if (of < 0) return fail(tr("there is nothing of this kind in the design to choose"));
  if (!readNumber(item(r, Weight), t.weight) || !(t.weight > 0))
    return fail(tr("the weight is a number above 0"));
  t.kind = kind;
  const QString value = item(r, Value)->text().trimmed();
  double v = NAN;
  const bool isNumber = readNumber(item(r, Value), v);
  if (kind == K::Stroke || kind == K::Position || kind == K::Path) {
    const std::optional<PointId> p = m.findPoint(what->currentText().toStdString());
    if (!p) return fail(tr("no point %1").arg(what->currentText()));
    t.point = *p;
  }
  switch (kind) {
    case K::Stroke: {
      // MM, or MM @ DIR as the command line's stroke:P@DIR=MM reads its direction.
      const qsizetype at = value.indexOf(QLatin1Char('@'));
      bool ok = false;
      t.stroke = (at < 0 ? value : value.left(at)).trimmed().toDouble(&ok);
      if (at >= 0)
        t.direction = parseDirection(value.mid(at + 1).remove(QLatin1Char(' ')).toStdString());
      if (!ok || !(t.stroke >= 0) || !std::isfinite(t.stroke) || (at >= 0 && !t.direction))
        return fail(valueUsage(kind));
      return true;
    }
    case K::Position: {
      const QStringList xy = value.split(QLatin1Char(','));
      bool okX = false, okY = false, okZ = true;
      if (xy.size() == 2 || xy.size() == 3)
        t.at = Vec2(xy[0].trimmed().toDouble(&okX), xy[1].trimmed().toDouble(&okY));
      if (xy.size() == 3) t.z = xy[2].trimmed().toDouble(&okZ);
      if (!okX || !okY || !okZ || !t.at.allFinite() || !std::isfinite(t.z.value_or(0)) ||
          !readNumber(item(r, Crank), t.crankDeg))
        return fail(valueUsage(kind));
      return true;
    }
    case K::Path: {
      if (value.isEmpty()) return fail(valueUsage(kind));
      // The command line's reading of the file (its format, comments and messages); "*1" so
      // that a '*' in the file's name is not taken for a weight.
      const std::string text =
          "path:" + what->currentText().toStdString() + "=" + value.toStdString() + "*1";
      std::string fault;
      OptTarget read;
      if (!parseOptTarget(m, text, read, fault))
        return fail(QString::fromStdString(fault.substr(("--target " + text + ": ").size())));
      t.path = std::move(read.path);
      t.pathZ = std::move(read.pathZ);
      return true;
    }
    default:
      if (!readOther(m, doc_->kinematics(), kind, of, isNumber, v, t))
        return fail(valueUsage(kind));
      return true;
  }
  return fail(tr("unknown kind"));
}

bool OptimizeTargets::read(std::vector<OptTarget>& out, QString* why) const {
  for (int r = 0; r < rowCount(); ++r) {
    OptTarget t;
    if (!readRow(r, t, why)) return false;
    out.push_back(std::move(t));
  }
  return true;
}

QStringList OptimizeTargets::probeLines() const {
  QStringList out;
  for (int r = 0; r < rowCount(); ++r) {
    const auto* kinds = qobject_cast<QComboBox*>(cellWidget(r, Kind));
    const auto* what = qobject_cast<QComboBox*>(cellWidget(r, Of));
    out << QStringLiteral("optimize target %1: %2 | %3 | %4 | %5 | %6")
               .arg(r + 1)
               .arg(kinds ? kinds->currentText() : QString(),
                    what ? what->currentText() : QString(), item(r, Value)->text(),
                    item(r, Crank)->text(), item(r, Weight)->text());
    if (kinds && !kinds->visibleRegion().isEmpty()) {
      const QPoint c = kinds->mapToGlobal(kinds->rect().center());
      out << QStringLiteral("at optimize target %1 kind: %2 %3").arg(r + 1).arg(c.x()).arg(c.y());
    }
    if (what && !what->visibleRegion().isEmpty()) {
      const QPoint c = what->mapToGlobal(what->rect().center());
      out << QStringLiteral("at optimize target %1 of: %2 %3").arg(r + 1).arg(c.x()).arg(c.y());
    }
  }
  return out;
}

namespace {

// A reaction target's peak as the result names it, with its unit.
QString reactionPeak(const Mechanism& m, const OptTarget& t) {
  const QString j =
      t.index < m.joints.size() ? reactionName(m, t.index, t.reaction) : QString::number(t.index);
  const QString what =
      t.reaction == OptTarget::Reaction::Normal ? QObject::tr("peak normal force |fn| at %1 (N)")
      : t.reaction == OptTarget::Reaction::Tilt ? QObject::tr("peak tilts |(mx, my)| at %1 (N m)")
                                                : QObject::tr("peak reaction |f| at %1 (N)");
  return what.arg(j);
}

}  // namespace

std::vector<MeasureRow> measureRows(const Mechanism& m, const OptTarget& t, const Measure& before,
                                    const Measure& after) {
  auto at = [](const Measure& v, size_t i) { return i < v.size() ? v[i] : NAN; };
  std::vector<MeasureRow> rows;
  auto add = [&](const QString& what, size_t i, const QString& target) {
    rows.push_back({what, at(before, i), at(after, i), target});
  };
  const QString p = t.point ? QString::fromStdString(m.pointLabel(t.point)) : QString();
  switch (t.kind) {
    case K::Stroke:
      if (t.direction)
        add(QObject::tr("stroke of %1 along %2 (mm)")
                .arg(p, QString::fromStdString(directionName(*t.direction))),
            0, number(t.stroke));
      else
        add(QObject::tr("stroke of %1 (mm)").arg(p), 0, number(t.stroke));
      break;
    case K::Position:
      for (size_t c = 0; c < 2; ++c)
        add(QObject::tr("%1 of %2 at crank %3° (mm)").arg(c ? "y" : "x", p).arg(t.crankDeg), c,
            number(t.at[static_cast<int>(c)]));
      if (t.z)
        add(QObject::tr("z of %1 at crank %2° (mm)").arg(p).arg(t.crankDeg), 2, number(*t.z));
      break;
    case K::Path:
      add(QObject::tr("rms distance of the path's %1 points to %2's curve (mm)")
              .arg(t.path.size())
              .arg(p),
          0, QStringLiteral("0"));
      add(QObject::tr("largest distance to %1's curve (mm)").arg(p), 1, QStringLiteral("0"));
      break;
    case K::Transmission: {
      const std::vector<TransmissionJoint> js = transmissionJoints(m);
      const QString j = t.joint < js.size() ? QString::fromStdString(js[t.joint].label) : p;
      add(QObject::tr("least %1 (°)").arg(j), 0, QStringLiteral(">= ") + number(t.limitDeg));
      add(QObject::tr("largest %1 (°)").arg(j), 1,
          QStringLiteral("<= ") + number(180 - t.limitDeg));
      break;
    }
    case K::Shaking: {
      const QString f = t.measure == BalanceMeasure::Fx   ? QStringLiteral("|fx|")
                        : t.measure == BalanceMeasure::Fy ? QStringLiteral("|fy|")
                        : t.measure == BalanceMeasure::Fz ? QStringLiteral("|fz|")
                                                          : QStringLiteral("|f|");
      if (t.moment)
        add(QObject::tr("peak shaking moment |m| (N m)"), 0,
            QStringLiteral("<= ") + number(t.limitN));
      else
        add(QObject::tr("peak shaking %1 (N)").arg(f), 0, QStringLiteral("<= ") + number(t.limitN));
      add(QObject::tr("its crank angle (°)"), 1, QString());
      break;
    }
    case K::Clearance: {
      const QString c = t.index < m.timing.clearances.size()
                            ? clearanceName(m, m.timing.clearances[t.index])
                            : QString::number(t.index);
      add(QObject::tr("least clearance %1 (mm)").arg(c), 0,
          QStringLiteral(">= ") + number(t.gapMm));
      add(QObject::tr("its crank angle (°)"), 1, QString());
      break;
    }
    case K::Window:
      add(QObject::tr("window %1 %2 at crank (°)")
              .arg(QString::fromStdString(t.window), t.windowEnd ? "end" : "start"),
          0, number(t.crankDeg));
      break;
    case K::Force:
      add(reactionPeak(m, t), 0, QStringLiteral("<= ") + number(t.limitN));
      add(QObject::tr("its crank angle (°)"), 1, QString());
      break;
  }
  return rows;
}

}  // namespace linkage::ui
