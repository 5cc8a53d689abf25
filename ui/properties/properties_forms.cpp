// The forms of the properties panel, one per kind of selection (properties_panel.h).
#include "properties/properties_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>
#include <cmath>

#include "document/commands.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "elements/element_ui.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/io/numbers.h"
#include "tools/selection.h"

namespace linkage::ui {

namespace {
constexpr double kDeg = M_PI / 180;
// Ten turns either way: enough for any start (a belt's slower shaft included); beyond it the
// crank would be tracked for ages to reach angle 0.
constexpr double kMaxStartDeg = 3600;

// A length or angle measured between points, to 12 digits: the 40 typed comes back 40, not the
// 39.99999999999999 that the coordinates' last bits make of it.
double measured(double v) {
  return std::isfinite(v) ? parseNumber(formatNumber(v, 12)).value_or(v) : v;
}
}  // namespace

void PropertiesPanel::fillMechanism() {
  title_->setText(tr("<b>Mechanism</b>"));
  addText(
      tr("Name"), [this] { return QString::fromStdString(doc_->design().name); },
      [this](const QString& t, QString* why) {
        return change(
            tr("Rename the mechanism"),
            [&](Mechanism& m, QString*) {
              m.name = t.toStdString();
              return true;
            },
            why);
      });
  if (doc_->design().driver) fillDriver();
}

void PropertiesPanel::fillDriver() {
  addNumber(
      tr("Driver speed"), [this] { return doc_->design().driver->rpm; },
      [this](double v, QString* why) {
        if (!(v > 0)) {
          *why = tr("the speed must be positive");
          return false;
        }
        return change(
            tr("Driver speed"),
            [&](Mechanism& m, QString*) {
              m.driver->rpm = v;
              return true;
            },
            why);
      },
      tr("rpm"));
  auto* dir = new QComboBox;
  dir->addItems({tr("counter-clockwise"), tr("clockwise")});
  form_->addRow(tr("Direction"), dir);
  auto current = [this] { return doc_->design().driver->direction == Direction::Cw ? 1 : 0; };
  dir->setCurrentIndex(current());
  rows_.push_back({tr("Direction"), dir, [dir, current] {
                     QSignalBlocker b(dir);
                     dir->setCurrentIndex(current());
                   }});
  connect(dir, &QComboBox::activated, this, [this](int i) {
    QString why;
    change(
        tr("Driver direction"),
        [&](Mechanism& m, QString*) {
          m.driver->direction = i == 1 ? Direction::Cw : Direction::Ccw;
          return true;
        },
        &why);
  });
  // The file's start_deg, as the editor shows it: crank angle 0 is the drawing turned on by it
  // in the driving direction. A new start angle turns the crank to 0 at once, so that the crank
  // is seen to start there (the drawing itself stays as it is).
  addNumber(
      tr("Start angle"), [this] { return doc_->design().driver->startDeg; },
      [this](double v, QString* why) {
        if (!(std::abs(v) <= kMaxStartDeg)) {
          *why = tr("the start angle must be between -%1 and %1 degrees").arg(kMaxStartDeg);
          return false;
        }
        if (!change(
                tr("Driver start angle"),
                [&](Mechanism& m, QString*) {
                  m.driver->startDeg = v;
                  return true;
                },
                why))
          return false;
        if (doc_->solved()) doc_->setCrankDeg(0);
        return true;
      },
      QStringLiteral("\u00b0"));
  field(tr("Start angle [\u00b0]"))
      ->setToolTip(tr("Crank angle 0 (Home, where the plots and tables start) is the drawing "
                      "turned on by this angle in the driving direction"));
  addInfo(tr("Crank 0 is"), [this] {
    const Driver& d = *doc_->design().driver;
    if (d.startDeg == 0) return tr("the drawing as it is");
    return tr("the drawing turned %1\u00b0 %2")
        .arg(shownText(d.startDeg))
        .arg(d.direction == Direction::Cw ? tr("clockwise") : tr("counter-clockwise"));
  });
}

void PropertiesPanel::fillBody(BodyId id) {
  const Body* b = doc_->design().body(id);
  title_->setText(tr("<b>Link</b> %1").arg(QString::fromStdString(b->name).toHtmlEscaped()));
  addText(
      tr("Name"), [this, id] { return QString::fromStdString(doc_->design().body(id)->name); },
      [this, id](const QString& t, QString* why) {
        if (!bodyNameFree(doc_->design(), t.toStdString(), id)) {
          *why = tr("another link is called \"%1\"").arg(t);
          return false;
        }
        return change(
            tr("Rename link"),
            [&](Mechanism& m, QString*) {
              m.body(id)->name = t.toStdString();
              return true;
            },
            why);
      });
  std::vector<PointId> pts;
  for (const Point& p : doc_->design().points)
    if (p.body == id) pts.push_back(p.id);
  addInfo(tr("Points"), [this, id] {
    QStringList names;
    for (const Point& p : doc_->design().points)
      if (p.body == id) names << QString::fromStdString(p.name);
    return names.join(QStringLiteral(", "));
  });
  if (pts.size() == 3 && !b->ground) fillTriangle(id);
  if (pts.size() != 2 || b->ground) return;
  // A bar: its length and angle, measured from its first point; editing them moves the second.
  const PointId p0 = pts[0], p1 = pts[1];
  auto ends = [this, p0, p1] {
    return std::make_pair(doc_->design().point(p0)->pos, doc_->design().point(p1)->pos);
  };
  auto moveSecond = [this, p0, p1](const QString& text, const Vec2& to, QString* why) {
    return change(
        text,
        [&](Mechanism& m, QString*) {
          for (PointId q : pinnedTogether(m, p1)) m.point(q)->pos = to;
          (void)p0;
          return true;
        },
        why);
  };
  addNumber(
      tr("Length"), [ends] { return (ends().second - ends().first).norm(); },
      [ends, moveSecond](double v, QString* why) {
        if (!(v > 0)) {
          *why = tr("a length must be positive");
          return false;
        }
        const auto [a, b] = ends();
        const Vec2 d = (b - a).normalized();
        return moveSecond(tr("Bar length"), a + v * d, why);
      },
      tr("mm"));
  addNumber(
      tr("Angle"),
      [ends] {
        const Vec2 d = ends().second - ends().first;
        return std::atan2(d.y(), d.x()) / kDeg;
      },
      [ends, moveSecond](double v, QString* why) {
        const auto [a, b] = ends();
        const double r = (b - a).norm();
        return moveSecond(tr("Bar angle"), a + r * Vec2(std::cos(v * kDeg), std::sin(v * kDeg)),
                          why);
      },
      QStringLiteral("\u00b0"));
}

void PropertiesPanel::fillPoint(PointId id) {
  const Mechanism& m0 = doc_->design();
  title_->setText(
      tr("<b>Point</b> %1").arg(QString::fromStdString(m0.pointLabel(id)).toHtmlEscaped()));
  addText(
      tr("Name"), [this, id] { return QString::fromStdString(doc_->design().point(id)->name); },
      [this, id](const QString& t, QString* why) {
        const Mechanism& m = doc_->design();
        if (!pointNameFree(m, m.point(id)->body, t.toStdString(), id)) {
          *why = tr("the link has another point \"%1\" (or the name has a dot)").arg(t);
          return false;
        }
        return change(
            tr("Rename point"),
            [&](Mechanism& n, QString*) {
              n.point(id)->name = t.toStdString();
              return true;
            },
            why);
      });
  // The point and the points pinned to it are one place: they move together.
  for (int axis = 0; axis < 2; ++axis)
    addNumber(
        axis ? QStringLiteral("y") : QStringLiteral("x"),
        [this, id, axis] { return doc_->design().point(id)->pos[axis]; },
        [this, id, axis](double v, QString* why) {
          return change(
              tr("Move point"),
              [&](Mechanism& m, QString*) {
                for (PointId q : pinnedTogether(m, id)) m.point(q)->pos[axis] = v;
                return true;
              },
              why);
        },
        tr("mm"));
  fillPolar(id);
  auto* out = new QCheckBox(tr("traced, plotted, exported"));
  auto isOut = [this, id] {
    const auto& o = doc_->design().outputs;
    return std::find(o.begin(), o.end(), id) != o.end();
  };
  out->setChecked(isOut());
  form_->addRow(tr("Output"), out);
  rows_.push_back({tr("Output"), out, [out, isOut] {
                     QSignalBlocker b(out);
                     out->setChecked(isOut());
                   }});
  connect(out, &QCheckBox::clicked, this, [this, id](bool) {
    QString why;
    change(
        tr("Output point"),
        [&](Mechanism& m, QString*) {
          toggleOutput(m, id);
          return true;
        },
        &why);
  });
  fillLoads(BodyId{}, id);
}

// Sides named by their points, in the order linkage/edits.h's setSideLengths takes them; each
// typed side re-solves the mechanism at once.
void PropertiesPanel::fillTriangle(BodyId id) {
  std::vector<QString> names;
  for (const Point& p : doc_->design().points)
    if (p.body == id) names.push_back(QString::fromStdString(p.name));
  const int ends[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (int k = 0; k < 3; ++k)
    addNumber(
        tr("Side %1%2").arg(names[ends[k][0]], names[ends[k][1]]),
        [this, id, k] {
          const std::vector<double> s = sideLengths(doc_->design(), id);
          return s.size() == 3 ? measured(s[k]) : NAN;
        },
        [this, id, k](double v, QString* why) {
          std::vector<double> sides = sideLengths(doc_->design(), id);
          if (sides.size() != 3) return false;
          sides[k] = v;
          return change(
              tr("Plate sides"),
              [&](Mechanism& m, QString* w) {
                std::string problem;
                if (setSideLengths(m, id, sides, &problem)) return true;
                *w = QString::fromStdString(problem);
                return false;
              },
              why);
        },
        tr("mm"));
}

// The point's distance and angle (counter-clockwise from +x) from another point of its link,
// chosen in "From"; typing either moves the point (and the points pinned to it).
void PropertiesPanel::fillPolar(PointId id) {
  const Mechanism& m0 = doc_->design();
  std::vector<PointId> others;
  for (const Point& p : m0.points)
    if (p.body == m0.point(id)->body && p.id != id) others.push_back(p.id);
  if (others.empty()) return;
  auto* from = new QComboBox;
  for (PointId o : others) from->addItem(QString::fromStdString(m0.point(o)->name));
  form_->addRow(tr("From"), from);
  rows_.push_back({tr("From"), from, [] {}});
  auto base = [others, from] { return others[std::max(0, from->currentIndex())]; };
  auto offset = [this, id, base] {
    return Vec2(doc_->design().point(id)->pos - doc_->design().point(base())->pos);
  };
  auto place = [this, id, base](double distance, double angle, QString* why) {
    return change(
        tr("Move point"),
        [&](Mechanism& m, QString* w) {
          std::string problem;
          if (setPolar(m, id, base(), distance, angle, &problem)) return true;
          *w = QString::fromStdString(problem);
          return false;
        },
        why);
  };
  addNumber(
      tr("Distance"), [offset] { return measured(offset().norm()); },
      [offset, place](double v, QString* why) {
        const Vec2 d = offset();
        return place(v, std::atan2(d.y(), d.x()) / kDeg, why);
      },
      tr("mm"));
  addNumber(
      tr("Angle"),
      [offset] {
        const Vec2 d = offset();
        return measured(std::atan2(d.y(), d.x()) / kDeg);
      },
      [offset, place](double v, QString* why) { return place(offset().norm(), v, why); },
      QStringLiteral("\u00b0"));
  connect(from, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
}

// The title, then the rows the joint's kind puts there (ui/elements/).
void PropertiesPanel::fillJoint(JointId id) {
  const Mechanism& m0 = doc_->design();
  title_->setText(
      tr("<b>Joint</b> %1").arg(QString::fromStdString(jointName(m0, id)).toHtmlEscaped()));
  elementUi(m0.joint(id)->type).form(*this, id);
}

void PropertiesPanel::fillSlot(SlotId id) {
  const Mechanism& m0 = doc_->design();
  title_->setText(
      tr("<b>Slot</b> %1").arg(QString::fromStdString(m0.slotLabel(id)).toHtmlEscaped()));
  addText(
      tr("Name"), [this, id] { return QString::fromStdString(doc_->design().slot(id)->name); },
      [this, id](const QString& t, QString* why) {
        const Mechanism& m = doc_->design();
        if (!slotNameFree(m, m.slot(id)->body, t.toStdString(), id)) {
          *why = tr("the link has another slot \"%1\" (or the name has a dot)").arg(t);
          return false;
        }
        return change(
            tr("Rename slot"),
            [&](Mechanism& n, QString*) {
              n.slot(id)->name = t.toStdString();
              return true;
            },
            why);
      });
  fillSlotShape(id);
  if (doc_->design().slot(id)->arc())
    fillArc(id);
  else
    fillSlotEnds(id);
}

// Straight or arc: an arc is bent through a point off the middle of the chord (a quarter of its
// length out), a straight slot keeps the arc's ends.
void PropertiesPanel::fillSlotShape(SlotId id) {
  auto* shape = new QComboBox;
  shape->addItems({tr("straight"), tr("arc (through three points)")});
  addChoice(
      tr("Shape"), shape, [this, id] { return doc_->design().slot(id)->arc() ? 1 : 0; },
      [this, id](int i) {
        QString why;
        change(
            tr("Slot shape"),
            [&](Mechanism& m, QString*) {
              Slot& s = *m.slot(id);
              if (i == 0) {
                s.mid.reset();
              } else if (!s.mid) {
                s.mid = (s.p0 + s.p1) / 2 + perp(s.p1 - s.p0) / 4;
              }
              return true;
            },
            &why);
      });
}

// Sets the slot's points (mid only for an arc) as one edit, refused when they make no curve.
bool PropertiesPanel::setSlot(SlotId id, const Vec2& p0, const std::optional<Vec2>& mid,
                              const Vec2& p1, QString* why) {
  Slot probe = *doc_->design().slot(id);
  probe.p0 = p0;
  probe.p1 = p1;
  probe.mid = mid;
  std::string problem;
  if (!guideOf(probe, &problem)) {
    *why = QString::fromStdString(problem);
    return false;
  }
  return change(
      tr("Slot"),
      [&](Mechanism& m, QString*) {
        *m.slot(id) = probe;
        return true;
      },
      why);
}

void PropertiesPanel::fillSlotEnds(SlotId id) {
  const char* names[4] = {"x0", "y0", "x1", "y1"};
  for (int k = 0; k < 4; ++k)
    addNumber(
        QString::fromLatin1(names[k]),
        [this, id, k] {
          const Slot* s = doc_->design().slot(id);
          return (k < 2 ? s->p0 : s->p1)[k % 2];
        },
        [this, id, k](double v, QString* why) {
          Vec2 p0 = doc_->design().slot(id)->p0, p1 = doc_->design().slot(id)->p1;
          (k < 2 ? p0 : p1)[k % 2] = v;
          return setSlot(id, p0, std::nullopt, p1, why);
        },
        tr("mm"));
}

// An arc's three points, or its centre, radius and the angles of its ends (degrees about the
// centre): either set moves the others.
void PropertiesPanel::fillArc(SlotId id) {
  const char* names[6] = {"x0", "y0", "xm", "ym", "x1", "y1"};
  auto point = [](Slot& s, int k) -> Vec2& { return k < 2 ? s.p0 : k < 4 ? *s.mid : s.p1; };
  for (int k = 0; k < 6; ++k)
    addNumber(
        QString::fromLatin1(names[k]),
        [this, id, k, point] {
          Slot s = *doc_->design().slot(id);
          return point(s, k)[k % 2];
        },
        [this, id, k, point](double v, QString* why) {
          Slot s = *doc_->design().slot(id);
          point(s, k)[k % 2] = v;
          return setSlot(id, s.p0, s.mid, s.p1, why);
        },
        tr("mm"));
  auto guide = [this, id] { return *guideOf(*doc_->design().slot(id)); };
  const char* circle[5] = {QT_TR_NOOP("Centre x"), QT_TR_NOOP("Centre y"), QT_TR_NOOP("Radius"),
                           QT_TR_NOOP("From"), QT_TR_NOOP("To")};
  for (int k = 0; k < 5; ++k)
    addNumber(
        tr(circle[k]),
        [guide, k] {
          const Guide g = guide();
          const double values[5] = {g.centre.x(), g.centre.y(), g.radius, g.a0 / kDeg,
                                    (g.a0 + g.sweep) / kDeg};
          return values[k];
        },
        [this, id, guide, k](double v, QString* why) {
          const Guide g = guide();
          double c[5] = {g.centre.x(), g.centre.y(), g.radius, g.a0, g.a0 + g.sweep};
          c[k] = k < 3 ? v : v * kDeg;
          // The arc keeps its turning direction, less than a full turn from its start.
          double sweep = std::remainder(c[4] - c[3], 2 * M_PI);
          if ((sweep < 0) != (g.sweep < 0)) sweep += g.sweep < 0 ? -2 * M_PI : 2 * M_PI;
          auto at = [&](double a) {
            return Vec2(c[0] + c[2] * std::cos(a), c[1] + c[2] * std::sin(a));
          };
          if (!(c[2] > 0)) {
            *why = tr("the radius must be positive");
            return false;
          }
          return setSlot(id, at(c[3]), at(c[3] + sweep / 2), at(c[3] + sweep), why);
        },
        k < 3 ? tr("mm") : tr("deg"));
}

}  // namespace linkage::ui
