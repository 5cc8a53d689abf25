// A point's stroke differentiated with respect to the dimensions (issue 29: "the derivative of
// ... a stroke"), exactly, by the envelope theorem: the stroke along a unit direction u is
// max - min of u . r(phi); at each of the two limit positions (found to 1e-9 degree of crank,
// linkage/limits.h) the crank derivative of u . r vanishes, so moving a dimension moves that
// extreme by u . dr/dp there, at its own crank angle, and
//   d(stroke)/dp = u . dr/dp (at the maximum) - u . dr/dp (at the minimum)
// with dr/dp the exact derivative of linkage/sensitivity.h. Where an extreme is not a limit
// position (a motion that does not repeat after a turn: its end counts) the theorem does not
// hold and the result says so.
#pragma once

#include <string>
#include <vector>

#include "linkage/limits.h"
#include "linkage/sensitivity.h"

namespace linkage {

struct StrokeSensitivity {
  Status status;  // BadModel (what cannot be differentiated), the limits' or a singular pose's
  Limits limits;  // the stroke, its extremes and their crank angles
  std::vector<Dimension> dims;
  std::vector<double> derivative;  // d(stroke)/d(dimension k): mm per mm, degree or ratio
};

StrokeSensitivity strokeSensitivity(const Kinematics& k, PointId p, const Vec2& direction,
                                    std::vector<Dimension> dims);

}  // namespace linkage
