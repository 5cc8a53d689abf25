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

// The shaking moment's (linkage/dynamics.h shaking(): about the drawing's origin, N m) per unit
// of dimension `dim`, at the pose of s's last at(). The frame feels each body's force F_b at its
// frame origin r_b with the moment M_b about it, so M = sum (M_b + r_b x F_b) and dM = sum (dM_b +
// dr_b x F_b + r_b x dF_b): dM_b, dF_b the generalized forces' change (with the loads' arms),
// dr_b the frame's move. A planar machine's (NaN at a singular position).
double shakingMomentSensitivity(const Kinematics& k, const Sensitivity& s, int dim);

// The same in the world (linkage/dynamics.h shaking(k, Vec3&, Vec3&): about the world's origin,
// N m), any machine (in space, s prepared with Space::World): each body's force and moment about
// its frame origin at its depth, and its weight's part along its plane's normal at its centre of
// mass, as the origin, the depth, the centre and the forces move. On a planar machine (0, 0,
// shakingMomentSensitivity) and the weights' tilt where gravity has a z. NaN where singular.
Vec3 shakingMomentSensitivity3(const Kinematics& k, const Sensitivity& s, int dim);

}  // namespace linkage
