// Steps without accelerations (KinematicsOptions::accelerations = false): positions and
// velocities must be those of full steps, accelerations NaN (never a stale or partial value),
// and switching them back on must give the full steps' accelerations at the current position.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

void expectSameWithoutAccelerations(const Mechanism& m, bool closedForm, const std::string& what) {
  KinematicsOptions full, lean;
  full.closedForm = lean.closedForm = closedForm;
  lean.accelerations = false;
  Kinematics a(full), b(lean);
  ASSERT_TRUE(a.load(m).ok()) << what;
  ASSERT_TRUE(b.load(m).ok()) << what;
  ASSERT_EQ(a.closedForm(), b.closedForm());
  const double L = a.size(), w = a.omega();
  for (double deg = 0; deg <= 720; deg += 7) {
    ASSERT_TRUE(a.moveTo(deg).ok()) << what << " at " << deg;
    ASSERT_TRUE(b.moveTo(deg).ok()) << what << " at " << deg;
    for (const Point& p : m.points) {
      EXPECT_LT((a.position(p.id) - b.position(p.id)).norm(), 1e-10 * L) << what << " " << deg;
      EXPECT_LT((a.velocity(p.id) - b.velocity(p.id)).norm(), 1e-9 * L * w) << what << " " << deg;
      if (b.closedForm() && deg > 0) {  // the load itself computes them
        EXPECT_TRUE(std::isnan(b.acceleration(p.id).x())) << what << " " << deg;
        EXPECT_TRUE(std::isnan(b.motion(p.id).acceleration.y())) << what << " " << deg;
      }
    }
  }
  b.setAccelerations(true);
  for (const Point& p : m.points)
    EXPECT_LT((a.acceleration(p.id) - b.acceleration(p.id)).norm(), 1e-9 * L * w * w) << what;
  ASSERT_TRUE(a.moveTo(1000).ok());
  ASSERT_TRUE(b.moveTo(1000).ok());
  for (const Point& p : m.points)
    EXPECT_LT((a.acceleration(p.id) - b.acceleration(p.id)).norm(), 1e-9 * L * w * w) << what;
}

TEST(Levels, WithoutAccelerationsPositionsAndVelocitiesAreThoseOfFullSteps) {
  auto sc = test::sliderCrank(12, 41, 5, 70, Direction::Cw, 1500, false);
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  for (bool closedForm : {true, false}) {
    expectSameWithoutAccelerations(sc.m, closedForm, "slider-crank");
    expectSameWithoutAccelerations(f.m, closedForm, "four-bar");
    for (const char* name : {"wanzer-inversion-1", "wanzer-inversion-2"}) {
      LoadResult r =
          loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
      ASSERT_TRUE(r.mechanism) << r.error;
      expectSameWithoutAccelerations(*r.mechanism, closedForm, name);
    }
  }
}

TEST(Levels, WithoutAccelerationsALockingPositionIsReportedTheSame) {
  // A non-Grashof four-bar: the crank cannot turn fully and locks at a dead point.
  auto f = test::fourBar(100, 60, 40, 70, 10);
  KinematicsOptions lean;
  lean.accelerations = false;
  Kinematics a, b(lean);
  ASSERT_TRUE(a.load(f.m).ok());
  ASSERT_TRUE(b.load(f.m).ok());
  const Status sa = a.moveTo(300), sb = b.moveTo(300);
  EXPECT_EQ(sa.code, StatusCode::Unreachable) << sa.message;
  EXPECT_EQ(sb.code, sa.code) << sb.message;
  ASSERT_TRUE(sa.lastReachedDeg && sb.lastReachedDeg);
  EXPECT_NEAR(*sb.lastReachedDeg, *sa.lastReachedDeg, 1e-5);
}

}  // namespace
}  // namespace linkage
