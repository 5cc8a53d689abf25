// A machine in space's reactions differentiated with respect to its dimensions (linkage/
// force_sensitivity.h): the RSSR crank-rocker with masses on its crank and rocker and gravity
// across both planes, every joint's in-plane reaction (a pin's force in its plane class's frame)
// and the ball rod's tension, against the changed designs (changeDimensions: depths, ground z,
// the rod's length and the planes' origins drawn exactly; central differences, 1e-6 of the
// reaction's size) over a turn.
#include <gtest/gtest.h>

#include <cstdio>

#include "examples.h"
#include "linkage/dimension_change.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"

namespace linkage {
namespace {

TEST(SpatialForceSensitivity, TheRssrsReactionsMoveAsChangedDesignsDo) {
  Mechanism m = test::example("rssr-crank-rocker");
  Body* crank = m.body(m.bodyNamed("crank")->id);
  Body* rocker = m.body(m.bodyNamed("rocker")->id);
  ASSERT_TRUE(crank && rocker);
  const Vec2 c0 = m.point(*m.findPoint("crank.A"))->pos,
             r0 = m.point(*m.findPoint("rocker.C"))->pos;
  crank->mass = Mass{0.3, 0.5 * c0 + Vec2(2, -1), 60, ""};
  rocker->mass = Mass{0.2, 0.6 * r0 + Vec2(-3, 2), 90, ""};
  m.gravity = Vec2(0, -9.81);
  m.gravityZ = -3.0;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const double h = 1e-5;
  std::vector<Kinematics> changed(2 * dims.size());
  for (size_t d = 0; d < dims.size(); ++d)
    for (int side = 0; side < 2; ++side) {
      Mechanism c = m;
      std::vector<double> delta(dims.size(), 0.0);
      delta[d] = side ? h : -h;
      const Status s = changeDimensions(c, dims, delta);
      ASSERT_TRUE(s.ok()) << dims[d].name << ": " << s.message;
      ASSERT_TRUE(changed[2 * d + side].load(c).ok()) << dims[d].name;
    }
  double largest = 0;
  for (int deg = 15; deg < 360; deg += 45) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    for (size_t j = 0; j < m.joints.size(); ++j) {
      const JointForceSensitivity s = jointForceSensitivity(k, m.joints[j].id, dims);
      ASSERT_TRUE(s.status.ok()) << s.status.message;
      const double size = 1 + s.reaction.force.norm() + std::abs(s.reaction.axialN);
      for (size_t d = 0; d < dims.size(); ++d) {
        Forces f[2];
        for (int side = 0; side < 2; ++side) {
          ASSERT_TRUE(changed[2 * d + side].moveTo(deg).ok());
          f[side] = computeForces(changed[2 * d + side]);
        }
        const JointReaction &p = f[1].joints[j], &q = f[0].joints[j], &c = s.change[d];
        const Eigen::Vector3d want((p.force.x() - q.force.x()) / (2 * h),
                                   (p.force.y() - q.force.y()) / (2 * h),
                                   (p.axialN - q.axialN) / (2 * h));
        const Eigen::Vector3d got(c.force.x(), c.force.y(), c.axialN);
        largest = std::max(largest, want.norm());
        EXPECT_LT((got - want).norm(), 1e-6 * size)
            << dims[d].name << " joint " << j << " at " << deg << ": " << got.transpose()
            << " against " << want.transpose();
      }
    }
  }
  EXPECT_GT(largest, 0.01);
}

}  // namespace
}  // namespace linkage
