// A point on a circle (a pin in an arc slot): point s_i of body i stays at distance rho from the
// point c_j of body j (the arc's centre, in j's frame).
//
//   a = R_i s_i;   b = R_j c_j;   d = r_i + a - r_j - b
//   Phi   = (d . d - rho^2) / (2 rho)          (1 row, mm: the distance's error to first order,
//                                              smooth through d = 0, unlike |d| - rho)
//   J     = [ d^T, d . perp(a) | -d^T, -d . perp(b) ] / rho
//   gamma = (d . (w_i^2 a - w_j^2 b) - d' . d') / rho
//           with d' = v_i + w_i perp(a) - v_j - w_j perp(b)
// (From Phi'' = (d' . d' + d . d'') / rho = 0 and d'' = J qdd - w_i^2 a + w_j^2 b.)
#pragma once

#include "elements/body_view.h"

namespace linkage::on_circle {

inline double residual(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& cj,
                       double rho) {
  const Vec2 d = i.r + i.R * si - j.r - j.R * cj;
  return (d.squaredNorm() - rho * rho) / (2 * rho);
}

template <class Mat>
inline void jacobian(Mat& J, int row, const BodyView& i, const Vec2& si, const BodyView& j,
                     const Vec2& cj, double rho) {
  const Vec2 a = i.R * si, b = j.R * cj;
  const Vec2 d = (i.r + a - j.r - b) / rho;
  if (i.col >= 0) {
    J(row, i.col) += d.x();
    J(row, i.col + 1) += d.y();
    J(row, i.col + 2) += d.dot(perp(a));
  }
  if (j.col >= 0) {
    J(row, j.col) -= d.x();
    J(row, j.col + 1) -= d.y();
    J(row, j.col + 2) -= d.dot(perp(b));
  }
}

inline double gamma(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& cj,
                    double rho) {
  const Vec2 a = i.R * si, b = j.R * cj;
  const Vec2 d = i.r + a - j.r - b;
  const Vec2 dd = i.v + i.w * perp(a) - j.v - j.w * perp(b);
  return (d.dot(i.w * i.w * a - j.w * j.w * b) - dd.squaredNorm()) / rho;
}

}  // namespace linkage::on_circle
