// A machine in space's reactions differentiated with respect to its dimensions (linkage/
// force_sensitivity.h): the RSSR crank-rocker with masses on its crank and rocker and gravity
// across both planes, every joint's in-plane reaction (a pin's force in its plane class's frame)
// and the ball rod's tension, against the changed designs (changeDimensions: depths, ground z,
// the rod's length and the planes' origins drawn exactly; central differences, 1e-6 of the
// reaction's size) over a turn.
#include <gtest/gtest.h>

#include <cstdio>

#include "changed_design.h"
#include "examples.h"
#include "linkage/balance.h"
#include "linkage/dimension_change.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
#include "linkage/io/model_file.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/space.h"
#include "loaded_rssr.h"
#include "optimize_checks.h"
#include "reaction_checks.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::bothCounterweights;
using test::loadedRssr;
using test::spaceSpec;
using test::turned;

TEST(SpatialForceSensitivity, TheRssrsReactionsMoveAsChangedDesignsDo) {
  const Mechanism m = loadedRssr();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const double h = 1e-5;
  std::vector<Kinematics> changed(2 * dims.size());
  for (size_t d = 0; d < dims.size(); ++d)
    for (int side = 0; side < 2; ++side)
      ASSERT_TRUE(changed[2 * d + side].load(test::changedDesign(m, dims, d, side ? h : -h)).ok())
          << dims[d].name;
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

// Each bearing's load out of its plane (its normal force and tilts): the crank's and the
// rocker's pins take their bodies' weights across the planes and the rod's pull at its balls'
// depths; as drawn, and with either body in a plane turned in its class.
TEST(SpatialForceSensitivity, TheBearingsOutOfPlaneReactionsMoveAsChangedDesignsDo) {
  for (const Mechanism& m : {loadedRssr(), turned("crank"), turned("rocker")}) {
    double largest = 0;
    test::expectOutOfPlaneMovesAsChangedDesignsDo(m, largest);
    EXPECT_GT(largest, 1.0);
  }
}

// The overedge machine with masses, gravity across its planes and loads (spatial_fixtures.h):
// its bearings carry the other joints' in-plane forces at those joints' depths too, so every
// multiplier's change moves them; and the lockstitch machine's.
TEST(SpatialForceSensitivity, TheMachinesBearingsOutOfPlaneMoveAsChangedDesignsDo) {
  for (const char* name : {"overedge-machine", "lockstitch-bevel"}) {
    Mechanism m = test::withMasses(test::example(name), 7);
    m.gravityZ = -4.0;
    double largest = 0;
    test::expectOutOfPlaneMovesAsChangedDesignsDo(m, largest, 70);
    EXPECT_GT(largest, 1.0) << name;
  }
}

// Slots at a bearing (spatial_fixtures.h): the oscillating block's bearing has no point on its
// body (a ground pin in the coupler's slot) and holds it at its plane's depth, which a plane's
// origin moves; the slotted lever's bearing carries a pin in the rocker's slot, whose force turns
// with the slot (its dJ) and acts at that plane's depth.
TEST(SpatialForceSensitivity, BearingsAndSlotsMoveAsChangedDesignsDo) {
  for (const std::string& text : {test::tiltedOscillatingBlock(), test::slottedLever()}) {
    const LoadResult loaded = parseMechanism(text);
    ASSERT_TRUE(loaded.mechanism) << loaded.error;
    double largest = 0;
    test::expectOutOfPlaneMovesAsChangedDesignsDo(*loaded.mechanism, largest, 30);
    EXPECT_GT(largest, 0.01) << loaded.mechanism->name;
  }
}

// The shaking force in the world (linkage/shaking_sensitivity.h) against the changed designs'.
TEST(SpatialForceSensitivity, TheShakingForceInTheWorldMovesAsChangedDesignsDo) {
  const Mechanism m = loadedRssr();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(m);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  const double h = 1e-5;
  double largest = 0;
  for (size_t d = 0; d < dims.size(); ++d) {
    Kinematics kc[2];
    ASSERT_TRUE(test::loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
    for (Kinematics& c : kc) c.setAccelerations(true);
    for (int deg = 15; deg < 360; deg += 45) {
      ASSERT_TRUE(k.moveTo(deg).ok() && s.at(k).ok());
      Vec3 F[2], M;
      for (int side = 0; side < 2; ++side) {
        ASSERT_TRUE(kc[side].moveTo(deg).ok());
        shaking(kc[side], F[side], M);
      }
      const Vec3 want = (F[1] - F[0]) / (2 * h);
      const Vec3 got = shakingForceSensitivity3(k, s, static_cast<int>(d));
      largest = std::max(largest, want.norm());
      EXPECT_LT((got - want).norm(), 1e-6 * (1 + want.norm())) << dims[d].name << " at " << deg;
    }
  }
  EXPECT_GT(largest, 0.01);
}

// The world's shaking moment's derivative (linkage/shaking_sensitivity.h) against the changed
// designs' (every dimension, central differences, 1e-6 of the moment's size) at several angles.
void expectMomentMovesAsChangedDesignsDo(const Mechanism& m) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(m);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  const double h = 1e-5;
  double largest = 0;
  for (size_t d = 0; d < dims.size(); ++d) {
    Kinematics kc[2];
    ASSERT_TRUE(test::loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
    for (Kinematics& c : kc) c.setAccelerations(true);
    for (int deg = 15; deg < 360; deg += 45) {
      ASSERT_TRUE(k.moveTo(deg).ok() && s.at(k).ok());
      Vec3 F, M0, M[2];
      shaking(k, F, M0);
      for (int side = 0; side < 2; ++side) {
        ASSERT_TRUE(kc[side].moveTo(deg).ok());
        shaking(kc[side], F, M[side]);
      }
      const Vec3 want = (M[1] - M[0]) / (2 * h);
      const Vec3 got = shakingMomentSensitivity3(k, s, static_cast<int>(d));
      largest = std::max(largest, want.norm());
      EXPECT_LT((got - want).norm(), 1e-6 * (1 + M0.norm() + want.norm()))
          << dims[d].name << " at " << deg << ": " << got.transpose() << " against "
          << want.transpose();
    }
  }
  EXPECT_GT(largest, 1e-4);
}

TEST(SpatialForceSensitivity, TheShakingMomentInTheWorldMovesAsChangedDesignsDo) {
  expectMomentMovesAsChangedDesignsDo(loadedRssr());
}

// On a planar machine the world's moment is the drawing's about z and the weights' tilt where
// gravity has a z: its derivative too.
TEST(SpatialForceSensitivity, APlanarShakingMomentInTheWorldMovesAsChangedDesignsDo) {
  Mechanism m = test::example("four-bar-crank-rocker");
  for (const Point& p : m.points)
    if (Body* b = m.body(p.body); !b->ground && !b->mass)
      b->mass = Mass{0.2, p.pos + Vec2(3, -2), 50, ""};
  m.gravity = Vec2(0, -9.81);
  m.gravityZ = -4.0;
  expectMomentMovesAsChangedDesignsDo(m);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(m), Sensitivity::Space::World).ok());
  ASSERT_TRUE(k.moveTo(70).ok() && s.at(k).ok());
  for (size_t d = 0; d < s.dims().size(); ++d)
    EXPECT_NEAR(shakingMomentSensitivity3(k, s, static_cast<int>(d)).z(),
                shakingMomentSensitivity(k, s, static_cast<int>(d)), 1e-12)
        << s.dims()[d].name;
}

