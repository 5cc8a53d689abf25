// Slider (prismatic) joint: a block, body i, slides in a slot of body j without turning relative
// to it. Two rows: point s_i on the slot line (the pin-in-slot row, joint_pin_in_slot.h), and the
// relative angle held at its sketch value c:
//
//   Phi   = L (theta_i - theta_j - c)          (1 row; L = mechanism size makes it a length, so
//                                              all rows share one scale for tolerances and rank)
//   J     = [ 0, 0, L | 0, 0, -L ]
//   gamma = 0
// The driver (driver.h) is the same row with c growing with the crank angle.
#pragma once

#include "solve/body_view.h"

namespace linkage::angle {

inline double residual(double thetaI, double thetaJ, double c, double L) {
  return L * (thetaI - thetaJ - c);
}

template <class Mat>
inline void jacobian(Mat& J, int row, const BodyView& i, const BodyView& j, double L) {
  if (i.col >= 0) J(row, i.col + 2) += L;
  if (j.col >= 0) J(row, j.col + 2) -= L;
}

}  // namespace linkage::angle
