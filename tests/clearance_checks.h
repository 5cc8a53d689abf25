// A clearance's derivatives (linkage/clearance_sensitivity.h) against the changed designs' least
// distances (in the tests only): each dimension changed by -h and +h (changeDimensions), the
// design solved again and its closest approach found again (findClearance), central differences.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "changed_design.h"
#include "linkage/clearance_sensitivity.h"

namespace linkage::test {

inline void expectClosestMovesAsChangedDesignsDo(const Mechanism& m, const ClearanceWatch& w,
                                                 double h) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const ClearanceSensitivity s = clearanceSensitivity(k, w, dims);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_EQ(s.derivative.size(), dims.size());
  double largest = 0;
  for (size_t d = 0; d < dims.size(); ++d) {
    if (dims[d].ratioOf) continue;  // shafts geared apart would not come back after a turn
    double least[2];
    Kinematics kc[2];
    ASSERT_TRUE(loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
    for (int side = 0; side < 2; ++side) {
      const Clearance cl = findClearance(kc[side], ClearancePart::of(w.point), w.other);
      ASSERT_TRUE(cl.status.ok()) << dims[d].name;
      least[side] = cl.closest.distance;
    }
    const double want = (least[1] - least[0]) / (2 * h);
    largest = std::max(largest, std::abs(want));
    EXPECT_NEAR(s.derivative[d], want, 1e-6 * (1 + std::abs(want))) << dims[d].name;
  }
  EXPECT_GT(largest, 0.1);  // the distance does depend on the dimensions
}

}  // namespace linkage::test
