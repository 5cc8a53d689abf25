// The units the plots show, switchable and remembered (QSettings, "plots/..."): velocities in
// mm/s or m/s, accelerations in mm/s^2, m/s^2 or g (standard gravity, 9806.65 mm/s^2); jerk
// follows the acceleration's choice (mm/s^3, m/s^3, g/s). Bodies turn in degrees, rad/s,
// rad/s^2, rad/s^3. The solver's own units are mm, mm/s, mm/s^2, rad, rad/s, rad/s^2.
#pragma once

#include <QString>

#include "linkage/motion_samples.h"

namespace linkage::ui {

constexpr double kStandardGravity = 9806.65;  // mm/s^2

enum class VelocityUnit { MillimetrePerSecond, MetrePerSecond };
enum class AccelerationUnit { MillimetrePerSecond2, MetrePerSecond2, G };

struct PlotUnits {
  VelocityUnit velocity = VelocityUnit::MillimetrePerSecond;
  AccelerationUnit acceleration = AccelerationUnit::MillimetrePerSecond2;

  // Shown value = solver value * scale.
  double scale(Order o, bool body) const;
  // "mm", "mm/s", "g", "deg", "rad/s", ...
  QString name(Order o, bool body) const;

  static PlotUnits fromSettings();
  void toSettings() const;
  bool operator==(const PlotUnits&) const = default;
};

// The crank-angle axis of every figure (the plots, the forces, the balance, the cycle diagram,
// and their exports): the driven body's name and the way it turns, "disk angle [deg],
// clockwise", so that a student reading an angle off a figure turns the right way (the
// Wanzer's disk turns clockwise, against the mathematical sense); "crank angle [deg]" without a
// driver.
QString crankAxisLabel(const Mechanism& m);
// The same for a plot too narrow for it: "disk [deg], cw".
QString briefCrankAxisLabel(const Mechanism& m);

// Words broken into lines of at most `width` characters (plot titles and notes).
QString wrapped(const QString& text, int width);

// A component of a point's motion as the labels name it: its kind, an Along's direction (its
// azimuth counter-clockwise from +x, its elevation above the x-y plane: a machine in space's)
// and a Distance's second point.
struct ComponentName {
  Quantity::Component c = Quantity::Component::Y;
  double azimuthDeg = 0, elevationDeg = 0;
  QString other;
};

// The component of a point's motion as the labels write it: "y", "|r|", "along 30°",
// "along 30° at 45° up", "d to hook.K", with the order's letter ("vy", "|v|", "d' to ...").
QString componentLabel(const ComponentName& c, Order o);

// An axis label with its unit: "Position y [mm]", "Speed |v| [m/s]", "Angular velocity [rad/s]".
QString axisLabel(bool body, const ComponentName& c, Order o, const PlotUnits& u);
// The same, short, for a plot too low for the long label ("vy [mm/s]", "ω [rad/s]").
QString shortAxisLabel(bool body, const ComponentName& c, Order o, const PlotUnits& u);

}  // namespace linkage::ui