// The rod's tension as an optimize target (its peak over the turn): the objective's gradient
// over the machine's own dimensions in space against central differences, and a limit met, the
// written design bearing the peak reported.
TEST(SpatialForceSensitivity, TheRodsTensionAsATarget) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  std::vector<double> x;
  OptimizeSpec spec = spaceSpec(base.mechanism(), "force:ball-rod:crank.A<=0", x);
  ASSERT_EQ(x.size(), 3u);
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-6);
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
  }
  const double before = e.measures[0][0];
  spec.targets[0].limitN = 0.95 * before;
  spec.variables = {{"ball-rod:crank.A.length", 70, 90}};
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  EXPECT_LE(peak, 0.95 * before * (1 + 1e-9));
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  EXPECT_NEAR(std::abs(computeForces(after).joints[2].axialN), peak, 1e-9 * peak);
}

// A bearing's load out of its plane as an optimize target (its normal force's or its tilts' peak
// over the turn): the objective's gradient over a depth, the rod's length and a plane's origin
// against central differences, for either pin; a limit on the rocker pin's tilts met, the
// written design bearing the peak reported.
TEST(SpatialForceSensitivity, ABearingsLoadOutOfItsPlaneAsATarget) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  for (const char* text : {"force:pin:ground.O:fn<=0", "force:pin:ground.O:tilt<=0",
                           "force:pin:ground.H:fn<=0", "force:pin:ground.H:tilt<=0"}) {
    std::vector<double> x;
    const OptimizeSpec spec = spaceSpec(base.mechanism(), text, x);
    const std::string name(text);
    EXPECT_EQ(optTargetName(base.mechanism(), spec.targets[0]), name.substr(6, name.find('<') - 6));
    // Off the drawing's mirror symmetry about the crank's plane's x = 0 (the rocker's plane at
    // x = 0): there each peak is one of two mirrored maxima of equal height, a corner.
    x[2] += 7;
    std::printf("%s\n", text);
    test::expectGradientAt(base, spec, x);
  }
  std::vector<double> x;
  OptimizeSpec spec = spaceSpec(base.mechanism(), "force:pin:ground.H:tilt<=0", x);
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  const double before = e.measures[0][0];
  spec.targets[0].limitN = 0.95 * before;
  spec.variables.pop_back();  // the design's own plane stays inside the bounds
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  std::printf("the rocker pin's tilts' peak %.6g N m -> %.6g N m\n", before, peak);
  EXPECT_LE(peak, 0.95 * before * (1 + 1e-9));
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  EXPECT_NEAR(computeForces(after).joints[1].tiltNm.norm(), peak, 1e-9 * peak);
}

