// Every joint's reaction's derivatives (linkage/force_sensitivity.h) against the changed designs'
// forces (changeDimensions, the whole solve again): central differences, to 1e-5 of the
// reaction's size (its force, its couple in N mm, a cam's contact force), every dimension, every
// stepDeg degrees of crank from 10. For what has no closed form in the tests.
#pragma once

#include <gtest/gtest.h>

#include "changed_design.h"
#include "linkage/balance.h"
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

// Every bearing's out-of-plane reaction on a machine in space (its normal force and tilts about
// its class's x and y axes, linkage/dynamics.h) differentiated by every dimension against the
// changed designs' (central differences of the whole solve), to 1e-6 of its size (N, N mm),
// every stepDeg degrees of crank from 15. `largest`: the largest derivative met.
inline void expectOutOfPlaneMovesAsChangedDesignsDo(const Mechanism& m, double& largest,
                                                    int stepDeg = 45) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(m);
  const double h = 1e-5;
  std::vector<Kinematics> changed(2 * dims.size());
  for (size_t d = 0; d < dims.size(); ++d) {
    for (int side = 0; side < 2; ++side) {
      Kinematics& kc = changed[2 * d + side];
      ASSERT_TRUE(kc.load(changedDesign(m, dims, d, side ? h : -h)).ok()) << dims[d].name;
      kc.setAccelerations(true);
    }
  }
  auto parts = [](const JointReaction& r) {
    return Eigen::Vector3d(r.normalN, 1000 * r.tiltNm.x(), 1000 * r.tiltNm.y());
  };
  for (int deg = 15; deg < 360; deg += stepDeg) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    std::vector<Forces> f(changed.size());
    for (size_t c = 0; c < changed.size(); ++c) {
      ASSERT_TRUE(changed[c].moveTo(deg).ok()) << dims[c / 2].name;
      f[c] = computeForces(changed[c]);
    }
    for (size_t j = 0; j < m.joints.size(); ++j) {
      const JointForceSensitivity s = jointForceSensitivity(k, m.joints[j].id, dims);
      ASSERT_TRUE(s.status.ok()) << s.status.message;
      const double size = 1 + parts(s.reaction).norm();
      for (size_t d = 0; d < dims.size(); ++d) {
        const Eigen::Vector3d want =
            (parts(f[2 * d + 1].joints[j]) - parts(f[2 * d].joints[j])) / (2 * h);
        const Eigen::Vector3d got = parts(s.change[d]);
        largest = std::max(largest, want.norm());
        EXPECT_LT((got - want).norm(), 1e-6 * size)
            << dims[d].name << " joint " << j << " at " << deg << ": " << got.transpose()
            << " against " << want.transpose();
      }
    }
  }
}

// A counterweight's share of every joint's reaction differentiated by every dimension
// (counterweightShareChange: the counterweight fixed in its body's drawing) against the changed
// designs with the counterweight written in less those without (the share is what its mass adds
// to the reactions; a changed drawing carries a body's masses along): central differences of
// the whole solve, to 1e-6 of the reaction's size (in space its bearing's load out of the plane
// with it), every stepDeg degrees of crank from 10.
// `largest`: the largest derivative met.
inline void expectShareMovesAsChangedDesignsDo(const Mechanism& m, const Counterweight& cw,
                                               double& largest, int stepDeg = 50) {
  Mechanism heavier = m;
  addCounterweights(heavier, {cw});
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(m);
  const double h = 1e-5;
  for (size_t d = 0; d < dims.size(); ++d) {
    // A 1:1 belt's ratio has no derivative: which pulley keeps its drawn size switches there
    // (elements/gear.cpp), and the tooth force's line with it.
    if (dims[d].ratioOf && dims[d].value == 1) continue;
    Kinematics kc[2], kh[2];
    ASSERT_TRUE(loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
    ASSERT_TRUE(loadChangedPair(heavier, dims, d, h, kh)) << dims[d].name;
    for (int deg = 10; deg < 360; deg += stepDeg) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      Forces f[2], fh[2];
      for (int side = 0; side < 2; ++side) {
        kc[side].setAccelerations(true);
        kh[side].setAccelerations(true);
        ASSERT_TRUE(kc[side].moveTo(deg).ok() && kh[side].moveTo(deg).ok()) << dims[d].name;
        f[side] = computeForces(kc[side]);
        fh[side] = computeForces(kh[side]);
      }
      for (size_t j = 0; j < m.joints.size(); ++j) {
        const CounterweightShareChange s = counterweightShareChange(k, m.joints[j].id, cw, dims);
        ASSERT_TRUE(s.status.ok()) << s.status.message;
        // Its force, couple (N mm), tension and, in space, its bearing's load out of the plane.
        using Parts = Eigen::Matrix<double, 7, 1>;
        auto parts = [](const JointReaction& r) {
          return (Parts() << r.force.x(), r.force.y(), 1000 * r.coupleNm, r.axialN, r.normalN,
                  1000 * r.tiltNm.x(), 1000 * r.tiltNm.y())
              .finished();
        };
        auto share = [&](int side) {
          return Parts(parts(fh[side].joints[j]) - parts(f[side].joints[j]));
        };
        const Parts want = (share(1) - share(0)) / (2 * h);
        const Parts got = parts(s.change[d]);
        const double size = 1 + parts(fh[1].joints[j]).cwiseAbs().sum();
        EXPECT_LT((got - want).norm(), 1e-6 * size)
            << dims[d].name << " joint " << j << " at " << deg << ": " << got.transpose()
            << " against " << want.transpose();
        largest = std::max(largest, want.norm());
      }
    }
  }
}

}  // namespace linkage::test
