// Every joint's reaction's derivatives (linkage/force_sensitivity.h) against the changed designs'
// forces (changeDimensions, the whole solve again): central differences, to 1e-5 of the
// reaction's size (its force, its couple in N mm, a cam's contact force), every dimension, every
// stepDeg degrees of crank from 10. For what has no closed form in the tests.
#pragma once

#include <gtest/gtest.h>

#include "changed_design.h"
#include "linkage/dimension_change.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"

namespace linkage::test {

inline void expectReactionsMoveAsChangedDesignsDo(const Mechanism& m, int stepDeg = 40) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const double h = 1e-5;
  for (size_t d = 0; d < dims.size(); ++d) {
    Kinematics kc[2];
    ASSERT_TRUE(loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
    for (int deg = 10; deg < 360; deg += stepDeg) {
      ASSERT_TRUE(k.moveTo(deg).ok() && kc[0].moveTo(deg).ok() && kc[1].moveTo(deg).ok());
      const Forces f[2] = {computeForces(kc[0]), computeForces(kc[1])};
      for (size_t j = 0; j < m.joints.size(); ++j) {
        const JointForceSensitivity s = jointForceSensitivity(k, m.joints[j].id, dims);
        ASSERT_TRUE(s.status.ok()) << s.status.message;
        const JointReaction &p = f[1].joints[j], &q = f[0].joints[j], &c = s.change[d];
        const Eigen::Vector4d want(
            (p.force.x() - q.force.x()) / (2 * h), (p.force.y() - q.force.y()) / (2 * h),
            1000 * (p.coupleNm - q.coupleNm) / (2 * h), (p.contactN - q.contactN) / (2 * h));
        const Eigen::Vector4d got(c.force.x(), c.force.y(), 1000 * c.coupleNm, c.contactN);
        const double size = 1 + s.force.norm() + 1000 * std::abs(s.reaction.coupleNm);
        EXPECT_LT((got - want).norm(), 1e-5 * size)
            << dims[d].name << " joint " << j << " at " << deg;
      }
    }
  }
}

}  // namespace linkage::test
