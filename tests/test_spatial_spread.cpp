// A timing window's spread on a machine in space (linkage/cycle_spread.h): the lockstitch
// machine's vertical-shaft point M at (V.x + r cos phi, ., V.z - r sin phi) is below z = -6
// (z > 6 with r = 12: sin phi < -1/2) from phi0 = 180 + asin(6 / r) degrees to 360 - asin(6 / r),
// so with r = vshaft.V-M within +-T the start's first-order worst case is |d phi0 / dr| T and
// every sample's start lies between phi0(r + T) and phi0(r - T) (it falls as r grows).
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/cycle_spread.h"

namespace linkage {
namespace {

TEST(SpatialSpread, AWindowsStartUnderARadiussTolerance) {
  const Mechanism m = test::exampleWithWindow("lockstitch-bevel", "low=vshaft.M:z>6");
  ToleranceSpec spec;
  const double T = 0.3, r = 12;
  spec.tolerances = {{"vshaft.V-M", T, false}};
  spec.samples = 2000;
  const SpreadResult s = windowSpread(m, spec, "low");
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_EQ(s.values.size(), 2u);
  auto start = [](double radius) { return 180 + std::asin(6 / radius) * 180 / M_PI; };
  const double slope = -6 / (r * r) / std::sqrt(1 - 36 / (r * r)) * 180 / M_PI;
  const Spread& from = s.values[0];
  EXPECT_NEAR(from.nominal, start(r), 1e-9);
  EXPECT_NEAR(from.worst, std::abs(slope) * T, 1e-9 * std::abs(slope));
  EXPECT_NEAR(from.rss, std::abs(slope) * T, 1e-9 * std::abs(slope));
  EXPECT_EQ(s.used, spec.samples);
  EXPECT_GE(from.lo, start(r + T) - 1e-9);
  EXPECT_LE(from.hi, start(r - T) + 1e-9);
  // 2000 uniform samples reach within 1 % of either end.
  EXPECT_LT(from.lo, start(r + T) + 0.01 * (start(r - T) - start(r + T)));
  EXPECT_GT(from.hi, start(r - T) - 0.01 * (start(r - T) - start(r + T)));
}

}  // namespace
}  // namespace linkage
