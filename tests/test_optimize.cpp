// Dimensions found for targets (linkage/optimize.h, issue 29): setDimension against the
// dimensions' own values, the objective's exact gradient against central differences (here, in
// the test only), a stroke met to 1e-9 mm, a path synthesis started in a wrong basin recovered
// by the multistart, and starts that do not assemble skipped.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/kinematics.h"
#include "linkage/limits.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission.h"
#include "mechanisms.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

using test::fourBar;

// A crank-rocker (Grashof: 20 + 60 < 55 + 45) with a coupler point off the coupler's line.
test::FourBar design(double r2 = 20, double r3 = 55, double r4 = 45, double px = 25,
                     double py = 20) {
  return fourBar(60, r2, r3, r4, 0, true, px, py);
}

const std::vector<std::string> kLinks = {"crank.O2-A", "coupler.A-B", "coupler.B-P", "coupler.A-P",
                                         "rocker.B-O4"};

std::vector<OptVariable> linkVariables(double lo, double hi) {
  std::vector<OptVariable> v;
  for (const std::string& n : kLinks) v.push_back({n, lo, hi});
  return v;
}

// The coupler curve of the design at n crank angles, from its own solve.
std::vector<Vec2> curve(const test::FourBar& f, int n, double from = 0) {
  Kinematics k;
  EXPECT_TRUE(k.load(f.m).ok());
  std::vector<Vec2> out;
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(k.moveTo(from + 360.0 * i / n).ok());
    out.push_back(k.position(f.P));
  }
  return out;
}

void expectEachSetAlone(const Mechanism& base) {
  for (const Dimension& d : dimensions(base)) {
    Mechanism m = base;
    const double to = d.value + (d.unit == Dimension::Unit::Deg ? 3.0 : 1.7);
    ASSERT_TRUE(setDimension(m, d.name, to).ok()) << d.name;
    for (const Dimension& e : dimensions(m)) {
      // A slot turns about its first end, so its offset (from the origin) changes with it, as
      // its derivative says: the one pair that is not independent.
      if (d.name.ends_with(".angle") && e.name.ends_with(".offset")) continue;
      EXPECT_NEAR(e.value, e.name == d.name ? to : test::dimensionValue(base, e.name), 1e-12)
          << d.name << " set, " << e.name << " read";
    }
  }
}

TEST(Optimize, SetDimensionGivesEachDimensionItsValueAndKeepsTheOthers) {
  expectEachSetAlone(test::sliderCrank(20, 60, 5, 30).m);  // the slot's offset and angle too
  const test::FourBar f = design();
  // All at once, in an order where one at a time would break the coupler's triangle first.
  Mechanism all = f.m;
  ASSERT_TRUE(
      setDimensions(all, {{"coupler.A-B", 70}, {"coupler.A-P", 40}, {"coupler.B-P", 40}}).ok());
  EXPECT_NEAR(test::dimensionValue(all, "coupler.A-B"), 70, 1e-12);
  EXPECT_NEAR(test::dimensionValue(all, "coupler.A-P"), 40, 1e-12);
  EXPECT_NEAR(test::dimensionValue(all, "coupler.B-P"), 40, 1e-12);
  Mechanism slot = test::sliderCrank(20, 60, 5, 30).m;
  ASSERT_TRUE(setDimensions(slot, {{"ground.guide.offset", 7}, {"ground.guide.angle", 4}}).ok());
  EXPECT_NEAR(test::dimensionValue(slot, "ground.guide.offset"), 7, 1e-12);
  EXPECT_NEAR(test::dimensionValue(slot, "ground.guide.angle"), 4, 1e-12);
  for (const Dimension& d : dimensions(f.m)) {
    Mechanism m = f.m;
    const double to = d.value + (d.unit == Dimension::Unit::Deg ? 3.0 : 1.7);
    ASSERT_TRUE(setDimension(m, d.name, to).ok()) << d.name;
    for (const Dimension& e : dimensions(m))
      EXPECT_NEAR(e.value, e.name == d.name ? to : test::dimensionValue(f.m, e.name), 1e-12)
          << d.name << " set, " << e.name << " read";
  }
  Mechanism m = f.m;
  EXPECT_FALSE(setDimension(m, "coupler.A-P", 200).ok());  // no triangle with A-B 55, B-P ...
  EXPECT_FALSE(setDimension(m, "coupler.nothing", 1).ok());
  EXPECT_FALSE(setDimension(m, "crank.O2-A", NAN).ok());
}

// The three kinds of target on one four-bar: the objective's gradient (exact sensitivities
// chained through the targets' extremes, angles and nearest points) against central differences
// of the objective itself.
TEST(Optimize, GradientMatchesCentralDifferences) {
  const test::FourBar f = design();
  Kinematics base;
  ASSERT_TRUE(base.load(f.m).ok());
  OptimizeSpec spec;
  spec.variables = linkVariables(1, 100);
  spec.variables.push_back({"ground.O4.x", 0, 100});
  const test::FourBar other = design(21, 54, 46, 24, 22);
  OptTarget stroke{OptTarget::Kind::Stroke, f.P, 30.0};
  OptTarget at{OptTarget::Kind::Position, f.P, 0, 40, Vec2(10, 50)};
  OptTarget path{OptTarget::Kind::Path, f.P};
  path.path = curve(other, 7, 10);
  path.weight = 0.5;
  OptTarget mu{OptTarget::Kind::Transmission, f.B};
  mu.joint = 0;      // the coupler-rocker dyad at B
  mu.limitDeg = 75;  // below its smallest angle and above 180 - its largest: both residuals
  spec.targets = {stroke, at, path, mu};
  std::vector<double> x;
  for (const OptVariable& v : spec.variables) x.push_back(test::dimensionValue(f.m, v.name));
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  ASSERT_LT(e.measures[3][0], 75);
  ASSERT_GT(e.measures[3][1], 105);
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-5);
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
  }
}

