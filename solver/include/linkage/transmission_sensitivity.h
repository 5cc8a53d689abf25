// A dyad's transmission angle differentiated with respect to the dimensions (issue 29), exactly:
// mu is the angle between the lines u = C->P1 and w = C->P2 of the dyad (linkage/transmission.h),
// and a line turns by cross(u, du) / |u|^2 when its ends move by du, so
//   d(mu)/dp = sign(turn) (cross(w, dw) / |w|^2 - cross(u, du) / |u|^2),
// du and dw from the points' exact sensitivities (linkage/sensitivity.h). Degrees per unit of
// the dimension (mm, degree or ratio).
//
// Only a dyad between points: a rod on a slider or in a slot, and a dyad whose line runs to an
// arc slot's centre (a centre is no point of the mechanism: its sensitivity is not one of
// linkage/sensitivity.h's), are refused by name.
#pragma once

#include <vector>

#include "linkage/sensitivity.h"
#include "linkage/transmission.h"

namespace linkage {

// Success, or BadModel naming the angle (its label) and why it has no derivatives yet.
Status dyadDifferentiable(const Mechanism& m, const TransmissionJoint& j);

// mu at k's pose, degrees (0 to 180), and with sens (its at() done at this pose) and d,
// d(mu)/d(dimension dim) in degrees per unit. For a dyad between points (above).
double dyadAngleSensitivity(const Kinematics& k, const TransmissionJoint& j,
                            const Sensitivity* sens, int dim, double* d);

// d(mu)/d(dimension) for each of s's dimensions, at k's pose (s.at(k) done).
std::vector<double> dyadAngleDerivatives(const Kinematics& k, const TransmissionJoint& j,
                                         const Sensitivity& s);

}  // namespace linkage
