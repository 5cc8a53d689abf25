// Numbers as the editor shows them: no sign or curve made of rounding, no digit for what is not
// a number. The solver's results agree with closed forms to about 1e-12 of their peak, so a
// value under 1e-9 of its quantity's scale is rounding of an exact zero (a pivot's velocity
// computed through a turning link comes out as 1e-14, not 0).
#pragma once

#include <QString>
#include <cmath>

#include "linkage/kinematics.h"

namespace linkage::ui {

constexpr double kRoundingFraction = 1e-9;

// v, or exactly 0 when it is rounding next to `scale`.
inline double cleaned(double v, double scale) {
  return std::abs(v) <= kRoundingFraction * std::abs(scale) ? 0.0 : v;
}

// The scale of a point's motion of order n (0 position, 1 velocity, 2 acceleration, 3 jerk):
// the mechanism's size times the crank's angular velocity to the n-th power.
inline double motionScale(const Kinematics& k, int order) {
  return k.size() * std::pow(std::abs(k.omega()), order);
}

// Fixed decimals, never "-0.000"; a dash for what is not a number.
inline QString fixedText(double v, int decimals) {
  if (!std::isfinite(v)) return QStringLiteral("\u2013");
  const QString s = QString::number(v, 'f', decimals);
  if (s.startsWith(QLatin1Char('-')) && QString(s)
                                            .remove(QLatin1Char('-'))
                                            .remove(QLatin1Char('0'))
                                            .remove(QLatin1Char('.'))
                                            .isEmpty())
    return s.mid(1);
  return s;
}

// An angle in degrees with fixed decimals, in exponent form when it is huge (a crank angle of
// 1e300 written out in full is 300 digits, which widened the window).
inline QString angleText(double deg, int decimals) {
  return std::abs(deg) < 1e9 || !std::isfinite(deg) ? fixedText(deg, decimals)
                                                    : QString::number(deg, 'g', 6);
}

}  // namespace linkage::ui
