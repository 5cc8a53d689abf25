// The 876-class eight-link needle mechanism of seed 001 by the paper's own formulas (2) to (13),
// group by group, positions only: the reference for the examples
// resources/examples/needle-876-alpha-*.linkage.json and the transmission angles mu_1, mu_2,
// mu_3. See README.md ("876-class needle mechanism") and resources/examples/README.md for the
// data the paper leaves out (y_C = 175, the straight lever with D opposite B).
#pragma once

#include "reference/scalar.h"
#include "reference/vec2.h"

namespace linkref {

template <class T>
class Needle876 {
 public:
  T OA{15}, AB{175}, BC{25}, CD{17}, DE{30}, EF{25}, EG{30}, b{20};
  Vec2<T> C{T(18), T(175)};

  struct State {
    Vec2<T> A, B, D, E, G;
    T mu1{}, mu2{}, mu3{};  // degrees: formulas (4), (7) and (11)
  };

  // alpha in degrees: F on its arc, formula (8).
  explicit Needle876(T alphaDeg) {
    // The lowest position: crank and coupler stretched, |OB| = OA + AB, B on the left of O->C.
    const Vec2<T> B0 = intersect(Vec2<T>{}, OA + AB, C, BC, T(1));
    phi0_ = atan2(B0.y, B0.x);
    const Vec2<T> D0 = C - (CD / BC) * (B0 - C);
    // The rocker EF horizontal, E to the right of F, F straight below C.
    const T xE = C.x + EF;
    E0_ = {xE, D0.y - sqrt(DE * DE - (xE - D0.x) * (xE - D0.x))};
    const T a = deg2rad(alphaDeg);
    F = {C.x + EF - EF * cos(a), E0_.y + EF * sin(a)};
    xH = C.x + b;
    sideB_ = side(Vec2<T>{OA * cos(phi0_), OA * sin(phi0_)}, C, B0);
    sideE_ = side(D0, F, E0_);
  }

  Vec2<T> F;
  T xH{};
  T CF() const { return C.y - E0_.y; }
  T phi0Deg() const { return phi0_ * T(180) / pi<T>(); }

  // At crank angle phi (degrees from the drawing, counter-clockwise).
  State at(T phiDeg) const {
    State s;
    const T p = phi0_ + deg2rad(phiDeg);
    s.A = {OA * cos(p), OA * sin(p)};  // (2)
    s.B = intersect(s.A, AB, C, BC, sideB_);
    s.D = C - (CD / BC) * (s.B - C);
    s.E = intersect(s.D, DE, F, EF, sideE_);
    const T sin62 = (xH - s.E.x) / EG;  // (11): (y_H2 - y_E2) / l_EG
    const T cos62 = sqrt(T(1) - sin62 * sin62);
    s.G = {xH, s.E.y - EG * cos62};  // (13)
    const T d1 = norm(C - s.A), d2 = norm(F - s.D);
    s.mu1 = acosDeg((AB * AB + BC * BC - d1 * d1) / (T(2) * AB * BC));  // (4)
    s.mu2 = acosDeg((DE * DE + EF * EF - d2 * d2) / (T(2) * DE * EF));  // (7)
    s.mu3 = T(90) - abs(atan2(sin62, cos62)) * T(180) / pi<T>();
    return s;
  }

 private:
  // The intersection of circles (P, r) and (Q, s) on the given side of P->Q (+1: left).
  static Vec2<T> intersect(Vec2<T> P, T r, Vec2<T> Q, T s, T sideSign) {
    const Vec2<T> d = Q - P;
    const T L = norm(d), m = (r * r - s * s + L * L) / (T(2) * L);
    const T h = sideSign * sqrt(r * r - m * m);
    return P + (m / L) * d + (h / L) * perp(d);
  }
  static T side(Vec2<T> P, Vec2<T> Q, Vec2<T> X) {
    return cross(Q - P, X - P) > T(0) ? T(1) : T(-1);
  }
  static T acosDeg(T c) { return atan2(sqrt(T(1) - c * c), c) * T(180) / pi<T>(); }

  T phi0_{};
  Vec2<T> E0_;
  T sideB_{1}, sideE_{1};
};

}  // namespace linkref
