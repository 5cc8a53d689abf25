// A pin's reaction differentiated with respect to the dimensions (issue 29: "the derivative of
// ... a force"), exactly. The joints' multipliers balance the bodies' applied and inertia forces,
// J^T lambda = Q; along a dimension p both sides change, J with the pose (dq/dp) and the
// constants, Q with the motion (dq/dp, dq'/dp, dq''/dp: the centres' accelerations, the moment
// arms), so J^T dlambda = dQ - dJ^T lambda. One component, lambda_r = w . Q with w = J^-1 e_r
// (the motion that opens row r by one unit: the reaction is the work of Q on it), changes by
//   dlambda_r = w . dQ - lambda . (dJ w),
// dJ w the change of J w with w held, what the velocities' sensitivities already compute for
// J q' (linkage/sensitivity.h, Sensitivity::jacobianChange): no second derivative is written
// out again. A pin's reaction is its two multipliers (linkage/dynamics.h's sign). A planar
// machine's; joints of other kinds (a slider's normal force turns with its slot), cams, and
// redundant joints (their shares are not determined) are refused by name.
#pragma once

#include <vector>

#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"

namespace linkage {

struct JointForceSensitivity {
  Status status;
  Vec2 force = Vec2::Zero();  // the reaction (linkage/dynamics.h JointReaction::force), N
  std::vector<Dimension> dims;
  std::vector<Vec2> derivative;  // d(force)/d(dimension k), N per unit
};

// At k's pose and speed, for the pin `joint`.
JointForceSensitivity jointForceSensitivity(const Kinematics& k, JointId joint,
                                            std::vector<Dimension> dims);

}  // namespace linkage
