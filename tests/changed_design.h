// A design with one of its dimensions changed (changeDimensions, exact): what the tests that
// hold derivatives to changed designs solved again (central differences) start from.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "linkage/dimension_change.h"
#include "linkage/kinematics.h"

namespace linkage::test {

// m with dimension d changed by `by`; a failure of the test (naming the dimension) where the
// change cannot be drawn.
inline Mechanism changedDesign(const Mechanism& m, const std::vector<Dimension>& dims, size_t d,
                               double by) {
  std::vector<double> delta(dims.size(), 0.0);
  delta[d] = by;
  Mechanism out = m;
  const Status s = changeDimensions(out, dims, delta);
  EXPECT_TRUE(s.ok()) << dims[d].name << ": " << s.message;
  return out;
}

// Both sides of a central difference, dimension d changed by -h and +h, solved: false where
// either does not load.
inline bool loadChangedPair(const Mechanism& m, const std::vector<Dimension>& dims, size_t d,
                            double h, Kinematics (&k)[2]) {
  for (int side = 0; side < 2; ++side)
    if (!k[side].load(changedDesign(m, dims, d, side ? h : -h)).ok()) return false;
  return true;
}

}  // namespace linkage::test
