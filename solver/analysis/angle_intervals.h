// Intervals of crank angle over one cycle where a condition holds, from where it toggles.
#pragma once

#include <vector>

#include "linkage/timing.h"

namespace linkage {

// The condition holds at 0+ when `holdsAtStart`, and changes at each of `toggles` (ascending;
// those at or outside the ends are ignored: a toggle at 360 is the one at 0 the start says).
// With `periodic`, an interval that ends at 360 and one that starts at 0 are one, wrapping.
std::vector<AngleInterval> intervalsOf(bool holdsAtStart, const std::vector<double>& toggles,
                                       bool periodic);

}  // namespace linkage
