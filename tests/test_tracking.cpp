// Following the motion: limit positions, branches, direction, start offset, edits.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using test::fourBar;
using test::sliderCrank;

constexpr double kDeg = M_PI / 180;

// Non-Grashof (s + l = 140 > p + q = 130): the crank, drawn at 30 degrees, locks where coupler
// and rocker line up: |A - O4| = r3 + r4, i.e. cos(theta) = (60^2 + 100^2 - 110^2) / (2 60 100).
TEST(Tracking, NonGrashofCrankLocksAtItsLimitAngle) {
  auto f = fourBar(100, 60, 40, 70, 30);
  const double limitDeg = std::acos((3600.0 + 10000 - 12100) / 12000) / kDeg - 30;  // 52.819...
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(50).ok());
  Status s = k.moveTo(60);
  EXPECT_EQ(s.code, StatusCode::Unreachable) << s.message;
  ASSERT_TRUE(s.lastReachedDeg.has_value());
  EXPECT_NEAR(*s.lastReachedDeg, limitDeg, 1e-3);
  EXPECT_NEAR(*s.crankDeg, 60, 1e-12);
  EXPECT_NE(s.message.find("locks at crank angle 52.81"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("'coupler'"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("'rocker'"), std::string::npos) << s.message;
  // The state stays at the last position reached: finite, on the drawn branch, joints closed.
  EXPECT_NEAR(k.crankDeg(), *s.lastReachedDeg, 1e-12);
  EXPECT_TRUE(k.q().allFinite());
  EXPECT_TRUE(k.dq().allFinite());
  const PointId rB = *f.m.findPoint("rocker.B");
  EXPECT_LT((k.position(rB) - k.position(f.B)).norm(), 1e-9);
  // It can still be driven back.
  ASSERT_TRUE(k.moveTo(0).ok());
  EXPECT_LT((k.position(f.B) - f.m.point(f.B)->pos).norm(), 1e-9);
}

TEST(Tracking, CrossedBranchIsKeptThroughFullRevolutions) {
  auto f = fourBar(60, 20, 70, 50, 60, /*open=*/false);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  for (int a = 0; a <= 720; a += 45) {
    ASSERT_TRUE(k.moveTo(a).ok()) << a;
    // Crossed: B stays below the line O2-O4... for this linkage the rocker never crosses it.
    EXPECT_LT(k.position(f.B).y(), 0) << "crank angle " << a;
  }
  EXPECT_LT((k.position(f.B) - f.m.point(f.B)->pos).norm(), 1e-9);
}

TEST(Tracking, OneLargeMoveEqualsManySmallOnes) {
  auto f = fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics big, small;
  ASSERT_TRUE(big.load(f.m).ok());
  ASSERT_TRUE(small.load(f.m).ok());
  ASSERT_TRUE(big.moveTo(250).ok());
  for (int a = 1; a <= 250; ++a) ASSERT_TRUE(small.moveTo(a).ok());
  EXPECT_LT((big.position(f.P) - small.position(f.P)).norm(), 1e-11);
  EXPECT_LT((big.velocity(f.P) - small.velocity(f.P)).norm(), 1e-9);
}

TEST(Tracking, ClockwiseTurnsTheOtherWayAndNegativeAnglesGoBack) {
  auto ccw = sliderCrank(15, 45, 0, 90, Direction::Ccw);
  auto cw = sliderCrank(15, 45, 0, 90, Direction::Cw);
  Kinematics a, b;
  ASSERT_TRUE(a.load(ccw.m).ok());
  ASSERT_TRUE(b.load(cw.m).ok());
  ASSERT_TRUE(a.moveTo(30).ok());
  ASSERT_TRUE(b.moveTo(-30).ok());
  EXPECT_LT((a.position(ccw.B) - b.position(cw.B)).norm(), 1e-12);
  const double crankAngleA = a.bodyAngle(ccw.crank);
  ASSERT_TRUE(b.moveTo(30).ok());
  EXPECT_NEAR(b.bodyAngle(cw.crank), -crankAngleA, 1e-12);
  EXPECT_NEAR(b.bodyOmega(cw.crank), -2 * M_PI * 60 / 60, 1e-12);
}

TEST(Tracking, StartOffsetTurnsTheDrawingBeforeCrankAngleZero) {
  auto f = sliderCrank(15, 45, 0, 90);
  f.m.driver->startDeg = 90;  // the crank starts pointing left, not up
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  EXPECT_NEAR(k.crankDeg(), 0, 1e-12);
  EXPECT_NEAR(k.position(f.A).x(), -15, 1e-12);
  EXPECT_NEAR(k.position(f.A).y(), 0, 1e-12);
}

TEST(Tracking, DrawingAtADeadPointIsReported) {
  // A non-Grashof four-bar drawn exactly at its crank's limit: coupler and rocker in line. The
  // crank cannot turn from there in the driving sense, and the report says so.
  const double d = 100, r2 = 60, r3 = 40, r4 = 70;
  const double limit = std::acos((r2 * r2 + d * d - (r3 + r4) * (r3 + r4)) / (2 * r2 * d)) / kDeg;
  auto f = fourBar(d, r2, r3, r4, limit);
  Kinematics k;
  Status s = k.load(f.m);
  EXPECT_EQ(s.code, StatusCode::Locked) << s.message;
  EXPECT_NE(s.message.find("dead point"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("the driver at " + jointName(f.m, f.m.joints[0].id)), std::string::npos)
      << s.message;
}

TEST(Tracking, NotLoadedAndNoDriverAreClearStatuses) {
  Kinematics k;
  EXPECT_EQ(k.moveTo(10).code, StatusCode::BadModel);
  auto f = fourBar(60, 20, 70, 50, 60);
  f.m.driver.reset();
  ASSERT_TRUE(k.load(f.m).ok());
  Status s = k.moveTo(10);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("no driver"), std::string::npos);
  EXPECT_EQ(k.moveTo(NAN).code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

TEST(Tracking, FarAnglesOfAPeriodicMotionCostOneTurn) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics far, near;
  ASSERT_TRUE(far.load(f.m).ok());
  ASSERT_TRUE(near.load(f.m).ok());
  // One million turns and 37 degrees: tracked step by step it would take seconds. A double
  // carries 3.6e8 degrees to about 6e-8 degrees, which bounds the agreement (1e-6 mm here).
  ASSERT_TRUE(far.moveTo(360e6 + 37).ok());
  ASSERT_TRUE(near.moveTo(37).ok());
  EXPECT_LT((far.position(f.P) - near.position(f.P)).norm(), 1e-6);
  EXPECT_LT((far.velocity(f.P) - near.velocity(f.P)).norm(), 1e-5);
  EXPECT_NEAR(far.crankDeg(), 360e6 + 37, 1e-6);
  // The crank's own angle keeps counting whole turns.
  EXPECT_NEAR(far.bodyAngle(f.crank) - near.bodyAngle(f.crank), 2 * M_PI * 1e6, 1e-6);
  // And back, two million turns the other way.
  ASSERT_TRUE(far.moveTo(-360e6 + 37).ok());
  EXPECT_LT((far.position(f.P) - near.position(f.P)).norm(), 1e-6);
}

// Far beyond 1e12 degrees a double cannot count a crank angle in steps (a step of a degree
// rounds to nothing past about 1e17): angles beyond 1e12, typed or in a file, are refused at
// once, naming the angle, and the mechanism stays where it was. 1e12 itself is still reached.
TEST(Tracking, AnglesBeyondATrillionDegreesAreRefusedNotTrackedForever) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k, near;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(near.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(37).ok());
  const Vec2 before = k.position(f.P);
  for (double a : {1e300, -1e300, 1e17, -2e12, 1.000001e12}) {
    const Status s = k.moveTo(a);
    EXPECT_EQ(s.code, StatusCode::BadModel) << a;
    EXPECT_NE(s.message.find("1e12 degrees"), std::string::npos) << s.message;
    ASSERT_TRUE(k.valid());
    EXPECT_EQ(k.position(f.P), before) << a;
    EXPECT_NEAR(k.crankDeg(), 37, 1e-12);
  }
  // 2777777777 turns and 280 degrees: the double carries it to 1.2e-4 degrees.
  ASSERT_TRUE(k.moveTo(1e12).ok());
  ASSERT_TRUE(near.moveTo(280).ok());
  EXPECT_LT((k.position(f.P) - near.position(f.P)).norm(), 20 * 1.2e-4 * M_PI / 180 * 5);
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

TEST(Tracking, CopiesAndMovesAreIndependent) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics reference;
  ASSERT_TRUE(reference.load(f.m).ok());
  ASSERT_TRUE(reference.moveTo(200).ok());
  std::optional<Kinematics> original(std::in_place);
  ASSERT_TRUE(original->load(f.m).ok());
  ASSERT_TRUE(original->moveTo(100).ok());
  Kinematics copy = *original;
  Kinematics moved = std::move(*original);
  original.reset();  // nothing may point into it any more
  ASSERT_TRUE(copy.moveTo(200).ok());
  ASSERT_TRUE(moved.moveTo(200).ok());
  EXPECT_LT((copy.position(f.P) - reference.position(f.P)).norm(), 1e-11);
  EXPECT_LT((moved.velocity(f.P) - reference.velocity(f.P)).norm(), 1e-9);
}

}  // namespace
}  // namespace linkage