// What a bearing's load out of its plane cannot be a target of, named: a planar machine, a joint
// that is no body's bearing.
TEST(SpatialForceSensitivity, OutOfPlaneTargetsRefusedAreNamed) {
  struct Case {
    Mechanism m;
    const char *target, *variable, *why;
  };
  const Case cases[] = {
      {test::example("drop-feed"), "force:pin:ground.L:fn<=1", "ground.L.x", "this one is planar"},
      {loadedRssr(), "force:ball-rod:crank.A:tilt<=1", "crank.A.depth", "is no body's one joint"}};
  for (const Case& c : cases) {
    Kinematics base;
    ASSERT_TRUE(base.load(c.m).ok());
    OptimizeSpec spec;
    spec.variables = {{c.variable, -50, 50}};
    OptTarget t;
    std::string why;
    ASSERT_TRUE(parseOptTarget(c.m, c.target, t, why)) << why;
    spec.targets = {t};
    const OptimizeResult r = optimize(base, spec);
    EXPECT_FALSE(r.status.ok()) << c.target;
    EXPECT_NE(r.status.message.find(c.why), std::string::npos) << r.status.message;
  }
  // A part that is not fn or tilt is read as a joint's name, which none has.
  OptTarget t;
  std::string why;
  EXPECT_FALSE(parseOptTarget(loadedRssr(), "force:pin:ground.O:fz<=1", t, why));
  EXPECT_NE(why.find("no joint 'pin:ground.O:fz' (the model's: pin:ground.O,"), std::string::npos)
      << why;
  EXPECT_FALSE(parseOptTarget(loadedRssr(), "force:pin:ground.H:tilt:fn<=1", t, why));  // one part
  EXPECT_NE(why.find("no joint 'pin:ground.H:tilt'"), std::string::npos) << why;
}

