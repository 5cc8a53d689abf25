// A number carried with its derivative along one direction (forward-mode differentiation): a
// kind's restated reaction (ElementKind::reactChange) is written once over a scalar type and
// read as its value (double) and, exactly, as its derivative (Dual) with respect to a dimension.
#pragma once

#include <cmath>

namespace linkage {

struct Dual {
  double v = 0, d = 0;  // the value and its derivative
  Dual() = default;
  Dual(double value, double derivative = 0) : v(value), d(derivative) {}
};

inline double value(double x) {
  return x;
}
inline double value(const Dual& x) {
  return x.v;
}

inline Dual operator+(Dual a, Dual b) {
  return {a.v + b.v, a.d + b.d};
}
inline Dual operator-(Dual a, Dual b) {
  return {a.v - b.v, a.d - b.d};
}
inline Dual operator-(Dual a) {
  return {-a.v, -a.d};
}
inline Dual operator*(Dual a, Dual b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}
inline Dual operator/(Dual a, Dual b) {
  return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
}
inline Dual sqrt(Dual a) {
  const double r = std::sqrt(a.v);
  return {r, a.d / (2 * r)};
}

}  // namespace linkage
