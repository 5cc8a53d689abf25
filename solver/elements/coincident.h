// Coincident points (a pin; a block in an arc slot at the arc's centre): point s_i of body i and
// point s_j of body j are one point.
//
//   Phi   = r_i + R_i s_i - r_j - R_j s_j                          (2 rows, mm)
//   J     = [ I, perp(a) | -I, -perp(b) ]   with a = R_i s_i, b = R_j s_j, columns (x, y, theta)
//   gamma = w_i^2 a - w_j^2 b                                     (J qdd = gamma)
#pragma once

#include "elements/body_view.h"

namespace linkage::coincident {

inline Vec2 residual(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& sj) {
  return i.r + i.R * si - j.r - j.R * sj;
}

// Writes the two Jacobian rows at `row` of J (only the columns of moving bodies).
template <class Mat>
inline void jacobian(Mat& J, int row, const BodyView& i, const Vec2& si, const BodyView& j,
                     const Vec2& sj) {
  if (i.col >= 0) {
    const Vec2 a = perp(i.R * si);
    J(row, i.col) += 1;
    J(row + 1, i.col + 1) += 1;
    J(row, i.col + 2) += a.x();
    J(row + 1, i.col + 2) += a.y();
  }
  if (j.col >= 0) {
    const Vec2 b = perp(j.R * sj);
    J(row, j.col) -= 1;
    J(row + 1, j.col + 1) -= 1;
    J(row, j.col + 2) -= b.x();
    J(row + 1, j.col + 2) -= b.y();
  }
}

inline Vec2 gamma(const BodyView& i, const Vec2& si, const BodyView& j, const Vec2& sj) {
  return i.w * i.w * (i.R * si) - j.w * j.w * (j.R * sj);
}

}  // namespace linkage::coincident
