// Clearance in space (linkage/clearance.h on a machine with planes): the lockstitch machine
// whose hook turns in the plane z = 0, at right angles to the needle's (x = 0), through two
// bevel pairs. Its hook point K and the needle's blade N-T are checked against the machine's
// closed form, derived from the drawing alone (spatial_fixtures.h).
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/clearance.h"
#include "linkage/kinematics.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

using test::lockstitch_bevel::hookK;
constexpr auto needle = test::lockstitch_bevel::needleAt;
double toSegment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 u = b - a;
  const double t = std::clamp((x - a).dot(u) / u.squaredNorm(), 0.0, 1.0);
  return (x - a - t * u).norm();
}

// The minima of f over a turn, by golden-section search in every bracket of 0.1-degree samples
// (of the closed form alone).
std::vector<double> minimaOf(const std::function<double(double)>& f) {
  std::vector<double> out;
  const int n = 3600;
  for (int i = 0; i < n; ++i) {
    const double a = (i - 1) * 0.1, b = i * 0.1, c = (i + 1) * 0.1;
    if (!(f(b * kDeg) < f(a * kDeg) && f(b * kDeg) <= f(c * kDeg))) continue;
    double lo = a, hi = c;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 200 && hi - lo > 1e-12; ++it) {
      const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
      (f(x1 * kDeg) < f(x2 * kDeg) ? hi : lo) = f(x1 * kDeg) < f(x2 * kDeg) ? x2 : x1;
    }
    out.push_back(std::fmod((lo + hi) / 2 + 360, 360));
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SpatialClearance, TheHookPointMeetsTheNeedleBladeWhereTheClosedFormSays) {
  const Mechanism m = test::example("lockstitch-bevel");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId K = *m.findPoint("hook.K");
  const ClearancePart blade =
      ClearancePart::segment(*m.findPoint("needlebar.N"), *m.findPoint("needlebar.T"));
  const Clearance c = findClearance(k, ClearancePart::of(K), blade);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  // Every sample of the distance, against the closed form.
  for (size_t i = 0; i < c.crankDeg.size(); ++i) {
    const double phi = c.crankDeg[i] * kDeg;
    EXPECT_NEAR(c.distance[i], toSegment(hookK(phi), needle(phi, 131), needle(phi, 96)), 1e-9)
        << c.crankDeg[i];
  }
  // They meet where 20 = 25 sin 2phi with K within the blade: 2 phi = 360 + asin(0.8), K at
  // y -185 while the blade spans -189.74 to -154.74.
  const double meet = (360 + std::asin(0.8) / kDeg) / 2;
  EXPECT_NEAR(c.closest.crankDeg, meet, 1e-7);
  EXPECT_LT(c.closest.distance, 1e-9);
  EXPECT_LT((c.closestPoint3 - hookK(meet * kDeg)).norm(), 1e-9);
  EXPECT_LT((c.closestOther3 - c.closestPoint3).norm(), 1e-9);
  // Every other minimum too, where the closed form's are.
  const std::vector<double> expected =
      minimaOf([](double phi) { return toSegment(hookK(phi), needle(phi, 131), needle(phi, 96)); });
  ASSERT_EQ(c.minima.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(c.minima[i].crankDeg, expected[i], 1e-6) << i;
    const double phi = expected[i] * kDeg;
    EXPECT_NEAR(c.minima[i].distance, toSegment(hookK(phi), needle(phi, 131), needle(phi, 96)),
                1e-9)
        << i;
  }
}

TEST(SpatialClearance, PointToPointInSpaceHasTheClosedFormsMinima) {
  const Mechanism m = test::example("lockstitch-bevel");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N");
  const Clearance c = findClearance(k, ClearancePart::of(K), ClearancePart::of(N));
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  auto f = [](double phi) { return (hookK(phi) - needle(phi, 131)).norm(); };
  const std::vector<double> expected = minimaOf(f);
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(c.minima.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(c.minima[i].crankDeg, expected[i], 1e-6) << i;
    EXPECT_NEAR(c.minima[i].distance, f(expected[i] * kDeg), 1e-9) << i;
  }
  EXPECT_NEAR(clearanceAt(k, ClearancePart::of(K), ClearancePart::of(N)), f(0), 1e-9);
}

// An arc slot is measured in space as in the plane: a guard of the ground's, an arc through
// (40, -150), (60, -200), (40, -250) in the hook's plane that no joint uses: centre C = (-12.5,
// -200), radius 72.5, spanning 43.6 degrees either side of +x. K, on its circle of 25 about (20,
// -200), is always inside the arc's circle and within its span near +x; the least distance is
// 72.5 - |K - C| there, 15 mm at K = (45, -200) (sin 2 phi = -1), else the nearer end's.
TEST(SpatialClearance, AnArcSlotInSpaceHasTheClosedFormsMinima) {
  Mechanism m = test::example("lockstitch-bevel");
  const SlotId guard = m.addSlot(m.ground()->id, "guard", Vec2(40, -150), Vec2(40, -250));
  m.slot(guard)->mid = Vec2(60, -200);
  Kinematics k;
  const Status loaded = k.load(m);
  ASSERT_TRUE(loaded.ok()) << loaded.message;
  const PointId K = *m.findPoint("hook.K");
  const Clearance c = findClearance(k, ClearancePart::of(K), ClearancePart::of(guard));
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const Vec3 C(-12.5, -200, 0), e0(40, -150, 0), e1(40, -250, 0);
  const double span = std::atan2(50, 52.5);
  auto f = [&](double phi) {
    const Vec3 r = hookK(phi) - C;
    if (std::abs(std::atan2(r.y(), r.x())) < span) return 72.5 - r.norm();
    return std::min((hookK(phi) - e0).norm(), (hookK(phi) - e1).norm());
  };
  EXPECT_NEAR(c.closest.distance, 15, 1e-9);
  EXPECT_LT((c.closestOther3 - Vec3(60, -200, 0)).norm(), 1e-6);
  const std::vector<double> expected = minimaOf(f);
  ASSERT_GE(expected.size(), 2u);  // 15 mm twice a turn (the hook turns twice)
  ASSERT_EQ(c.minima.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(c.minima[i].crankDeg, expected[i], 1e-6) << i;
    EXPECT_NEAR(c.minima[i].distance, f(expected[i] * kDeg), 1e-9) << i;
  }
}

}  // namespace
}  // namespace linkage