// A shaking target's limit at 0.97 of its peak met by the rod's length alone, and the written
// design feeling the peak reported where it was found (|F|, or |M| for the moment).
void limitMetByTheRod(const Kinematics& base, OptimizeSpec spec, double peakBefore) {
  spec.targets[0].limitN = 0.97 * peakBefore;
  spec.variables = {{"ball-rod:crank.A.length", 70, 90}};
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  EXPECT_LE(peak, spec.targets[0].limitN * (1 + 1e-9));
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  Vec3 F, M;
  shaking(after, F, M);
  EXPECT_NEAR(spec.targets[0].moment ? M.norm() : F.norm(), peak, 1e-9 * peak);
}

// The shaking force's peak in the world as an optimize target (|F| and its z): the gradient over
// the machine's dimensions in space against central differences, and a limit met by the rod's
// length, the written design feeling the peak reported.
TEST(SpatialForceSensitivity, TheShakingForceAsATarget) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  for (const char* text : {"shaking:force<=0", "shaking:fz<=0"}) {
    std::vector<double> x;
    OptimizeSpec spec = spaceSpec(base.mechanism(), text, x);
    const OptTarget& t = spec.targets[0];
    const Evaluation e = evaluate(base, spec, x);
    ASSERT_TRUE(e.feasible) << e.why;
    for (size_t i = 0; i < x.size(); ++i) {
      const double fd = test::centralDifference(base, spec, x, i, 1e-6);
      EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << text << spec.variables[i].name;
    }
    if (t.measure != BalanceMeasure::Force) continue;
    limitMetByTheRod(base, spec, e.measures[0][0]);
  }
}

// The shaking moment's peak in the world (|M|, the world's 3-vector about its origin) as an
// optimize target: the gradient over the machine's dimensions in space against central
// differences, and a limit met by the rod's length, the written design feeling the peak reported.
TEST(SpatialForceSensitivity, TheShakingMomentAsATarget) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  std::vector<double> x;
  OptimizeSpec spec = spaceSpec(base.mechanism(), "shaking:moment<=0", x);
  ASSERT_EQ(x.size(), 3u);
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-6);
    EXPECT_GT(std::abs(fd), 1e-6) << spec.variables[i].name;
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
  }
  limitMetByTheRod(base, spec, e.measures[0][0]);
}

// Counterweights on the RSSR's crank and rocker (in two planes, gravity across both) varied by
// optimize for the peak of |F| in the world: the gradient against central differences, the
// optimum against balance's certified one (a convex programme, linkage/balance.h), and the
// written design feeling the peak reported.
TEST(SpatialForceSensitivity, CounterweightsInSpaceAgainstBalance) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  OptimizeSpec spec = bothCounterweights();
  OptTarget t;
  t.kind = OptTarget::Kind::Shaking;
  spec.targets = {t};
  spec.steps = 180;
  const std::vector<double> x{3, -2, 1.5, 4};
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-6);
    EXPECT_GT(std::abs(fd), 1e-3) << spec.variables[i].name;
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
  }
  BalanceOptions opt;
  opt.bodies = {base.mechanism().bodyNamed("crank")->id, base.mechanism().bodyNamed("rocker")->id};
  const BalanceResult exact = balanceShaking(base, opt);
  ASSERT_TRUE(exact.status.ok()) << exact.status.message;
  spec.starts = 2;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  std::printf("  peak %.9g -> %.9g N (balance: %.9g, its lower bound %.9g), %d of %d starts\n",
              r.atBefore.measures[0][0], peak, exact.peakAfter, exact.lowerBound, r.foundBest,
              r.starts);
  EXPECT_GE(peak, exact.lowerBound * (1 - 1e-9));
  EXPECT_NEAR(peak, exact.peakAfter, 1e-6 * exact.peakAfter);
  ASSERT_EQ(r.counterweights.size(), 2u);
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  Vec3 F, M;
  shaking(after, F, M);
  EXPECT_NEAR(F.norm(), peak, 1e-9 * peak);
}

