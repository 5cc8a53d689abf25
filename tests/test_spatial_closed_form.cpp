// The closed form of a machine in space (kinematics/closed_form.h, group RS): a rocker pinned
// to a known body and held by a ball rod to another solves a cos t + b sin t = c on the drawn
// root. Checked against the general Newton solve of the same rows, against the RSSR's equation
// derived in the test (spatial_fixtures.h) on both of its roots, and where the rod cannot reach.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/groups.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using namespace test::rssr;

Mechanism load(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism();
}

Kinematics make(const Mechanism& m, bool closedForm) {
  KinematicsOptions o;
  o.closedForm = closedForm;
  Kinematics k(o);
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

int groupsOfKind(const Mechanism& m, GroupKind kind) {
  int n = 0;
  for (const AssurGroup& g : decomposeAssur(m).groups) n += g.kind == kind;
  return n;
}

TEST(SpatialClosedForm, TheSpatialExamplesSolveGroupByGroupAsTheGeneralSolveDoes) {
  const struct {
    const char* name;
    int rockers;  // RS groups: seed 004's needle and upper gripper rockers, the RSSR's
  } cases[] = {{"rssr-crank-rocker", 1}, {"overedge-machine", 2}, {"lockstitch-bevel", 0}};
  for (const auto& c : cases) {
    const Mechanism m = test::example(c.name);
    EXPECT_EQ(groupsOfKind(m, GroupKind::RS), c.rockers) << c.name;
    Kinematics fast = make(m, true), slow = make(m, false);
    ASSERT_TRUE(fast.closedForm()) << c.name;
    ASSERT_FALSE(slow.closedForm()) << c.name;
    for (double a = 0; a <= 720; a += 7) {
      ASSERT_TRUE(fast.moveTo(a).ok()) << c.name << " at " << a;
      ASSERT_TRUE(slow.moveTo(a).ok()) << c.name << " at " << a;
      EXPECT_LT((fast.q() - slow.q()).cwiseAbs().maxCoeff(), 1e-10 * fast.size()) << c.name << a;
      EXPECT_LT((fast.dq() - slow.dq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.dq().norm()))
          << c.name << " at " << a;
      EXPECT_LT((fast.ddq() - slow.ddq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.ddq().norm()))
          << c.name << " at " << a;
    }
  }
}

// The rocker's absolute angle psi (its drawing's is kPsi0) and its rates by the crank angle.
test::Rocker rockerOf(const Kinematics& k, BodyId rocker) {
  const double w = k.omega();
  return {kPsi0 + k.bodyAngle(rocker), k.bodyOmega(rocker) / w, k.bodyAlpha(rocker) / (w * w)};
}

TEST(SpatialClosedForm, TheRssrRockersOtherBranchIsTheEquationsOtherRoot) {
  const Mechanism m = load(test::rssrText());
  const BodyId rocker = m.bodyNamed("rocker")->id;
  const PointId C = *m.findPoint("rocker.C");
  const double l = test::rssrRod();
  Kinematics k = make(m, true);
  ASSERT_TRUE(k.closedForm());
  // As drawn, the rocker is on one root; which one, the equation says.
  const test::RssrEquation e0 = test::rssrEquation(0, l);
  const int drawn = std::abs(std::remainder(e0.root(1) - kPsi0, 2 * M_PI)) < 1e-9 ? 1 : -1;
  ASSERT_LT(std::abs(std::remainder(e0.root(drawn) - kPsi0, 2 * M_PI)), 1e-9);
  Mechanism redrawn;
  const Status s = k.flipBranch(rocker, &redrawn);
  ASSERT_TRUE(s.ok()) << s.message;
  for (double deg = 0; deg < 360; deg += 15) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const double phi = deg * M_PI / 180;
    const test::RssrEquation e = test::rssrEquation(phi, l);
    const test::Rocker got = rockerOf(k, rocker), want = test::rockerAt(phi, e.root(-drawn));
    EXPECT_LT(std::abs(std::remainder(got.psi - want.psi, 2 * M_PI)), 1e-10) << deg;
    EXPECT_NEAR(got.d1, want.d1, 1e-9 * (1 + std::abs(want.d1))) << deg;
    EXPECT_NEAR(got.d2, want.d2, 1e-9 * (1 + std::abs(want.d2))) << deg;
    // and not the drawn root's
    EXPECT_GT(std::abs(std::remainder(got.psi - e.root(drawn), 2 * M_PI)), 0.1) << deg;
  }
  // The design redrawn on that root loads there, by either solve, with no assembly move.
  for (bool closedForm : {true, false}) {
    Kinematics again = make(redrawn, closedForm);
    EXPECT_FALSE(again.assembly().moved);
    for (double deg : {0.0, 100.0, 250.0}) {
      ASSERT_TRUE(again.moveTo(deg).ok()) << deg;
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      // (its angles count from its own drawing: compare where its ball is)
      EXPECT_LT((again.position(C) - k.position(C)).norm(), 1e-9 * kW) << deg;
    }
  }
}

TEST(SpatialClosedForm, WhereTheRodCannotReachTheMotionStopsAtTheEquationsDeadPoint) {
  // The rocker's axis moved off the crank's: |A - H| now changes with the crank, and past
  // about 181 degrees no rocker angle keeps the rod's length.
  const test::RssrDims d{15, Vec3(0, 60, 60)};
  const Mechanism m = load(test::rssrText(d));
  const double l = test::rssrRod(d);
  // The dead point: the first crank angle where |c| = hypot(a, b), by bisection.
  double lo = 0, hi = 0;
  for (int deg = 0; deg <= 360 && hi == 0; ++deg)
    if (!test::rssrEquation(deg * M_PI / 180, l, d).reaches()) hi = deg;
  ASSERT_GT(hi, 90);
  lo = hi - 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    (test::rssrEquation(mid * M_PI / 180, l, d).reaches() ? lo : hi) = mid;
  }
  for (bool closedForm : {true, false}) {
    Kinematics k = make(m, closedForm);
    EXPECT_EQ(k.closedForm(), closedForm);
    ASSERT_TRUE(k.moveTo(lo - 1).ok());
    const Status s = k.moveTo(lo + 5);
    EXPECT_EQ(s.code, StatusCode::Unreachable) << s.message;
    EXPECT_NEAR(s.lastReachedDeg.value_or(0), lo, 1e-3) << s.message;
    // and it turns back, on the drawn branch
    ASSERT_TRUE(k.moveTo(10).ok());
    const test::Rocker want = test::rockerNear(10 * M_PI / 180, kPsi0, l, d);
    EXPECT_NEAR(kPsi0 + k.bodyAngle(m.bodyNamed("rocker")->id), want.psi, 1e-9);
  }
}

}  // namespace
}  // namespace linkage
