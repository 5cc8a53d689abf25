// A point's stroke differentiated with respect to the dimensions (issue 29: "the derivative of
// ... a stroke"), exactly, by the envelope theorem: the stroke along a unit direction u is
// max - min of u . r(phi); at each of the two limit positions (found to 1e-9 degree of crank,
// linkage/limits.h) the crank derivative of u . r vanishes, so moving a dimension moves that
// extreme by u . dr/dp there, at its own crank angle, and
//   d(stroke)/dp = u . dr/dp (at the maximum) - u . dr/dp (at the minimum)
// with dr/dp the exact derivative of linkage/sensitivity.h. Where an extreme is not a limit
// position (a motion that does not repeat after a turn: its end counts) the theorem does not
// hold and the result says so.
//
// On a machine in space (planes, docs/spatial.md) the stroke is along a direction in the world,
// u . r with r the point's world x, y, z, as `linkage-cli limits` measures a point there
// (LimitMeasure::alongInSpace), and dr/dp is the world's (Sensitivity::Space::World, point3).
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
// Along a direction in the world: on a machine in space any (x, y, z); on a planar one its z
// must be 0 (the planar stroke above).
StrokeSensitivity strokeSensitivity(const Kinematics& k, PointId p, const Vec3& direction,
                                    std::vector<Dimension> dims);

// The direction a point's stroke is taken along by default: defaultDirection (linkage/limits.h)
// on a planar machine; on a machine in space the world's +y, as `linkage-cli limits` takes it
// there (a slot's direction is in its block's plane, which need not be the world's).
Vec3 strokeDirection(const Mechanism& m, PointId p);

}  // namespace linkage
