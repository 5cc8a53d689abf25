// The dimensions of a machine in space beyond the planar ones (linkage/sensitivity.h,
// analysis/dimensions.cpp): depths, the ground's z, ball rods' lengths, planes' origins, and a
// ground slot's offset and angle in its block's plane.
#pragma once

#include <string>
#include <vector>

#include "linkage/sensitivity.h"

namespace linkage::internal {

// Whether the mechanism has dimensions only a machine in space has (a plane, a third number, a
// ball rod).
bool hasSpaceDimensions(const Mechanism& m);
// A straight ground slot's offset and angle in the plane of the block running in it, an arc's
// centre (world x, y, z) and radius (none when no joint runs in it).
void groundSlotInSpace(const Mechanism& m, const Slot& s, std::vector<Dimension>& out);
// Appends the depths, the ground's z, the rods' lengths and the planes' origins.
void spaceDimensions(const Mechanism& m, std::vector<Dimension>& out);

}  // namespace linkage::internal