// Issue 29's test: a path synthesis whose first start is in a basin that is not the global one
// (a local search from it alone stays at an objective of hundreds of mm^2) reaches the design the
// path was drawn from: eight points of its coupler curve, the five link dimensions free. Most
// random starts in the bounds do not turn fully: they are skipped, and nothing is NaN.
TEST(Optimize, PathSynthesisFromAWrongBasinReachesTheKnownDesign) {
  const test::FourBar truth = design();
  const test::FourBar start = design(18, 60, 50, -20, 25);
  Kinematics base;
  ASSERT_TRUE(base.load(start.m).ok());
  OptimizeSpec spec;
  spec.variables = linkVariables(10, 80);
  OptTarget path{OptTarget::Kind::Path, start.P};
  path.path = curve(truth, 8, 5);
  spec.targets = {path};
  spec.starts = 1;
  const OptimizeResult one = optimize(base, spec);
  ASSERT_TRUE(one.status.ok()) << one.status.message;
  EXPECT_GT(one.atAfter.objective, 100);  // a local minimum, not the design
  spec.starts = 32;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_GT(r.infeasibleStarts, 0);
  EXPECT_GE(r.foundBest, 1);
  EXPECT_LT(r.atAfter.objective, 1e-20);
  for (size_t i = 0; i < kLinks.size(); ++i)
    EXPECT_NEAR(r.after[i], test::dimensionValue(truth.m, kLinks[i]), 1e-6) << kLinks[i];
  EXPECT_LT(r.atAfter.measures[0][1], 1e-9);  // largest distance of a given point, mm
  // The design written out closes and, loaded afresh, passes through the points.
  Kinematics again;
  ASSERT_TRUE(again.load(r.design).ok());
  for (size_t i = 0; i < kLinks.size(); ++i)
    EXPECT_NEAR(test::dimensionValue(r.design, kLinks[i]), r.after[i], 1e-9) << kLinks[i];
  EXPECT_TRUE(std::isfinite(one.atBefore.objective) && std::isfinite(r.atBefore.objective));
}

// A stroke target met to 1e-9 mm: the coupler point's stroke (along +y) of the same four-bar
// with a 23 mm crank, built apart, reached by varying the crank alone from 20 mm.
TEST(Optimize, StrokeTargetIsMetToANanometre) {
  const test::FourBar f = design(), other = design(23);
  Kinematics k, base;
  ASSERT_TRUE(k.load(other.m).ok());
  const double stroke = findLimits(k, LimitMeasure::along(other.P, Vec2(0, 1))).stroke;
  ASSERT_TRUE(base.load(f.m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O2-A", 15, 25}};
  spec.targets = {{OptTarget::Kind::Stroke, f.P, stroke}};
  spec.starts = 4;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.after[0], 23, 1e-6);
  Kinematics again;
  ASSERT_TRUE(again.load(r.design).ok());
  const Limits l = findLimits(again, LimitMeasure::along(r.design.outputs.front(), Vec2(0, 1)));
  EXPECT_NEAR(l.stroke, stroke, 1e-9);
  EXPECT_EQ(r.foundBest, 4);
}

// No start turns fully (a crank longer than the rest can follow): refused, saying so, no NaN.
TEST(Optimize, NoFeasibleStartIsRefusedWithItsReason) {
  const test::FourBar f = design();
  Kinematics base;
  ASSERT_TRUE(base.load(f.m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O2-A", 45, 60}};
  spec.targets = {{OptTarget::Kind::Stroke, f.P, 40}};
  spec.starts = 5;
  const OptimizeResult r = optimize(base, spec);
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.message.find("no start assembles"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.infeasibleStarts, 5);
  spec.variables = {{"crank.nothing", 1, 2}};
  EXPECT_NE(optimize(base, spec).status.message.find("crank.nothing"), std::string::npos);
}

// A transmission angle kept within 50 to 130 degrees: the crank-rocker's coupler-rocker angle
// leaves that band as drawn; varying the rocker and its pivot brings it inside, the swept
// angles of the design written out agreeing (the measures are the transmission sweep's own).
TEST(Optimize, TransmissionAngleIsBroughtIntoItsBand) {
  const test::FourBar f = design();
  Kinematics base;
  ASSERT_TRUE(base.load(f.m).ok());
  const TransmissionSweep before = sweepTransmission(base);
  ASSERT_LT(before.summaries[0].min, 50);
  OptimizeSpec spec;
  spec.variables = {{"rocker.B-O4", 30, 70}, {"ground.O4.x", 40, 80}, {"coupler.A-B", 40, 70}};
  OptTarget mu{OptTarget::Kind::Transmission, f.B};
  mu.limitDeg = 50;
  spec.targets = {mu};
  spec.starts = 4;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  Kinematics again;
  ASSERT_TRUE(again.load(r.design).ok());
  const TransmissionSweep after = sweepTransmission(again);
  EXPECT_GE(after.summaries[0].min, 50 - 1e-6);
  EXPECT_LE(after.summaries[0].max, 130 + 1e-6);
  EXPECT_NEAR(r.atAfter.measures[0][0], after.summaries[0].min, 1e-9);
}

}  // namespace
}  // namespace linkage
