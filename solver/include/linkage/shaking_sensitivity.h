// The exact derivative of a planar machine's shaking force (linkage/dynamics.h shaking(): what
// the frame feels, sum over the bodies of m (g - a) at their centres of mass, with the loads)
// with respect to a dimension (linkage/sensitivity.h). The loads and the weights are the same in
// every design, and a dimension moves a body's points, not its mass (its centre stays where it
// is drawn in the body), so dF/dp = -sum m da/dp, each centre's acceleration's exact derivative.
#pragma once

#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"

namespace linkage {

// N per unit of dimension `dim`, at the pose of s's last at() (k's pose). A planar machine's.
Vec2 shakingForceSensitivity(const Kinematics& k, const Sensitivity& s, int dim);

// The same in the world (linkage/dynamics.h shaking(k, Vec3&, Vec3&)), any machine (in space, s
// prepared with Space::World): each moving body's force's change (its centre's acceleration's,
// linkage/force_sensitivity.h generalizedForcesChange) lifted from its plane class's frame; the
// weights and loads do not change.
Vec3 shakingForceSensitivity3(const Kinematics& k, const Sensitivity& s, int dim);

}  // namespace linkage
