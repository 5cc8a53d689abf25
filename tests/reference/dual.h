// Forward-mode dual numbers: a value and its derivative, carried through the reference closed
// forms (which are templates on the scalar type) to differentiate them once more without
// differences. Used for the slider-crank's jerk: the derivative of its closed-form acceleration.
#pragma once

#include "reference/scalar.h"
#include "reference/slider_crank.h"

namespace linkref {

template <class T>
struct Dual {
  T v{}, d{};
  Dual() = default;
  Dual(T value, T derivative = T(0)) : v(value), d(derivative) {}
  Dual(int value) : v(T(value)) {}
  friend Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
  friend Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
  friend Dual operator-(Dual a) { return {-a.v, -a.d}; }
  friend Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
  friend Dual operator/(Dual a, Dual b) {
    return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
  }
  friend bool operator>(Dual a, Dual b) { return a.v > b.v; }
  friend bool operator>=(Dual a, Dual b) { return a.v >= b.v; }
  friend Dual sin(Dual a) { return {linkref::sin(a.v), linkref::cos(a.v) * a.d}; }
  friend Dual cos(Dual a) { return {linkref::cos(a.v), -linkref::sin(a.v) * a.d}; }
  friend Dual sqrt(Dual a) {
    const T s = linkref::sqrt(a.v);
    return {s, a.d / (T(2) * s)};
  }
  friend Dual atan2(Dual y, Dual x) {
    return {linkref::atan2(y.v, x.v), (x.v * y.d - y.v * x.d) / (x.v * x.v + y.v * y.v)};
  }
};

// The slider pin of slider_crank() with its jerk: y, vy, ay as slider_crank() gives them, and
// jy = d(ay)/dt = s omega d(ay)/dphi by carrying a dual number through slider_crank().
template <class T>
struct SliderJerk {
  T y{}, vy{}, ay{}, jy{};
};
template <class T>
SliderJerk<T> slider_crank_jerk(const SliderCrankParams<T>& q, T phi) {
  SliderCrankParams<Dual<T>> p;
  p.r = q.r, p.l = q.l, p.e = q.e, p.a0 = q.a0, p.s = q.s, p.omega = q.omega;
  const auto st = slider_crank(p, Dual<T>(phi, T(1)));
  return {st.y.v, st.vy.v, st.ay.v, q.omega * st.ay.d};
}

}  // namespace linkref
