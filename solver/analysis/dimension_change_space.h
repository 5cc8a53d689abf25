// Exact changes of the dimensions only a machine in space has (linkage/dimension_change.h,
// analysis/dimensions_space.h), each the finite form of its derivative's move of the drawing.
#pragma once

#include <string>
#include <vector>

#include "linkage/sensitivity.h"
#include "linkage/status.h"

namespace linkage::internal {

// Depths and ground z: the third number moved; a plane's origin: the plane moved (its bodies'
// points keep their plane coordinates, so they move with it in the world); a ground slot of a
// machine in space: turned about its first end around the normal of its block's plane, then
// moved across it in that plane (x, y and z of both ends).
Status changeInSpace(Mechanism& m, const std::vector<Dimension>& dims,
                     const std::vector<double>& delta);

// Each ball rod's length as the changes make it: as drawn, plus its own dimension's change.
struct RodLength {
  JointId rod;
  double length = 0;
};
std::vector<RodLength> rodLengths(const Mechanism& m, const std::vector<Dimension>& dims,
                                  const std::vector<double>& delta);

// The rods back at `rods`' lengths, last. The file keeps a rod's length as its ends' drawn
// distance, which a rod's own change and any other that moves an end (a depth, a plane, a
// body's dimension) change; the derivatives hold every other dimension, the rods' lengths
// among them. So where a drawn length differs, the machine is solved at the drawing's crank
// angle with the rods' lengths and every body the solve moves is redrawn there, rigidly (its
// plane coordinates turned and shifted, its depths kept): the bodies keep their shapes, each
// rod reads back its length, and the machine is the derivative's exactly. `what` names the
// changes in a refusal.
Status keepRodLengths(Mechanism& m, const std::vector<RodLength>& rods, const std::string& what);

}  // namespace linkage::internal
