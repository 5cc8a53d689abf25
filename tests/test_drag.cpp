// Dragging a point (Kinematics::dragTo): the nearest reachable position against closed forms
// (a crank's circle, a rocker's and a slider's end of travel, the four-bar coupler curve of the
// independent reference), stops at limit positions of the crank, never a jump to the other
// assembly branch, bounded work per call, refusals that move nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "four_bar_reference.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "reference/wanzer.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

Vec2 polar(double r, double deg) {
  return r * Vec2(std::cos(deg * kDeg), std::sin(deg * kDeg));
}

// Drags until the drag says it is as near as it goes; at most `calls` calls.
Kinematics::DragResult dragFully(Kinematics& k, PointId p, const Vec2& target, int calls = 10) {
  Kinematics::DragResult r;
  for (int i = 0; i < calls; ++i) {
    r = k.dragTo(p, target);
    if (r.converged || !r.status.ok()) break;
  }
  return r;
}

TEST(Drag, ACrankPointGoesToTheNearestPointOfItsCircle) {
  auto f = test::fourBar(60, 20, 70, 50, 60);  // crank 20 mm, drawn at 60 degrees
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const Kinematics::DragResult r = k.dragTo(f.A, polar(50, 100));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.converged);
  EXPECT_FALSE(r.atLimit);
  EXPECT_NEAR(r.crankDeg, 40, 1e-9);
  EXPECT_NEAR(r.distance, 30, 1e-9);
  EXPECT_LT((k.position(f.A) - polar(20, 100)).norm(), 1e-9);
  EXPECT_EQ(r.crankDeg, k.crankDeg());

  // 170 degrees the short way round (counter-clockwise from 100 to 270): more than one call's
  // work (8 steps of at most 15 degrees), reached over a few calls, never the long way.
  const Kinematics::DragResult first = k.dragTo(f.A, polar(50, 270));
  EXPECT_TRUE(first.status.ok());
  EXPECT_FALSE(first.converged);
  EXPECT_GT(first.crankDeg, 40);
  EXPECT_LE(first.crankDeg, 40 + 8 * 15 + 1e-9);
  const Kinematics::DragResult last = dragFully(k, f.A, polar(50, 270));
  ASSERT_TRUE(last.converged);
  EXPECT_NEAR(last.crankDeg, 210, 1e-9);
  EXPECT_NEAR(last.distance, 30, 1e-9);
}

TEST(Drag, ACouplerPointReachesTheNearestPointOfItsCurve) {
  // The open four-bar's coupler point, against the reference closed form: at the end the
  // point is on the curve at the crank angle reached, and no point of the curve within 10
  // degrees of crank is nearer (a scan of the reference).
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const auto p = test::fourBarReference(60, 20, 70, 50, 60, true, 35, 25);
  auto ref = [&](double deg) {
    const auto s = linkref::four_bar(p, deg * kDeg);
    return Vec2(s.P.x, s.P.y);
  };
  for (double near : {-50.0, 20.0, 140.0, 250.0}) {
    for (const Vec2& off : {Vec2(4, 3), Vec2(-6, 1), Vec2(0.5, -8)}) {
      Kinematics k;
      ASSERT_TRUE(k.load(f.m).ok());
      ASSERT_TRUE(k.moveTo(near).ok());
      const Vec2 target = ref(near + 5) + off;
      const Kinematics::DragResult r = dragFully(k, f.P, target);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      ASSERT_TRUE(r.converged);
      EXPECT_LT((k.position(f.P) - ref(r.crankDeg)).norm(), 1e-9);
      double best = INFINITY;
      for (double d = r.crankDeg - 10; d <= r.crankDeg + 10; d += 0.001)
        best = std::min(best, (ref(d) - target).norm());
      EXPECT_LE(r.distance, best + 1e-12) << near;
      EXPECT_NEAR(r.distance, (k.position(f.P) - target).norm(), 1e-12);
    }
  }
}

