// A point on a line (a pin in a straight slot; with an angle row, a block in one): point s_i of
// body i stays on the line of body j through u_j with unit normal n_j, both in j's frame.
//
//   p = r_i + a, a = R_i s_i;   q = r_j + b, b = R_j u_j;   n = R_j n_j;   d = p - q
//   Phi   = n . d                                                   (1 row, mm)
//   J     = [ n^T, n . perp(a) | -n^T, perp(n) . (p - r_j) ]
//   gamma = w_j^2 (n . d) - 2 w_j perp(n) . d' + w_i^2 (n . a) - w_j^2 (n . b)
//           with d' = v_i + w_i perp(a) - v_j - w_j perp(b)
#pragma once

#include "elements/body_view.h"

namespace linkage::on_line {

inline double residual(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& uj,
                       const Vec2& nj) {
  return (j.R * nj).dot(i.r + i.R * si - j.r - j.R * uj);
}

template <class Mat>
inline void jacobian(Mat& J, int row, const BodyView& i, const Vec2& si, const BodyView& j,
                     const Vec2& nj) {
  const Vec2 n = j.R * nj;
  const Vec2 a = i.R * si;
  if (i.col >= 0) {
    J(row, i.col) += n.x();
    J(row, i.col + 1) += n.y();
    J(row, i.col + 2) += n.dot(perp(a));
  }
  if (j.col >= 0) {
    J(row, j.col) -= n.x();
    J(row, j.col + 1) -= n.y();
    J(row, j.col + 2) += perp(n).dot(i.r + a - j.r);
  }
}

inline double gamma(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& uj,
                    const Vec2& nj) {
  const Vec2 n = j.R * nj;
  const Vec2 a = i.R * si;
  const Vec2 b = j.R * uj;
  const Vec2 d = i.r + a - j.r - b;
  const Vec2 dd = i.v + i.w * perp(a) - j.v - j.w * perp(b);
  return j.w * j.w * n.dot(d) - 2 * j.w * perp(n).dot(dd) + i.w * i.w * n.dot(a) -
         j.w * j.w * n.dot(b);
}

}  // namespace linkage::on_line
