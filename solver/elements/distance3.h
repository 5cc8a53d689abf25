// Two points at a distance in space (a ball rod): point s_i of body i, in the frame of its plane
// class f_i (elements/rows.h: Row::frame) at depth d_i along that frame's normal, stays at
// distance l from point s_j of body j. A body's pose (r, R) is planar in its class frame, whose
// axes E = [x_axis y_axis] (3 x 2) and normal n lift it to the world:
//
//   a = R_i s_i;   b = R_j s_j;   W_i = O_i + E_i (r_i + a) + n_i d_i   (likewise W_j)
//   D     = W_i - W_j
//   Phi   = (D . D - l^2) / (2 l)                  (1 row, mm: on_circle.h's, in space)
//   J     = [ g_i^T, g_i . perp(a) | -g_j^T, -g_j . perp(b) ] / l,   g = E^T D
//   gamma = (D . (E_i w_i^2 a - E_j w_j^2 b) - D' . D') / l
//           with D' = E_i (v_i + w_i perp(a)) - E_j (v_j + w_j perp(b))
// (From Phi'' = (D' . D' + D . D'') / l = 0 and D'' = E_i (J_i qdd_i - w_i^2 a) - likewise j.)
// When both frames are one and the depths equal, it is on_circle.h's row.
#pragma once

#include "elements/body_view.h"
#include "linkage/model.h"

namespace linkage::distance3 {

struct End {
  const BodyView& b;
  const Vec2& s;
  const Plane& f;
  double depth;
};

inline Vec3 lift(const Plane& f, const Vec2& v) {
  return v.x() * f.xAxis + v.y() * f.yAxis;
}

inline Vec3 world(const End& e) {
  return e.f.origin + lift(e.f, e.b.r + e.b.R * e.s) + e.depth * e.f.normal();
}

inline double residual(const End& i, const End& j, double l) {
  const Vec3 D = world(i) - world(j);
  return (D.squaredNorm() - l * l) / (2 * l);
}

template <class Mat>
inline void jacobian(Mat& J, int row, const End& i, const End& j, double l) {
  const Vec3 D = (world(i) - world(j)) / l;
  for (const auto& [e, sign] : {std::pair{&i, 1.0}, std::pair{&j, -1.0}}) {
    if (e->b.col < 0) continue;
    const Vec2 g(D.dot(e->f.xAxis), D.dot(e->f.yAxis));
    J(row, e->b.col) += sign * g.x();
    J(row, e->b.col + 1) += sign * g.y();
    J(row, e->b.col + 2) += sign * g.dot(perp(e->b.R * e->s));
  }
}

inline double gamma(const End& i, const End& j, double l) {
  const Vec2 a = i.b.R * i.s, b = j.b.R * j.s;
  const Vec3 D = world(i) - world(j);
  const Vec3 dD = lift(i.f, i.b.v + i.b.w * perp(a)) - lift(j.f, j.b.v + j.b.w * perp(b));
  const Vec3 centripetal = lift(i.f, i.b.w * i.b.w * a) - lift(j.f, j.b.w * j.b.w * b);
  return (D.dot(centripetal) - dD.squaredNorm()) / l;
}

// The row's gradient as forces per unit multiplier: g_i / l at W_i's place in i's frame on
// body i, and -g_j / l at W_j's in j's frame on body j.
inline void force(const End& i, const End& j, double l, Vec2 at[2], Vec2 u[2]) {
  const Vec3 D = (world(i) - world(j)) / l;
  at[0] = i.b.r + i.b.R * i.s;
  at[1] = j.b.r + j.b.R * j.s;
  u[0] = Vec2(D.dot(i.f.xAxis), D.dot(i.f.yAxis));
  u[1] = Vec2(D.dot(j.f.xAxis), D.dot(j.f.yAxis));
}

}  // namespace linkage::distance3
