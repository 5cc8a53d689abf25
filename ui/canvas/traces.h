// The paths of a mechanism's output points over one revolution of the crank (or between the
// limit positions of a crank that cannot turn fully), sampled on a copy of the kinematics so the
// document's pose is left alone.
#pragma once

#include <vector>

#include "linkage/kinematics.h"
#include "linkage/plane_view.h"

namespace linkage::ui {

// One path per output point, in the order of Mechanism::outputs; world coordinates, mm (a
// machine in space: as `view` shows them, linkage/plane_view.h).
std::vector<std::vector<Vec2>> tracePaths(const Kinematics& k, const PlaneView& view = {},
                                          double stepDeg = 1.0);

// The box every point and slot end of the mechanism passes through over that motion (what
// "fit to view" shows, so that nothing leaves the view while it runs); min and max corners.
std::pair<Vec2, Vec2> motionExtent(const Kinematics& k, const PlaneView& view = {},
                                   double stepDeg = 5.0);

}  // namespace linkage::ui