TEST(Drag, ARockerStopsAtTheEndOfItsSwing) {
  // Crank-rocker 60, 20, 70, 50: the rocker's end B swings between the positions where crank
  // and coupler are in line. Dragged beyond the outer one, B stops there: |O2 B| = 20 + 70 on
  // the rocker's circle, and the crank points at B. Not a limit of the crank: it turns on.
  const double x = (90.0 * 90 - 50 * 50 + 60 * 60) / 120;
  const Vec2 outer(x, std::sqrt(90.0 * 90 - x * x));
  for (bool accelerations : {true, false}) {
    for (bool closedForm : {true, false}) {
      KinematicsOptions opt;
      opt.accelerations = accelerations;
      opt.closedForm = closedForm;
      auto f = test::fourBar(60, 20, 70, 50, 60);
      Kinematics k(opt);
      ASSERT_TRUE(k.load(f.m).ok());
      const Vec2 target = Vec2(60, 0) + polar(60, 40);  // the rocker at 40 degrees: beyond
      const Kinematics::DragResult r = dragFully(k, f.B, target, 20);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      EXPECT_TRUE(r.converged);
      EXPECT_FALSE(r.atLimit);
      EXPECT_LT((k.position(f.B) - outer).norm(), 1e-9) << accelerations << closedForm;
      EXPECT_NEAR(r.distance, (outer - target).norm(), 1e-9);
      // The crank in line with the coupler (the distance is flat there: the angle to 1e-6 deg).
      EXPECT_NEAR(r.crankDeg, std::atan2(outer.y(), outer.x()) / kDeg - 60, 1e-6);
    }
  }
}

TEST(Drag, ACrankThatRocksStopsAtItsLimitAndSaysSo) {
  // Driven 50 mm link, coupler 70, follower 20 on 60 mm of ground: the follower turns fully, the
  // driven link rocks between cos t = 0.6 and cos t = -1/3 (|A O4| = 70 -+ 20). Drawn at 80
  // degrees and dragged towards 150 degrees, it stops at the limit acos(-1/3).
  auto f = test::fourBar(60, 50, 70, 20, 80);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const Kinematics::DragResult r = dragFully(k, f.A, polar(50, 150));
  EXPECT_EQ(r.status.code, StatusCode::Unreachable) << r.status.message;
  EXPECT_TRUE(r.atLimit);
  EXPECT_TRUE(r.converged);
  const double limit = std::acos(-1.0 / 3) / kDeg - 80;
  EXPECT_NEAR(r.crankDeg, limit, 1e-5);
  EXPECT_TRUE(k.valid());
  EXPECT_LT((k.position(f.A) - polar(50, 80 + r.crankDeg)).norm(), 1e-9);
  EXPECT_NEAR(r.distance, (k.position(f.A) - polar(50, 150)).norm(), 1e-12);
  // Pushed further, it stays; pulled back, it follows.
  const Kinematics::DragResult again = k.dragTo(f.A, polar(50, 170));
  EXPECT_TRUE(again.atLimit);
  EXPECT_NEAR(again.crankDeg, limit, 1e-5);
  const Kinematics::DragResult back = dragFully(k, f.A, polar(60, 90));
  ASSERT_TRUE(back.status.ok()) << back.status.message;
  EXPECT_FALSE(back.atLimit);
  EXPECT_NEAR(back.crankDeg, 10, 1e-9);
}

TEST(Drag, NeverJumpsToTheOtherBranch) {
  // Targets on the crossed branch's coupler curve, and far away: the open four-bar follows
  // along its own branch, as a fresh load turned to the same crank angle shows.
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto crossed = test::fourBar(60, 20, 70, 50, 60, false, 35, 25);
  Kinematics k, other;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(other.load(crossed.m).ok());
  for (double deg : {0.0, 90.0, 200.0, 310.0}) {
    ASSERT_TRUE(other.moveTo(deg).ok());
    for (const Vec2& target : {other.position(crossed.P), Vec2(1000, -1000), Vec2(-5, -300)}) {
      const Kinematics::DragResult r = dragFully(k, f.P, target);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      Kinematics fresh;
      ASSERT_TRUE(fresh.load(f.m).ok());
      ASSERT_TRUE(fresh.moveTo(r.crankDeg).ok());
      for (const Point& p : f.m.points)
        EXPECT_LT((k.position(p.id) - fresh.position(p.id)).norm(), 1e-10);
      // Open: B to the left of A -> O4.
      const Vec2 A = k.position(f.A), B = k.position(f.B);
      EXPECT_GT(cross(Vec2(60, 0) - A, B - A), 0);
    }
  }
}

