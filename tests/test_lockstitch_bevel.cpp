// The lockstitch-bevel example (resources/examples/spatial.py): an arm shaft along x, a vertical
// shaft geared 1:1 to it and a hook shaft along z geared 2:1 to that, by two bevel pairs; the
// hook turns in the plane z = 0, at right angles to the needle's x = 0. Against closed forms
// written here: the hook's and the vertical shaft's angles are the ratios times the crank's, to
// rounding, their rates constant; the needle is the central slider-crank r 16, l 45; and the
// points a clearance check in space takes (the hook point, the needle's blade from its point N
// up to T) meet where the drawing says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "examples.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;
constexpr double kR = 16, kL = 45, kNeedle = 131, kBlade = 35, kHookR = 25;
const Vec3 kHookAxis(20, -200, 0);
// The crank angle where the hook point crosses the needle's line (lockstitch-machine's: 26.57
// degrees after the needle's lowest position).
const double kMeet = M_PI + (M_PI / 2 - std::atan2(9.0, 12.0)) / 2;

// The needle point's height and its first two derivatives by the crank angle phi: the crank pin
// at (0, r cos phi, r sin phi), the pin B on x = 0, z = 0 at l from it.
struct Needle {
  double y, y1, y2;
};
Needle needle(double phi) {
  const double s = std::sin(phi), c = std::cos(phi), q = std::sqrt(kL * kL - kR * kR * s * s);
  // q q' = -r^2 s c, and once more: q'^2 + q q'' = -r^2 (c^2 - s^2).
  const double q1 = -kR * kR * s * c / q;
  const double q2 = (-kR * kR * (c * c - s * s) - q1 * q1) / q;
  return {kR * c - q - kNeedle, -kR * s - q1, -kR * c - q2};
}

struct Bevel : ::testing::Test {
  void SetUp() override {
    m = test::example("lockstitch-bevel");
    ASSERT_TRUE(k.load(m).ok());
    EXPECT_FALSE(k.assembly().moved);
  }
  Mechanism m;
  Kinematics k;
};

TEST_F(Bevel, TheHookTurnsInAPlaneAtRightAnglesToTheNeedles) {
  const Plane& needlePlane = planeOf(m, m.bodyNamed("needlebar")->id);
  const Plane& hook = planeOf(m, m.bodyNamed("hook")->id);
  const Plane& vertical = planeOf(m, m.bodyNamed("vshaft")->id);
  EXPECT_EQ(needlePlane.normal(), Vec3(1, 0, 0));
  EXPECT_EQ(vertical.normal(), Vec3(0, 1, 0));
  EXPECT_EQ(hook.normal(), Vec3(0, 0, 1));
  EXPECT_EQ(k.structure().mobility, 1);
}

TEST_F(Bevel, TheShaftsTurnAtTheirRatiosAndTheNeedleIsTheSliderCrank) {
  const BodyId arm = m.bodyNamed("armshaft")->id, vshaft = m.bodyNamed("vshaft")->id,
               hook = m.bodyNamed("hook")->id;
  const PointId N = *m.findPoint("needlebar.N"), K = *m.findPoint("hook.K");
  const Vec3 K0 = worldOf(m, *m.point(K)) - kHookAxis;
  const double k0 = std::atan2(K0.y(), K0.x());
  EXPECT_NEAR(K0.norm(), kHookR, 1e-12);
  const double w = k.omega();
  double peak1 = 0, peak2 = 0;
  for (int i = 0; i < 360; ++i)
    peak1 = std::max(peak1, std::abs(needle(i * kDeg).y1)),
    peak2 = std::max(peak2, std::abs(needle(i * kDeg).y2));
  for (double deg = 0; deg <= 720; deg += 1.25) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const double phi = deg * kDeg;
    EXPECT_NEAR(k.bodyAngle(arm), phi, 1e-12 * (1 + phi)) << deg;
    EXPECT_NEAR(k.bodyAngle(vshaft), phi, 1e-12 * (1 + phi)) << deg;
    EXPECT_NEAR(k.bodyAngle(hook), 2 * phi, 1e-12 * (1 + phi)) << deg;
    EXPECT_NEAR(k.bodyOmega(vshaft), w, 1e-12 * w) << deg;
    EXPECT_NEAR(k.bodyOmega(hook), 2 * w, 1e-12 * w) << deg;
    EXPECT_NEAR(k.bodyAlpha(hook), 0, 1e-12 * w * w) << deg;
    // The hook point, 25 from its axis at twice the crank's angle.
    const double h = k0 + 2 * phi;
    const Vec3 u(std::cos(h), std::sin(h), 0), t(-std::sin(h), std::cos(h), 0);
    const Kinematics::PointMotion3 kp = k.motionInSpace(K);
    EXPECT_LT((kp.position - (kHookAxis + kHookR * u)).norm(), 1e-9) << deg;
    EXPECT_LT((kp.velocity - kHookR * 2 * w * t).norm(), 1e-9 * kHookR * 2 * w) << deg;
    EXPECT_LT((kp.acceleration + kHookR * 4 * w * w * u).norm(), 1e-9 * kHookR * 4 * w * w) << deg;
    // The needle: on its line x = 0, z = 0, at the slider-crank's height.
    const Needle e = needle(phi);
    const Kinematics::PointMotion3 np = k.motionInSpace(N);
    EXPECT_LT((np.position - Vec3(0, e.y, 0)).norm(), 1e-9) << deg;
    EXPECT_LT((np.velocity - Vec3(0, e.y1 * w, 0)).norm(), 1e-9 * peak1 * w) << deg;
    EXPECT_LT((np.acceleration - Vec3(0, e.y2 * w * w, 0)).norm(), 1e-9 * peak2 * w * w) << deg;
  }
}

// The points a clearance check in space takes: the hook point hook.K and the needle's blade, the
// segment from its point needlebar.N up to needlebar.T (35 mm). The hook point crosses the
// needle's line on the blade, 4.74 mm above the needle's point, at crank 206.57 degrees, and
// then only: over the rest of the turn it is away from the blade's line.
TEST_F(Bevel, TheHookPointMeetsTheNeedlesBladeWhereItTakesTheLoop) {
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N"),
                T = *m.findPoint("needlebar.T");
  ASSERT_TRUE(k.moveTo(kMeet / kDeg).ok());
  const Vec3 kp = k.motionInSpace(K).position, n = k.motionInSpace(N).position,
             t = k.motionInSpace(T).position;
  EXPECT_NEAR((t - n).norm(), kBlade, 1e-9);
  EXPECT_LT((kp - Vec3(0, -185, 0)).norm(), 1e-9);
  EXPECT_NEAR(kp.y() - n.y(), -185 - needle(kMeet).y, 1e-9);
  EXPECT_NEAR(kp.y() - n.y(), 4.74, 0.005);
  EXPECT_LT((kp - n).cross(t - n).norm() / kBlade, 1e-9);  // on the blade's line, between
  EXPECT_GT(kp.y(), n.y());
  EXPECT_LT(kp.y(), t.y());
}

}  // namespace
}  // namespace linkage
