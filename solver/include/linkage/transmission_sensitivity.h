// A transmission angle differentiated with respect to the dimensions (issue 29), exactly, for
// each kind linkage/transmission.h reads. A line turns by cross(u, du) / |u|^2 when its ends
// move by du, so
// - a dyad's mu, the angle between the lines u = C->P1 and w = C->P2, changes by
//     d(mu)/dp = sign(turn) (cross(w, dw) / |w|^2 - cross(u, du) / |u|^2),
//   du and dw from the ends' exact sensitivities (linkage/sensitivity.h). An end at an arc
//   slot's centre (a block in a curved guide, a pin in an arc slot) is no point of the
//   mechanism: the centre is where the slot's body carries it, moved in the drawing by the
//   dimension (linkage/slot_sensitivity.h); a block's point there is held at the centre by its
//   joint whatever the dimensions, so it moves as the centre does.
// - a rod's mu = 90 - |theta|, theta the angle from the slot's line to the rod's, changes by
//     d(mu)/dp = -sign(theta) (cross(u, du) / |u|^2 - dbeta/dp - cross(t, dt) / |t|^2),
//   beta the angle of the slot's body and t = p1 - p0 the slot as drawn, dt its ends' move.
// On a machine in space each angle lies in its link's plane class (the sensitivities prepared
// with Sensitivity::Space::World: point() gives a moving point's move in that class's frame);
// a rod's slot is read there (slotLine in linkage/transmission.h), a ground slot's move with its
// ends' z seen along the class's normal, and an arc's centre and its move in that frame too
// (SpaceMoves::arcMove: from its three points' moves there).
// Degrees per unit of the dimension (mm, degree or ratio).
#pragma once

#include <string>
#include <vector>

#include "linkage/sensitivity.h"
#include "linkage/transmission.h"

namespace linkage {

// mu at k's pose, degrees (0 to 180; a rod's 0 to 90), and with sens (its at() done at this
// pose) and d, d(mu)/d(dimension dim) in degrees per unit.
double transmissionAngleSensitivity(const Kinematics& k, const TransmissionJoint& j,
                                    const Sensitivity* sens, int dim, double* d);

// d(mu)/d(dimension) for each of s's dimensions, at k's pose (s.at(k) done).
std::vector<double> transmissionAngleDerivatives(const Kinematics& k, const TransmissionJoint& j,
                                                 const Sensitivity& s);

}  // namespace linkage
