// Complex-step differentiation for the tests' closed forms: a closed form written over
// std::complex, one dimension stepped by i h (h = 1e-30), gives its derivative as Im / h, exact to
// rounding and independent of the solver's rows. Plane vectors over complex numbers for it.
#pragma once

#include <complex>

namespace linkage::test {

using C = std::complex<double>;
inline constexpr double kH = 1e-30;

struct CVec {
  C x, y;
};
inline CVec operator+(CVec a, CVec b) {
  return {a.x + b.x, a.y + b.y};
}
inline CVec operator-(CVec a, CVec b) {
  return {a.x - b.x, a.y - b.y};
}
inline CVec operator*(C s, CVec a) {
  return {s * a.x, s * a.y};
}
inline C dot(CVec a, CVec b) {
  return a.x * b.x + a.y * b.y;
}
inline C cross(CVec a, CVec b) {
  return a.x * b.y - a.y * b.x;
}
// A quarter turn counter-clockwise, as linkage's perp().
inline CVec perp(CVec a) {
  return {-a.y, a.x};
}

}  // namespace linkage::test
