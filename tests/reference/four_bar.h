// Closed-form four-bar linkage (Freudenstein / Norton style, written with vectors so that the
// ground may lie at any angle). See README.md for the derivation and conventions.
#pragma once

#include <algorithm>
#include <stdexcept>

#include "reference/scalar.h"
#include "reference/vec2.h"

namespace linkref {

// Open: B lies to the left of the directed line from the crank pin A to the rocker pivot O4
// (cross(O4 - A, B - A) > 0). With the ground drawn from O2 on the left to O4 on the right this is
// Norton's open circuit (B above the ground line when the crank points up); the orientation of
// triangle A B O4 can only change at a toggle, so the choice holds for a whole circuit.
enum class FourBarBranch { kOpen, kCrossed };

// Ground pivots O2 (crank) and O4 (rocker); crank O2A = r2, coupler AB = r3, rocker O4B = r4.
// Absolute crank angle theta2 = theta20 + s phi (rad, ccw from +x), phi = omega t.
// Coupler point P = A + px u + py n, u = (B - A) / |B - A|, n = u turned +90 degrees.
template <class T>
struct FourBarParams {
  Vec2<T> O2, O4;
  T r2{}, r3{}, r4{};
  T theta20{};
  int s = 1;  // +1 ccw, -1 cw
  T omega{};  // rad/s, > 0
  FourBarBranch branch = FourBarBranch::kOpen;
  T px{}, py{};
};

// Angles are absolute, ccw from +x, rad: theta3 of A->B, theta4 of O4->B. Time derivatives use
// the constant crank speed (alpha2 = 0).
template <class T>
struct FourBarState {
  T theta2{}, w2{};
  T theta3{}, w3{}, al3{};
  T theta4{}, w4{}, al4{};
  Vec2<T> A, vA, aA;
  Vec2<T> B, vB, aB;
  Vec2<T> P, vP, aP;
};

// (d^2 - (r3 - r4)^2) ((r3 + r4)^2 - d^2), d = |O4 - A|: 16 times the squared area of triangle
// A B O4, so it is >= 0 exactly when the coupler and rocker can close at crank angle phi (rad).
template <class T>
T four_bar_discriminant(const FourBarParams<T>& p, T phi) {
  const T th2 = p.theta20 + T(p.s) * phi;
  const Vec2<T> A = p.O2 + p.r2 * unit_at(th2);
  const Vec2<T> D = p.O4 - A;
  const T d2 = dot(D, D);
  const T dm = p.r3 - p.r4, dp = p.r3 + p.r4;
  return (d2 - dm * dm) * (dp * dp - d2);
}

template <class T>
bool four_bar_reachable(const FourBarParams<T>& p, T phi) {
  return four_bar_discriminant(p, phi) >= T(0);
}

template <class T>
FourBarState<T> four_bar(const FourBarParams<T>& p, T phi) {
  FourBarState<T> st;
  st.theta2 = p.theta20 + T(p.s) * phi;
  st.w2 = T(p.s) * p.omega;
  const T w2 = st.w2;

  const Vec2<T> a = p.r2 * unit_at(st.theta2);  // O2 -> A
  st.A = p.O2 + a;
  st.vA = w2 * perp(a);
  st.aA = -(w2 * w2) * a;

  // B from the two circles about A (r3) and O4 (r4): foot of the altitude at distance m from A
  // along A->O4, height h to the chosen side.
  const Vec2<T> D = p.O4 - st.A;
  const T d2 = dot(D, D);
  const T d = sqrt(d2);
  const T m = (p.r3 * p.r3 - p.r4 * p.r4 + d2) / (T(2) * d);
  const T h2 = p.r3 * p.r3 - m * m;
  if (!(h2 >= T(0)) || !(d > T(0)))
    throw std::domain_error("four_bar: coupler and rocker cannot close at this crank angle");
  const T side = p.branch == FourBarBranch::kOpen ? T(1) : T(-1);
  const T h = side * sqrt(h2);
  st.B = st.A + (m / d) * D + (h / d) * perp(D);

  const Vec2<T> b = st.B - st.A;  // coupler, length r3
  const Vec2<T> c = st.B - p.O4;  // rocker, length r4
  st.theta3 = angle_of(b);
  st.theta4 = angle_of(c);

  // Loop a + b - c - (O4 - O2) = 0 differentiated once and twice gives, for (w3, w4) and then
  // (al3, al4), the same 2x2 matrix [[-b.y, c.y], [b.x, -c.x]]; solve by Cramer's rule.
  const T det = b.y * c.x - c.y * b.x;
  if (det == T(0)) throw std::domain_error("four_bar: toggle position, velocities undefined");
  auto solve = [&](T r0, T r1, T& u3, T& u4) {
    u3 = (r0 * (-c.x) - c.y * r1) / det;
    u4 = ((-b.y) * r1 - b.x * r0) / det;
  };
  solve(a.y * w2, -a.x * w2, st.w3, st.w4);
  const T w3 = st.w3, w4 = st.w4;
  solve(a.x * w2 * w2 + b.x * w3 * w3 - c.x * w4 * w4,
        a.y * w2 * w2 + b.y * w3 * w3 - c.y * w4 * w4, st.al3, st.al4);

  st.vB = st.vA + w3 * perp(b);
  st.aB = st.aA + st.al3 * perp(b) - (w3 * w3) * b;

  const T len = norm(b);
  const Vec2<T> u = (T(1) / len) * b;
  const Vec2<T> q = p.px * u + p.py * perp(u);  // A -> P
  st.P = st.A + q;
  st.vP = st.vA + w3 * perp(q);
  st.aP = st.aA + st.al3 * perp(q) - (w3 * w3) * q;
  return st;
}

// Grashof classes by which link is the shortest (s + l < p + q), after Norton.
enum class Grashof {
  kCrankRocker,   // shortest is the crank (input link r2)
  kDoubleCrank,   // shortest is the ground
  kDoubleRocker,  // Grashof double rocker: shortest is the coupler
  kRockerCrank,   // shortest is the rocker r4 (it turns fully, the input rocks)
  kChangePoint,   // s + l = p + q (within rel_tol of the longest link)
  kTripleRocker,  // non-Grashof: s + l > p + q, no link turns fully
};

template <class T>
Grashof grashof_class(T r1, T r2, T r3, T r4, T rel_tol = T(0)) {
  T L[4] = {r1, r2, r3, r4};
  T sorted[4] = {r1, r2, r3, r4};
  std::sort(sorted, sorted + 4);
  const T sum_sl = sorted[0] + sorted[3], sum_pq = sorted[1] + sorted[2];
  if (abs(sum_sl - sum_pq) <= rel_tol * sorted[3]) return Grashof::kChangePoint;
  if (sum_sl > sum_pq) return Grashof::kTripleRocker;
  // Ties for the shortest favour the crank, then the ground, as a designer would read them.
  if (L[1] == sorted[0]) return Grashof::kCrankRocker;
  if (L[0] == sorted[0]) return Grashof::kDoubleCrank;
  if (L[2] == sorted[0]) return Grashof::kDoubleRocker;
  return Grashof::kRockerCrank;
}

template <class T>
Grashof grashof_class(const FourBarParams<T>& p, T rel_tol = T(0)) {
  return grashof_class(norm(p.O4 - p.O2), p.r2, p.r3, p.r4, rel_tol);
}

// The crank-rocker of resources/examples/four-bar-crank-rocker.linkage.json: O2 = (0, 0),
// O4 = (60, 0), crank 20, coupler 70, rocker 50, crank at 60 degrees in the sketch, open circuit,
// coupler point (35, 25), 60 rpm ccw. Crank angle 0 is the sketch.
template <class T>
FourBarParams<T> four_bar_crank_rocker_example() {
  FourBarParams<T> p;
  p.O2 = {T(0), T(0)};
  p.O4 = {T(60), T(0)};
  p.r2 = T(20);
  p.r3 = T(70);
  p.r4 = T(50);
  p.theta20 = pi<T>() / T(3);
  p.s = 1;
  p.omega = rpm_to_rad_s(T(60));
  p.branch = FourBarBranch::kOpen;
  p.px = T(35);
  p.py = T(25);
  return p;
}

}  // namespace linkref
