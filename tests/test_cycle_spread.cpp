// The spread of a closest approach and of a window's ends under tolerances
// (linkage/cycle_spread.h): first order against the slider-crank's closed forms (the block on
// x = e tops out at Y1 = sqrt((l + r)^2 - e^2): a ground point h above the slot's foot is h - Y1
// away, its derivative -(l + r) / Y1 for the crank and the rod alike); the samples, each solved
// exactly, inside the worst case but for second order and reaching most of it.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/cycle_spread.h"
#include "linkage/window_sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

ToleranceSpec tolerancesOf(std::vector<std::pair<std::string, double>> tols, int samples) {
  ToleranceSpec spec;
  for (const auto& [name, t] : tols) spec.tolerances.push_back({name, t, false});
  spec.samples = samples;
  spec.seed = 7;
  return spec;
}

TEST(CycleSpread, AClosestApproachsSpread) {
  const double r = 20, l = 70, e = 12, h = 110, Y1 = std::sqrt((l + r) * (l + r) - e * e);
  test::SliderCrank sc = test::sliderCrank(r, l, e, 30);
  const PointId Q = sc.m.addPoint(sc.ground, "Q", Vec2(e, h));
  const ClearanceWatch w{sc.B, ClearancePart::of(Q), {}};
  const SpreadResult s =
      clearanceSpread(sc.m, tolerancesOf({{"crank.O-A", 0.1}, {"rod.A-B", 0.1}}, 400), w);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_EQ(s.values.size(), 1u);
  const Spread& x = s.values[0];
  const double d = (l + r) / Y1;
  EXPECT_NEAR(x.nominal, h - Y1, 1e-9);
  EXPECT_NEAR(x.worst, d * 0.2, 1e-9);
  EXPECT_NEAR(x.rss, d * 0.1 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(s.used, 400) << s.firstFailure;
  EXPECT_GE(x.lo, x.nominal - x.worst - 1e-4);
  EXPECT_LE(x.hi, x.nominal + x.worst + 1e-4);
  EXPECT_LT(x.lo, x.nominal - 0.85 * x.worst);
  EXPECT_GT(x.hi, x.nominal + 0.85 * x.worst);
}

// The samples run on every core, gathered in their order: the same figures on one thread and
// on three.
TEST(CycleSpread, TheSameFiguresOnAnyNumberOfThreads) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  sc.m.timing.windows.push_back({"low", LimitMeasure::along(sc.B, Vec2(0, 1)), true, 70});
  ToleranceSpec spec = tolerancesOf({{"crank.O-A", 0.05}, {"rod.A-B", 0.1}}, 60);
  spec.threads = 1;
  const SpreadResult one = windowSpread(sc.m, spec, "low");
  spec.threads = 3;
  const SpreadResult three = windowSpread(sc.m, spec, "low");
  ASSERT_TRUE(one.status.ok() && three.status.ok());
  EXPECT_EQ(one.used, 60);
  EXPECT_EQ(three.used, one.used);
  ASSERT_EQ(one.values.size(), three.values.size());
  for (size_t i = 0; i < one.values.size(); ++i) {
    EXPECT_EQ(one.values[i].lo, three.values[i].lo);
    EXPECT_EQ(one.values[i].hi, three.values[i].hi);
    EXPECT_EQ(one.values[i].mean, three.values[i].mean);
    EXPECT_EQ(one.values[i].sd, three.values[i].sd);
    EXPECT_LT(one.values[i].lo, one.values[i].hi);
  }
}

TEST(CycleSpread, AWindowsEndsSpread) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  sc.m.timing.windows.push_back({"low", LimitMeasure::along(sc.B, Vec2(0, 1)), true, 70});
  const SpreadResult s = windowSpread(sc.m, tolerancesOf({{"crank.O-A", 0.05}}, 200), "low");
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_EQ(s.values.size(), 2u);
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  const WindowSensitivity w = windowSensitivity(k, "low", dimensions(sc.m));
  size_t crank = 0;
  while (w.dims[crank].name != "crank.O-A") ++crank;
  EXPECT_NEAR(s.values[0].worst, std::abs(w.intervals[0].dFrom[crank]) * 0.05, 1e-12);
  EXPECT_NEAR(s.values[1].worst, std::abs(w.intervals[0].dTo[crank]) * 0.05, 1e-12);
  EXPECT_EQ(s.used, 200) << s.firstFailure;
  for (const Spread& x : s.values) {
    EXPECT_GE(x.lo, x.nominal - 1.02 * x.worst);
    EXPECT_LE(x.hi, x.nominal + 1.02 * x.worst);
    EXPECT_GT(x.hi - x.lo, 1.6 * x.worst);  // one uniform dimension: its range nearly all of it
  }
}

TEST(CycleSpread, APlayIsRefusedHere) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  const PointId Q = sc.m.addPoint(sc.ground, "Q", Vec2(12, 110));
  ToleranceSpec spec;
  spec.tolerances.push_back({"crank.A-rod.A", 0.01, true});
  EXPECT_NE(
      clearanceSpread(sc.m, spec, {sc.B, ClearancePart::of(Q), {}}).status.message.find("play"),
      std::string::npos);
}

}  // namespace
}  // namespace linkage
