// A linear relation of body angles (a block's angle in a straight slot; a gear or belt; the
// driver): up to three bodies k with coefficients c_k, a constant and the driver angle phi.
//
//   Phi   = L (sum_k c_k theta_k - value - driven phi)   (1 row; L = mechanism size makes it a
//                                                         length, so all rows share one scale)
//   J     = [ 0, 0, L c_0 | 0, 0, L c_1 | 0, 0, L c_2 ]   (Phi_phi = -L driven)
//   gamma = 0
// A slider holds theta_i - theta_j at its drawn value (c = 1, -1); a gear theta_b - theta_c =
// ratio (theta_a - theta_c) (c = 1, -ratio, ratio - 1); the driver theta_b - theta_a = sigma phi.
// Kinematics are solved in phi: q' and q'' do not depend on the speed, and qdot = omega q',
// qddot = omega^2 q'' for omega = 2 pi rpm / 60.
#pragma once

#include "elements/body_view.h"

namespace linkage::angles {

inline double driveSign(bool clockwise) {
  return clockwise ? -1.0 : 1.0;
}

}  // namespace linkage::angles
