// A watched clearance and a timing window's end as optimiser targets (linkage/optimize.h, issue
// 29): their gradients (exact: the envelope theorem at the closest approach, the implicit
// function theorem at a window's end) against central differences of the objective (in the test
// only), and both targets met.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "examples.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "mechanisms.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

// A crank-rocker whose coupler point P is watched against the rocker's pivot O4 and opens a
// window while P is above y = 40.
test::FourBar watched() {
  test::FourBar f = test::fourBar(60, 20, 55, 45, 0, true, 25, 20);
  f.m.timing.clearances.push_back({f.P, ClearancePart::of(f.O4), std::nullopt});
  TimingWindow w;
  w.name = "high";
  w.output = LimitMeasure::along(f.P, Vec2(0, 1));
  w.below = false;
  w.level = 40;
  f.m.timing.windows.push_back(w);
  return f;
}

OptTarget clearance(double gap) {
  OptTarget t;
  t.kind = OptTarget::Kind::Clearance;
  t.index = 0;
  t.gapMm = gap;
  return t;
}

OptTarget window(bool end, double deg) {
  OptTarget t;
  t.kind = OptTarget::Kind::Window;
  t.window = "high";
  t.windowEnd = end;
  t.crankDeg = deg;
  return t;
}

TEST(OptimizeWatch, GradientMatchesCentralDifferences) {
  const test::FourBar f = watched();
  Kinematics base;
  ASSERT_TRUE(base.load(f.m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O2-A", 1, 100},
                    {"coupler.A-B", 1, 100},
                    {"coupler.B-P", 1, 100},
                    {"coupler.A-P", 1, 100},
                    {"ground.O4.x", 0, 100}};
  const std::vector<double> x = {20, 55, std::hypot(55 - 25, 20), std::hypot(25, 20), 60};
  spec.targets = {clearance(0), window(false, 0), window(true, 0)};
  const Evaluation probe = evaluate(base, spec, x);
  ASSERT_TRUE(probe.feasible) << probe.why;
  const double least = probe.measures[0][0];
  ASSERT_GT(least, 1);
  // The gap above the least distance, the window's ends away from where they are.
  spec.targets = {clearance(least + 5), window(false, probe.measures[1][0] + 7),
                  window(true, probe.measures[2][0] - 4)};
  spec.targets[2].weight = 0.5;
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-6);
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
    EXPECT_GT(std::abs(fd), 1e-3) << spec.variables[i].name;  // each variable moves something
  }
}

TEST(OptimizeWatch, ClearanceAndWindowTargetsAreMet) {
  const test::FourBar f = watched();
  Kinematics base;
  ASSERT_TRUE(base.load(f.m).ok());
  OptimizeSpec spec;
  spec.variables = {{"coupler.B-P", 20, 60}, {"coupler.A-P", 20, 60}};
  spec.starts = 6;
  spec.targets = {clearance(0), window(false, 0)};
  const Evaluation before = evaluate(base, spec, {std::hypot(30, 20), std::hypot(25, 20)});
  ASSERT_TRUE(before.feasible) << before.why;
  spec.targets = {clearance(before.measures[0][0] + 3), window(false, before.measures[1][0] - 5)};
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  std::printf("  least %.6f -> %.6f mm, window opens %.6f -> %.6f deg, %d of %d starts\n",
              before.measures[0][0], r.atAfter.measures[0][0], before.measures[1][0],
              r.atAfter.measures[1][0], r.foundBest, r.starts);
  EXPECT_GE(r.atAfter.measures[0][0], before.measures[0][0] + 3 - 1e-6);
  EXPECT_NEAR(r.atAfter.measures[1][0], before.measures[1][0] - 5, 1e-6);
  EXPECT_LT(r.atAfter.objective, 1e-10);
}

TEST(OptimizeWatch, TheLockstitchNeedleOpensWhereAsked) {
  Kinematics base;
  ASSERT_TRUE(base.load(test::example("lockstitch-machine")).ok());
  OptimizeSpec spec;
  spec.variables = {{"rod.A-B", 20, 200}};
  OptTarget t = window(false, 128);
  t.window = "needle";
  spec.targets = {t};
  spec.starts = 4;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.atBefore.measures[0][0], 131.58827336748303, 1e-9);
  EXPECT_NEAR(r.atAfter.measures[0][0], 128, 1e-9);
  // Refused by name: a clearance the file does not watch, a window it does not have.
  spec.targets = {clearance(1)};
  spec.targets[0].index = 7;
  EXPECT_NE(optimize(base, spec).status.message.find("the file watches 1"), std::string::npos);
  t.window = "nothing";
  spec.targets = {t};
  EXPECT_NE(optimize(base, spec).status.message.find("no window named \"nothing\""),
            std::string::npos);
}

// The targets' text (linkage/optimize_text.h), the CLI's, Python's and the editor's: a path's
// file may cite its source in comments before its header; a bad line is named by its number.
TEST(OptimizeText, APathFilesCommentsHeaderAndBadLine) {
  const test::FourBar f = watched();
  const std::string good = ::testing::TempDir() + "path_good.csv",
                    bad = ::testing::TempDir() + "path_bad.csv";
  std::ofstream(good) << "# McGarva (1994), as four-bar-rs keeps it\n\nx,y\n1,2\r\n3.5,-4\n";
  std::ofstream(bad) << "x,y\n1,2\n# a comment\nthree,4\n";
  OptTarget t;
  std::string why;
  ASSERT_TRUE(parseOptTarget(f.m, "path:coupler.P=" + good + "*2", t, why)) << why;
  EXPECT_EQ(t.kind, OptTarget::Kind::Path);
  ASSERT_EQ(t.path.size(), 2u);
  EXPECT_EQ(t.path[1], Vec2(3.5, -4));
  EXPECT_EQ(t.weight, 2);
  EXPECT_FALSE(parseOptTarget(f.m, "path:coupler.P=" + bad, t, why));
  EXPECT_NE(why.find(bad + ":4: not two numbers x,y"), std::string::npos) << why;
  EXPECT_TRUE(parseOptTarget(f.m, "window:high.end=30", t, why)) << why;
  EXPECT_EQ(optTargetName(f.m, t), "high.end");
  EXPECT_TRUE(parseOptTarget(f.m, "force:pin:crank.A<=3", t, why)) << why;
  EXPECT_EQ(optTargetName(f.m, t), "pin:crank.A");
}

}  // namespace
}  // namespace linkage
