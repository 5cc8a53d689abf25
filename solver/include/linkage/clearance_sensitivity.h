// A clearance's closest approach differentiated with respect to the dimensions (issue 29: "the
// derivative of ... a clearance minimum"), exactly, by the envelope theorem: at the closest
// crank angle (found to 1e-9 degree, linkage/clearance.h) the distance's crank derivative
// vanishes, and so does its derivative along the part (the nearest point of a segment or a
// slot), so moving a dimension changes the least distance by
//   d(min)/dp = n . (dA/dp - dB/dp),   n = (A - B) / |A - B|
// at that pose, with A the point, B the other point or the nearest point of the part held at
// its place on the part: on a rigid body the point at parameter t of a segment is
// (1 - t) N + t E, so its derivative is (1 - t) dN/dp + t dE/dp, from linkage/sensitivity.h; a
// slot's point is fixed in the slot's body and moves in its drawing as the slot does
// (linkage/slot_sensitivity.h): a straight slot's as its ends at t, an arc's end as that end,
// and an arc's point between its ends radially, with its centre and radius (n is radial there).
// Where the two touch (a distance of 0: no derivative) or where the motion does not repeat after
// a turn, the result says so instead.
#pragma once

#include <vector>

#include "linkage/clearance.h"
#include "linkage/sensitivity.h"

namespace linkage {

struct ClearanceSensitivity {
  Status status;
  Clearance clearance;  // the closest approach and its crank angle
  std::vector<Dimension> dims;
  std::vector<double> derivative;  // d(least distance)/d(dimension k)
};

ClearanceSensitivity clearanceSensitivity(const Kinematics& k, const ClearanceWatch& watch,
                                          std::vector<Dimension> dims);

}  // namespace linkage