// A counterweight's share of every joint's reaction on a machine in space (the in-plane force,
// the couple, the ball rod's tension) is the design with the counterweight written in as a mass
// of its body, solved by the dynamics again: on the RSSR's crank and its rocker (in the inclined
// plane, gravity across both), and on each drawn in a plane turned in its class.
TEST(SpatialForceSensitivity, ACounterweightsShareIsTheMassWrittenIn) {
  for (const Mechanism& m : {loadedRssr(), turned("crank"), turned("rocker")})
    for (const char* body : {"crank", "rocker"}) {
      Counterweight cw;
      ASSERT_TRUE(counterweightOn(m, m.bodyNamed(body)->id, cw).ok()) << body;
      cw.staticMoment = Vec2(1.5, -2);
      cw.kg = cw.staticMoment.norm() / cw.maxRadiusMm;
      Mechanism heavier = m;
      addCounterweights(heavier, {cw});
      Kinematics k, kh;
      ASSERT_TRUE(k.load(m).ok() && kh.load(heavier).ok()) << body;
      k.setAccelerations(true);
      kh.setAccelerations(true);
      double largest = 0, tilted = 0;
      for (int deg = 0; deg < 360; deg += 30) {
        ASSERT_TRUE(k.moveTo(deg).ok() && kh.moveTo(deg).ok());
        const Forces before = computeForces(k), after = computeForces(kh);
        for (size_t j = 0; j < m.joints.size(); ++j) {
          const CounterweightShare sh = counterweightShare(k, m.joints[j].id, cw);
          ASSERT_TRUE(sh.status.ok()) << sh.status.message;
          const JointReaction &a = after.joints[j], &b = before.joints[j];
          const double size = 1e-9 * (1 + a.force.norm() + std::abs(a.axialN));
          EXPECT_LT((sh.share.force - (a.force - b.force)).norm(), size)
              << body << " " << j << " at " << deg;
          EXPECT_NEAR(sh.share.coupleNm, a.coupleNm - b.coupleNm, size) << body << " " << j;
          EXPECT_NEAR(sh.share.axialN, a.axialN - b.axialN, size) << body << " " << j;
          // What its bearing takes out of the plane (N, N m).
          const double out = 1e-9 * (1 + std::abs(a.normalN) + 1000 * a.tiltNm.norm());
          EXPECT_NEAR(sh.share.normalN, a.normalN - b.normalN, out) << body << " " << j;
          EXPECT_LT(1000 * (sh.share.tiltNm - (a.tiltNm - b.tiltNm)).norm(), out) << body << j;
          largest = std::max(largest, (a.force - b.force).norm() + std::abs(a.axialN - b.axialN));
          tilted = std::max(tilted,
                            std::abs(a.normalN - b.normalN) + 1000 * (a.tiltNm - b.tiltNm).norm());
        }
      }
      EXPECT_GT(largest, 1e-3) << body;
      EXPECT_GT(tilted, 1e-3) << body;
    }
}