TEST(Drag, ASliderFollowsAlongItsLineAndStopsAtItsDeadCentre) {
  // Slider on x = 5; crank 20, rod 60. Within its travel the block comes level with the target;
  // beyond it, it stops at the top dead centre, |O B| = 80.
  auto s = test::sliderCrank(20, 60, 5, 30);
  Kinematics k;
  ASSERT_TRUE(k.load(s.m).ok());
  Kinematics::DragResult r = dragFully(k, s.B, Vec2(30, 60));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LT((k.position(s.B) - Vec2(5, 60)).norm(), 1e-9);
  EXPECT_NEAR(r.distance, 25, 1e-9);
  r = dragFully(k, s.B, Vec2(5, 200));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_FALSE(r.atLimit);
  EXPECT_LT((k.position(s.B) - Vec2(5, std::sqrt(80.0 * 80 - 25))).norm(), 1e-9);
  // The crank in line with the rod.
  const Vec2 A = k.position(s.A);
  EXPECT_NEAR(cross(A, k.position(s.B)), 0, 1e-6);
}

TEST(Drag, TheWanzerNeedleFollowsAndStopsAtItsTopDeadCentre) {
  // The needle G runs on the line x = 0: within its stroke it comes level with the target;
  // dragged far above, it stops where it turns back (the reduced formulation of the reference:
  // no higher G within 20 degrees of crank, and its velocity is zero there).
  const Mechanism m = test::example("wanzer-inversion-2");
  const PointId G = *m.findPoint("needlebar.G");
  auto ref = [](double deg) {
    return linkref::wanzer_state(linkref::WanzerInversion::k2, deg * kDeg);
  };
  for (bool closedForm : {true, false}) {
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics k(opt);
    ASSERT_TRUE(k.load(m).ok());
    const Vec2 level = k.position(G) + Vec2(7, 3);
    Kinematics::DragResult r = dragFully(k, G, level);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_NEAR(k.position(G).y(), level.y(), 1e-9);
    EXPECT_NEAR(r.distance, 7, 1e-9);
    r = dragFully(k, G, Vec2(0, 1000));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_TRUE(r.converged);
    const auto top = ref(r.crankDeg);
    EXPECT_NEAR(k.position(G).y(), top.G.y, 1e-9);
    EXPECT_LT(std::abs(top.vG.y), 1e-6 * k.omega() * k.size());
    for (double d = r.crankDeg - 20; d <= r.crankDeg + 20; d += 0.01)
      EXPECT_LE(ref(d).G.y, top.G.y + 1e-12) << d;
  }
}

TEST(Drag, PointsTheDriverDoesNotMoveAreReportedAndNothingMoves) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  // A body hung from the ground by one pin: free, held where drawn.
  const BodyId free = f.m.addBody("flap");
  f.m.addPin(f.m.addPoint(f.ground, "H", {-20, 0}), f.m.addPoint(free, "H", {-20, 0}));
  const PointId tip = f.m.addPoint(free, "T", {-20, -10});
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(25).ok());
  const Vec2 before = k.position(f.P);
  const PointId ground = f.m.points[0].id;
  for (PointId p : {ground, tip}) {
    const Kinematics::DragResult r = k.dragTo(p, Vec2(10, 10));
    EXPECT_EQ(r.status.code, StatusCode::BadModel);
    EXPECT_NE(r.status.message.find(f.m.pointLabel(p)), std::string::npos) << r.status.message;
    EXPECT_EQ(r.crankDeg, 25);
    EXPECT_EQ(k.position(f.P), before);
    EXPECT_NEAR(r.distance, (k.position(p) - Vec2(10, 10)).norm(), 1e-12);
  }
  EXPECT_EQ(k.dragTo(f.A, Vec2(NAN, 0)).status.code, StatusCode::BadModel);
  EXPECT_EQ(k.position(f.P), before);
  // A point already on its target: nothing to do.
  const Kinematics::DragResult here = k.dragTo(f.B, k.position(f.B));
  EXPECT_TRUE(here.status.ok());
  EXPECT_TRUE(here.converged);
  EXPECT_EQ(here.crankDeg, 25);
  // No mechanism.
  Kinematics none;
  EXPECT_EQ(none.dragTo(f.A, Vec2(0, 0)).status.code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage
