// Numerical stress: positions near singular ones, long runs, extreme scales. Each compares with
// an independent closed form (tests/reference, __float128) or with exact geometric facts.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "reference/four_bar.h"
#include "reference/slider_crank.h"

namespace linkage {
namespace {

using Q = __float128;

#if defined(__SANITIZE_ADDRESS__) || defined(__OPTIMIZE__) == 0
constexpr bool kSlowBuild = true;  // sanitizers or -O0: keep the long runs short
#else
constexpr bool kSlowBuild = false;
#endif

struct Worst {
  double pos = 0, vel = 0, acc = 0, peakVel = 0, peakAcc = 0;
  void add(const Vec2& x, const Vec2& v, const Vec2& a, const linkref::Vec2<Q>& xr,
           const linkref::Vec2<Q>& vr, const linkref::Vec2<Q>& ar) {
    const Vec2 X(double(xr.x), double(xr.y)), V(double(vr.x), double(vr.y)),
        A(double(ar.x), double(ar.y));
    pos = std::max(pos, (x - X).norm());
    vel = std::max(vel, (v - V).norm());
    acc = std::max(acc, (a - A).norm());
    peakVel = std::max(peakVel, V.norm());
    peakAcc = std::max(peakAcc, A.norm());
  }
};

// A parallelogram 100/40/100/40 has a change point where all four links line up. Shortening the
// crank by 0.01 mm makes a Grashof crank-rocker that passes within about 0.01 mm of it: the
// Jacobian comes within 1e-4 of singular twice a turn, and the open branch must be kept.
TEST(Stress, FourBarPassingAHundredthOfAMillimetreFromItsChangePoint) {
  const double d = 100, r2 = 40 - 0.01, r3 = 100, r4 = 40;
  auto f = test::fourBar(d, r2, r3, r4, 60, true, 30, 10);
  linkref::FourBarParams<Q> p;
  p.O2 = {Q(0), Q(0)};
  p.O4 = {Q(d), Q(0)};
  p.r2 = r2, p.r3 = r3, p.r4 = r4;
  p.theta20 = linkref::deg2rad(Q(60));
  p.s = 1;
  p.omega = linkref::rpm_to_rad_s(Q(60));
  p.branch = linkref::FourBarBranch::kOpen;
  p.px = 30, p.py = 10;
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Worst w;
  for (int i = 0; i <= 3600; ++i) {
    ASSERT_TRUE(k.moveTo(i * 0.1).ok()) << i * 0.1;
    const auto r = linkref::four_bar(p, linkref::deg2rad(Q(i) / Q(10)));
    w.add(k.position(f.P), k.velocity(f.P), k.acceleration(f.P), r.P, r.vP, r.aP);
  }
  EXPECT_LT(w.pos, 1e-9);
  EXPECT_LT(w.vel, 1e-9 * w.peakVel);
  EXPECT_LT(w.acc, 1e-9 * w.peakAcc);
}

TEST(Stress, SliderCrankWithLambdaNearOne) {
  for (double l : {15.0 / 0.99, 15.0 / 0.999}) {
    auto sc = test::sliderCrank(15, l, 0, 90, Direction::Ccw, 1000);
    linkref::SliderCrankParams<Q> p;
    p.r = 15, p.l = l, p.e = 0, p.a0 = linkref::pi<Q>() / 2, p.s = 1;
    p.omega = linkref::rpm_to_rad_s(Q(1000));
    Kinematics k;
    ASSERT_TRUE(k.load(sc.m).ok());
    Worst w;
    for (int i = 0; i <= 720; ++i) {
      ASSERT_TRUE(k.moveTo(i * 0.5).ok()) << i * 0.5;
      const auto r = linkref::slider_crank(p, linkref::deg2rad(Q(i) / Q(2)));
      w.add(k.position(sc.B), k.velocity(sc.B), k.acceleration(sc.B), {Q(0), r.y}, {Q(0), r.vy},
            {Q(0), r.ay});
    }
    EXPECT_LT(w.pos, 1e-9) << "l = " << l;
    EXPECT_LT(w.vel, 1e-9 * w.peakVel) << "l = " << l;
    EXPECT_LT(w.acc, 1e-9 * w.peakAcc) << "l = " << l;
  }
}

// A non-Grashof four-bar whose crank locks exactly on a step of the sweep (crank angle 40).
TEST(Stress, DeadPointExactlyOnAStepIsReportedWhereItLocks) {
  const double d = 100, r2 = 60, r3 = 40, r4 = 70;
  const double limit = std::acos((r2 * r2 + d * d - (r3 + r4) * (r3 + r4)) / (2 * r2 * d));
  auto f = test::fourBar(d, r2, r3, r4, limit * 180 / M_PI - 40);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  for (int i = 0; i < 40; ++i) {
    ASSERT_TRUE(k.moveTo(i).ok()) << i;
    ASSERT_TRUE(k.velocity(f.P).allFinite());
  }
  Status s = k.moveTo(40);
  EXPECT_FALSE(s.ok());
  EXPECT_TRUE(s.code == StatusCode::Unreachable || s.code == StatusCode::Singular)
      << toString(s.code) << ": " << s.message;
  EXPECT_NE(s.message.find("crank angle"), std::string::npos) << s.message;
  EXPECT_NEAR(s.lastReachedDeg.value_or(k.crankDeg()), 40, 1e-3) << s.message;
  EXPECT_TRUE(k.q().allFinite());
  EXPECT_TRUE(k.dq().allFinite());
  // Past it: a clear Unreachable naming the limit, and the state stays put.
  Status past = k.moveTo(41);
  EXPECT_EQ(past.code, StatusCode::Unreachable) << past.message;
  EXPECT_NE(past.message.find("locks at crank angle 39.99"), std::string::npos) << past.message;
}

// A long run: closure stays at rounding level and the motion returns to itself.
TEST(Stress, ManyRevolutionsWithoutDrift) {
  const long steps = kSlowBuild ? 36'000 : 1'000'080;  // 1 degree each: 2778 turns
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const Vec2 P0 = k.position(f.P), V0 = k.velocity(f.P);
  const PointId cA = *f.m.findPoint("crank.A"), rB = *f.m.findPoint("rocker.B");
  double worstGap = 0;
  for (long i = 1; i <= steps; ++i) {
    ASSERT_TRUE(k.moveTo(static_cast<double>(i)).ok()) << i;
    if (i % 997 == 0) {
      worstGap = std::max(worstGap, (k.position(cA) - k.position(f.A)).norm());
      worstGap = std::max(worstGap, (k.position(rB) - k.position(f.B)).norm());
    }
  }
  EXPECT_LT(worstGap, 1e-12);  // rounding on ~100 mm coordinates is ~1e-14 per term
  ASSERT_EQ(steps % 360, 0);
  EXPECT_LT((k.position(f.P) - P0).norm(), 1e-9);
  EXPECT_LT((k.velocity(f.P) - V0).norm(), 1e-9 * V0.norm());
}

// The Wanzer mechanism at 1e-3 and 1e4 times its size, and far from the origin: the same
// motion, scaled, to the same relative accuracy.
TEST(Stress, ScaleAndPlacementDoNotChangeRelativeAccuracy) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/wanzer-inversion-2.linkage.json");
  ASSERT_TRUE(r.mechanism);
  const PointId G = r.mechanism->outputs[0];
  Kinematics ref;
  ASSERT_TRUE(ref.load(*r.mechanism).ok());
  struct Case {
    double scale;
    Vec2 shift;
  };
  for (const Case c : {Case{1e-3, {0, 0}}, Case{1e4, {0, 0}}, Case{1, {3e3, -2e3}}}) {
    Mechanism m = *r.mechanism;
    for (Point& p : m.points) p.pos = p.pos * c.scale + c.shift;
    for (Slot& s : m.slots) s.p0 = s.p0 * c.scale + c.shift, s.p1 = s.p1 * c.scale + c.shift;
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    ASSERT_TRUE(ref.moveTo(0).ok());
    double pos = 0, vel = 0, acc = 0, peakV = 0, peakA = 0;
    for (int i = 0; i <= 360; ++i) {
      ASSERT_TRUE(k.moveTo(i).ok());
      ASSERT_TRUE(ref.moveTo(i).ok());
      pos = std::max(pos, ((k.position(G) - c.shift) / c.scale - ref.position(G)).norm());
      vel = std::max(vel, (k.velocity(G) / c.scale - ref.velocity(G)).norm());
      acc = std::max(acc, (k.acceleration(G) / c.scale - ref.acceleration(G)).norm());
      peakV = std::max(peakV, ref.velocity(G).norm());
      peakA = std::max(peakA, ref.acceleration(G).norm());
    }
    const double size = 130;  // the mechanism's extent, mm
    EXPECT_LT(pos, 1e-11 * size) << c.scale << " shift " << c.shift.transpose();
    EXPECT_LT(vel, 1e-11 * peakV) << c.scale;
    EXPECT_LT(acc, 1e-11 * peakA) << c.scale;
  }
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

// A parallelogram's change point: all four pins in line, where the parallelogram and the
// antiparallelogram branch cross. The driver cannot decide which way it goes on: it must stop
// there with a report, never turn onto the other branch silently.
TEST(Stress, ParallelogramChangePointIsReportedNotCrossedSilently) {
  for (bool closedForm : {true, false}) {
    auto f = test::fourBar(60, 25, 60, 25, 30);  // crank at 30 deg: the change point is at -30
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    // Landing on it: positions, but no velocities.
    Kinematics k(opt);
    ASSERT_TRUE(k.load(f.m).ok());
    ASSERT_TRUE(k.moveTo(-29).ok());
    Status s = k.moveTo(-30);
    EXPECT_EQ(s.code, StatusCode::Singular) << s.message;
    EXPECT_NE(s.message.find("crank angle -30"), std::string::npos) << s.message;
    EXPECT_FALSE(k.derivativesValid());
    EXPECT_TRUE(k.position(f.B).allFinite());
    EXPECT_NEAR(k.position(f.B).x(), 85, 1e-6);
    // Across it, from either side of it, without stopping on it.
    for (double from : {-29.0, -25.0}) {
      Kinematics c(opt);
      ASSERT_TRUE(c.load(f.m).ok());
      ASSERT_TRUE(c.moveTo(from).ok());
      Status across = c.moveTo(-35);
      EXPECT_FALSE(across.ok()) << "crossed the change point from " << from;
      EXPECT_EQ(across.code, StatusCode::Singular) << across.message;
      EXPECT_NE(across.message.find("branches meet"), std::string::npos) << across.message;
      // Still the parallelogram: the coupler has not turned, B is level with A.
      EXPECT_NEAR(c.bodyAngle(f.coupler), 0, 1e-5) << across.message;
      EXPECT_NEAR(c.position(f.B).y(), c.position(f.A).y(), 1e-5);
      EXPECT_GT(c.crankDeg(), -30.0001);
    }
  }
}

}  // namespace
}  // namespace linkage