// Shares prepared once for a design answer as the one-off does at every pose, with accelerations
// or without; another design (the same pose, a depth changed) is refused, not answered stale.
TEST(SpatialForceSensitivity, SharesPreparedOnceAreTheOneOffs) {
  const Mechanism m = loadedRssr();
  Mechanism deeper = m;
  deeper.point(*deeper.findPoint("crank.A"))->third = 12.0;
  Counterweight cw;
  ASSERT_TRUE(counterweightOn(m, m.bodyNamed("rocker")->id, cw).ok());
  cw.staticMoment = Vec2(3, -2);
  cw.kg = 0.1;
  Kinematics k, other;
  ASSERT_TRUE(k.load(m).ok() && other.load(deeper).ok());
  CounterweightShares shares;
  ASSERT_TRUE(shares.prepare(k, m.joints[1].id).ok());
  for (int deg : {0, 130, 130, 250}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    k.setAccelerations(deg == 250);
    const CounterweightShare a = shares.at(k, cw), b = counterweightShare(k, m.joints[1].id, cw);
    ASSERT_TRUE(a.status.ok() && b.status.ok()) << a.status.message << b.status.message;
    EXPECT_EQ(a.share.force, b.share.force) << deg;
    EXPECT_EQ(a.share.tiltNm, b.share.tiltNm) << deg;
    EXPECT_EQ(a.perY.normalN, b.perY.normalN) << deg;
  }
  const CounterweightShare stale = shares.at(other, cw);
  EXPECT_FALSE(stale.status.ok());
  EXPECT_NE(stale.status.message.find("another design"), std::string::npos);
}

// The share's derivatives by every dimension on a machine in space, against the share on the
// changed designs: on the RSSR's rocker, as drawn and in a plane turned in its class (the driven
// crank's share is its own weight and spin whatever the dimensions), and with gravity along the
// rocker's normal (the world's x), whose weight then tilts the rocker's bearing from where the
// counterweight turns to.
TEST(SpatialForceSensitivity, ACounterweightsShareMovesAsChangedDesignsDo) {
  Mechanism across = loadedRssr();
  across.gravity = Vec2(2.5, -9.81);
  for (const Mechanism& m : {loadedRssr(), turned("rocker"), across}) {
    Counterweight cw;
    ASSERT_TRUE(counterweightOn(m, m.bodyNamed("rocker")->id, cw).ok());
    cw.staticMoment = Vec2(1.5, -2);
    cw.kg = cw.staticMoment.norm() / cw.maxRadiusMm;
    double largest = 0;
    test::expectShareMovesAsChangedDesignsDo(m, cw, largest, 90);
    EXPECT_GT(largest, 1e-3);
  }
}

// A reaction over counterweights on a machine in space (their shares added to the design's
// reaction): the crank's bearing and the rod's tension, the objective's gradient over both
// bodies' counterweights against central differences; the bearing's peak lowered below 0.9 of
// its value by the crank's counterweight alone, the written design bearing the peak reported.
TEST(SpatialForceSensitivity, AReactionOverCounterweights) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  OptimizeSpec spec = bothCounterweights();
  const std::vector<double> x{3, -2, 1.5, 4};
  for (const char* text : {"force:pin:ground.O<=0", "force:ball-rod:crank.A<=0"}) {
    std::string why;
    OptTarget t;
    ASSERT_TRUE(parseOptTarget(base.mechanism(), text, t, why)) << why;
    spec.targets = {t};
    const Evaluation e = evaluate(base, spec, x);
    ASSERT_TRUE(e.feasible) << e.why;
    for (size_t i = 0; i < x.size(); ++i) {
      const double fd = test::centralDifference(base, spec, x, i, 1e-6);
      EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd)))
          << text << " " << spec.variables[i].name;
    }
  }
  std::string why;
  ASSERT_TRUE(parseOptTarget(base.mechanism(), "force:pin:ground.O<=0", spec.targets[0], why));
  spec.variables.resize(2);
  const double before = evaluate(base, spec, {0, 0}).measures[0][0];
  spec.targets[0].limitN = 0.9 * before;
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  EXPECT_LE(peak, 0.9 * before * (1 + 1e-9));
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  EXPECT_NEAR(computeForces(after).joints[0].force.norm(), peak, 1e-9 * peak);
}

}  // namespace
}  // namespace linkage
