// Regressions found by review of the state-per-body step, the in-place edit and the branch
// tests; each failed before its fix.
#include <gtest/gtest.h>

#include <cmath>

#include "kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

Kinematics make(const Mechanism& m, bool closedForm) {
  KinematicsOptions o;
  o.closedForm = closedForm;
  Kinematics k(o);
  EXPECT_TRUE(k.load(m).ok());
  return k;
}

// The plan is checked against a fresh solve, not against what the scratch state held before
// (a stale check dropped the closed-form path, or read past the end of a smaller state).
TEST(Regression, AnEditOrALoadAfterStepsKeepsTheClosedFormPath) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Mechanism more = f.m;
  more.addPoint(f.coupler, "Q", Vec2(10, 10));
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(1).ok());
  ASSERT_TRUE(k.edit(more).ok());
  EXPECT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(2).ok());
  ASSERT_TRUE(k.load(test::fourBarChain(3)).ok());
  EXPECT_TRUE(k.closedForm());
}

// Whole turns are counted step to step, which needs steps under half a turn whatever
// maxStepDeg says.
TEST(Regression, LargeMaxStepKeepsTheCrankAngle) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  for (double maxStep : {90.0, 181.0, 360.0}) {
    KinematicsOptions fo, so;
    fo.maxStepDeg = so.maxStepDeg = maxStep;
    so.closedForm = false;
    Kinematics fast(fo), slow(so);
    ASSERT_TRUE(fast.load(f.m).ok());
    ASSERT_TRUE(slow.load(f.m).ok());
    for (double deg : {270.0, 500.0, 100.0}) {
      ASSERT_TRUE(fast.moveTo(deg).ok()) << maxStep << " " << deg;
      ASSERT_TRUE(slow.moveTo(deg).ok()) << maxStep << " " << deg;
      for (BodyId b : {f.crank, f.coupler, f.rocker})
        EXPECT_NEAR(fast.bodyAngle(b), slow.bodyAngle(b), 1e-8) << maxStep << " " << deg;
    }
  }
}

// 1e12 degrees is 2.8e9 turns: more than an int counts.
TEST(Regression, HugeAnglesCountTheirTurns) {
  auto f = test::fourBar(20, 50, 60, 55, 30, true, 10, 5);  // a drag link: every body turns
  Kinematics k = make(f.m, true);
  const double deg = 1e12;
  ASSERT_TRUE(k.moveTo(deg).ok());
  EXPECT_NEAR(k.bodyAngle(f.crank) / (deg * M_PI / 180), 1, 1e-12);
}

// A parallelogram first loop crossed from many start angles: the tracker must stop at the change
// point every time, never carry on along the other branch. Next to it the computed
// accelerations grow without bound and could excuse a jump made in tiny steps; positions that
// close to singular are no longer bases (Kinematics::tryStep).
TEST(Regression, AChangePointIsNeverCrossedSilentlyWhateverTheStart) {
  for (int loops : {3, 4}) {
    const Mechanism m = test::fourBarChain(loops, 25, 60, 25);
    const BodyId coupler0 = m.bodyNamed("coupler0")->id;
    for (double start = -50; start > -57.25; start -= 0.137) {
      for (bool closedForm : {true, false}) {
        Kinematics k = make(m, closedForm);
        ASSERT_TRUE(k.moveTo(start).ok());
        const Status s = k.moveTo(-70);
        EXPECT_EQ(s.code, StatusCode::Singular)
            << loops << " loops from " << start << (closedForm ? ", closed form" : "");
        EXPECT_NEAR(k.bodyAngle(coupler0), 0, 1e-6)
            << loops << " loops from " << start << (closedForm ? ", closed form" : "");
      }
    }
  }
}

}  // namespace
}  // namespace linkage
