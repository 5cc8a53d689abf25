// Numbers as the editor shows them: no sign or curve made of rounding, no digit for what is not
// a number. The solver's results agree with closed forms to about 1e-12 of their peak, so a
// value under 1e-9 of its quantity's scale is rounding of an exact zero (a pivot's velocity
// computed through a turning link comes out as 1e-14, not 0).
#pragma once

#include <QString>
#include <algorithm>
#include <cmath>

#include "linkage/io/numbers.h"
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

// A number for a person to read (a Properties field, a row): a value typed shows as it was typed
// (at most kTypedDigits significant digits: all of them, "12.3456789"), a value that comes of
// arithmetic is rounded to kShownDigits ("0.248223", not the 17 digits 0.24822347805543243 needs
// to be exact; "40", not 39.99999999999999); whole digits are never dropped into an exponent
// ("1234568"). Never "-0"; a dash for what is not a number. Files keep every digit.
constexpr int kTypedDigits = 9;
constexpr int kShownDigits = 6;
inline QString shownText(double v) {
  if (!std::isfinite(v)) return QStringLiteral("\u2013");
  const double a = std::abs(v);
  const int whole = a >= 1 && a < 1e15 ? static_cast<int>(std::floor(std::log10(a))) + 1 : 1;
  for (int digits = whole; digits <= kTypedDigits; ++digits) {
    const std::string s = formatNumber(v, digits);
    if (parseNumber(s) == v) return QString::fromStdString(s);
  }
  return QString::fromStdString(formatNumber(v, std::max(kShownDigits, whole)));
}

// A result among others of its quantity (a table's rows in one unit, before and after): 0 when
// it is rounding next to their largest, `scale` (a counterweight's moment of 1e-14 kg mm beside
// 1500 is an exact 0, not "5.822746424e-14"); otherwise down to the digit of 1e-9 of the scale,
// the digits below it being rounding too, and at most kResultDigits significant digits.
constexpr int kResultDigits = 10;
inline QString resultText(double v, double scale) {
  if (!std::isfinite(v)) return QStringLiteral("\u2013");
  const double rounding = kRoundingFraction * std::abs(scale);
  if (std::abs(v) <= rounding) return QStringLiteral("0");
  const double digits =
      rounding > 0 ? std::floor(std::log10(std::abs(v))) - std::floor(std::log10(rounding)) + 1
                   : kResultDigits;
  return QString::fromStdString(
      formatShown(v, scale, static_cast<int>(std::clamp<double>(digits, 1, kResultDigits))));
}

}  // namespace linkage::ui
