#include "figures/units.h"

#include <QSettings>
#include <cmath>

namespace linkage::ui {

double PlotUnits::scale(Order o, bool body) const {
  if (body) return o == Order::Position ? 180.0 / M_PI : 1.0;
  switch (o) {
    case Order::Position:
      return 1;
    case Order::Velocity:
      return velocity == VelocityUnit::MetrePerSecond ? 1e-3 : 1;
    case Order::Acceleration:
    case Order::Jerk:
      switch (acceleration) {
        case AccelerationUnit::MillimetrePerSecond2:
          return 1;
        case AccelerationUnit::MetrePerSecond2:
          return 1e-3;
        case AccelerationUnit::G:
          return 1 / kStandardGravity;
      }
  }
  return 1;
}

QString PlotUnits::name(Order o, bool body) const {
  if (body) {
    static const char* names[] = {"deg", "rad/s", "rad/s²", "rad/s³"};
    return QString::fromUtf8(names[static_cast<int>(o)]);
  }
  const bool metres = o == Order::Velocity ? velocity == VelocityUnit::MetrePerSecond
                                           : acceleration == AccelerationUnit::MetrePerSecond2;
  switch (o) {
    case Order::Position:
      return "mm";
    case Order::Velocity:
      return metres ? "m/s" : "mm/s";
    case Order::Acceleration:
      if (acceleration == AccelerationUnit::G) return "g";
      return QString::fromUtf8(metres ? "m/s²" : "mm/s²");
    case Order::Jerk:
      if (acceleration == AccelerationUnit::G) return "g/s";
      return QString::fromUtf8(metres ? "m/s³" : "mm/s³");
  }
  return {};
}

PlotUnits PlotUnits::fromSettings() {
  QSettings s;
  PlotUnits u;
  const int v = s.value("plots/velocityUnit", 0).toInt();
  const int a = s.value("plots/accelerationUnit", 0).toInt();
  if (v >= 0 && v <= 1) u.velocity = static_cast<VelocityUnit>(v);
  if (a >= 0 && a <= 2) u.acceleration = static_cast<AccelerationUnit>(a);
  return u;
}

void PlotUnits::toSettings() const {
  QSettings s;
  s.setValue("plots/velocityUnit", static_cast<int>(velocity));
  s.setValue("plots/accelerationUnit", static_cast<int>(acceleration));
}

QString componentLabel(const ComponentName& n, Order o) {
  static const char* letters[] = {"", "v", "a", "j"};
  static const char* vectors[] = {"r", "v", "a", "j"};
  static const char* distances[] = {"d", "d'", "d''", "d'''"};
  const int i = static_cast<int>(o);
  switch (n.c) {
    case Quantity::Component::X:
      return QString(letters[i]) + "x";
    case Quantity::Component::Y:
      return QString(letters[i]) + "y";
    case Quantity::Component::Z:
      return QString(letters[i]) + "z";
    case Quantity::Component::Magnitude:
      return QString("|%1|").arg(vectors[i]);
    case Quantity::Component::Along: {
      QString s = QString::fromUtf8("%1 along %2°").arg(vectors[i]).arg(n.azimuthDeg, 0, 'g', 6);
      if (n.elevationDeg != 0) s += QString::fromUtf8(" at %1° up").arg(n.elevationDeg, 0, 'g', 6);
      return s;
    }
    case Quantity::Component::Distance:
      return QString("%1 to %2").arg(distances[i], n.other);
  }
  return {};
}

QString axisLabel(bool body, const ComponentName& c, Order o, const PlotUnits& u) {
  const int i = static_cast<int>(o);
  if (body) {
    static const char* names[] = {"Angle", "Angular velocity", "Angular acceleration",
                                  "Angular jerk"};
    return QString("%1 [%2]").arg(names[i], u.name(o, true));
  }
  static const char* names[] = {"Position", "Velocity", "Acceleration", "Jerk"};
  const QString what =
      (c.c == Quantity::Component::Magnitude && o == Order::Velocity) ? QString("Speed")
      : c.c == Quantity::Component::Distance && o == Order::Position  ? QString("Distance")
                                                                      : QString(names[i]);
  return QString("%1 %2 [%3]").arg(what, componentLabel(c, o), u.name(o, false));
}

QString shortAxisLabel(bool body, const ComponentName& c, Order o, const PlotUnits& u) {
  const int i = static_cast<int>(o);
  if (body) {
    static const char* names[] = {"θ", "ω", "α", "α'"};
    return QString("%1 [%2]").arg(QString::fromUtf8(names[i]), u.name(o, true));
  }
  return QString("%1 [%2]").arg(componentLabel(c, o), u.name(o, false));
}

namespace {

// The name of the body the driver turns ("crank" without one).
QString drivenName(const Mechanism& m) {
  if (m.driver)
    if (const Joint* j = m.joint(m.driver->joint))
      if (const Point* p = m.point(j->b))
        if (const Body* b = m.body(p->body)) return QString::fromStdString(b->name);
  return QStringLiteral("crank");
}

}  // namespace

QString crankAxisLabel(const Mechanism& m) {
  if (!m.driver) return QStringLiteral("crank angle [deg]");
  return QStringLiteral("%1 angle [deg], %2")
      .arg(drivenName(m), m.driver->direction == Direction::Cw
                              ? QStringLiteral("clockwise")
                              : QStringLiteral("counter-clockwise"));
}

QString briefCrankAxisLabel(const Mechanism& m) {
  if (!m.driver) return QStringLiteral("crank [deg]");
  return QStringLiteral("%1 [deg], %2")
      .arg(drivenName(m),
           m.driver->direction == Direction::Cw ? QStringLiteral("cw") : QStringLiteral("ccw"));
}

QString wrapped(const QString& text, int width) {
  QStringList lines;
  QString line;
  for (const QString& word : text.split(' ', Qt::SkipEmptyParts)) {
    if (!line.isEmpty() && line.size() + 1 + word.size() > width) {
      lines << line;
      line.clear();
    }
    line += (line.isEmpty() ? "" : " ") + word;
  }
  if (!line.isEmpty()) lines << line;
  return lines.join('\n');
}

}  // namespace linkage::ui
