// The Jacobian the forces are solved with (linkage/dynamics.h: a cam's contact row in place of
// its kinematic row, elements/cam_row.h) and its change along a dimension with a vector held,
// for a reaction's derivative (linkage/force_sensitivity.h). A planar machine's.
#pragma once

#include <Eigen/Core>

#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"

namespace linkage {

// Dense, by the kinematics' independent rows (their row map), at k's pose.
Eigen::MatrixXd forcesJacobian(const Kinematics& k);

// d(J w)/d(dimension dim) with w held, J forcesJacobian(k): the kinematics' rows'
// (Sensitivity::jacobianChange), each cam's contact row's from its contact's change
// (cam::contactChange): J_contact w = n . (the follower's velocity at the contact C less the
// cam's there), so it changes by dn . (that) + n . (w_f perp(dC - dr_f) - w_c perp(dC - dr_c)).
Eigen::VectorXd forcesJacobianChange(const Kinematics& k, const Sensitivity& s,
                                     const Eigen::VectorXd& w, int dim);

}  // namespace linkage
