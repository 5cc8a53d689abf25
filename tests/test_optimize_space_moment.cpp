// Counterweights against the shaking moment on a machine in space (linkage/optimize.h): the RSSR
// with masses on its crank and rocker (crossed shafts, the crank's ball end 5 mm out of its
// plane, gravity across both planes). The peak the search measures is the written design's
// (the counterweights added to their bodies' masses and the dynamics solved again), and its
// gradient over counterweights and dimensions together is the central differences'.
#include <gtest/gtest.h>

#include <cstdio>

#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/optimize.h"
#include "loaded_rssr.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

using test::bothCounterweights;
using test::loadedRssr;
using test::turned;

OptimizeSpec momentOver(OptimizeSpec spec) {
  OptTarget t;
  t.kind = OptTarget::Kind::Shaking;
  t.moment = true;
  spec.targets = {t};
  spec.steps = 120;
  return spec;
}

// The design with the counterweights of `spec`'s variables at x (x, y of each body's, in
// bothCounterweights' order) written in as masses of their bodies.
Kinematics writtenIn(const Mechanism& m, const std::vector<double>& x) {
  Mechanism heavier = m;
  std::vector<Counterweight> cws(2);
  const char* bodies[] = {"crank", "rocker"};
  for (int c = 0; c < 2; ++c) {
    EXPECT_TRUE(counterweightOn(m, m.bodyNamed(bodies[c])->id, cws[c]).ok());
    cws[c].staticMoment = Vec2(x[2 * c], x[2 * c + 1]);
    cws[c].kg = cws[c].staticMoment.norm() / cws[c].maxRadiusMm;
  }
  addCounterweights(heavier, cws);
  Kinematics k;
  EXPECT_TRUE(k.load(heavier).ok());
  k.setAccelerations(true);
  return k;
}

// The peak of |M| (the world's 3-vector about its origin) the search measures with both bodies'
// counterweights is the written design's at the peak's angle, and no sample of the written
// design over the turn is above it: as drawn, and with the crank or the rocker in a plane turned
// in its class.
TEST(OptimizeSpaceMoment, CounterweightsWrittenInBearTheMeasuredPeak) {
  const std::vector<double> x{3, -2, 1.5, 4};
  for (const char* which : {"", "crank", "rocker"}) {
    const Mechanism m = *which ? turned(which) : loadedRssr();
    Kinematics base;
    ASSERT_TRUE(base.load(m).ok());
    const Evaluation e = evaluate(base, momentOver(bothCounterweights()), x, false);
    ASSERT_TRUE(e.feasible) << e.why;
    Kinematics written = writtenIn(m, x);
    Vec3 F, M;
    double largest = 0;
    for (int i = 0; i < 3600; ++i) {
      ASSERT_TRUE(written.moveTo(i * 0.1).ok());
      shaking(written, F, M);
      largest = std::max(largest, M.norm());
    }
    ASSERT_TRUE(written.moveTo(e.measures[0][1]).ok());
    shaking(written, F, M);
    const double peak = e.measures[0][0];
    std::printf(
        "  %-7s peak %.12g N m at %.6f degrees; written design there %.12g, sampled %.12g\n",
        *which ? which : "drawn", peak, e.measures[0][1], M.norm(), largest);
    EXPECT_NEAR(M.norm(), peak, 1e-12 * peak) << which;
    EXPECT_GE(peak, largest - 1e-12 * largest) << which;
    EXPECT_LT(peak, largest + 1e-6 * largest) << which;
    Kinematics bare;  // the counterweights change it: the test sees their part
    ASSERT_TRUE(bare.load(m).ok());
    bare.setAccelerations(true);
    ASSERT_TRUE(bare.moveTo(e.measures[0][1]).ok());
    Vec3 F0, M0;
    shaking(bare, F0, M0);
    EXPECT_GT((M - M0).norm(), 1e-2 * peak) << which;
  }
}

// The objective's gradient against central differences: over the counterweights alone, and over
// the crank's ball end's depth (it moves the crank's mass off its pivot's depth), the rod's
// length and the rocker's plane's origin together with the counterweights.
TEST(OptimizeSpaceMoment, GradientMatchesCentralDifferences) {
  for (const char* which : {"", "rocker"}) {
    Kinematics base;
    ASSERT_TRUE(base.load(*which ? turned(which) : loadedRssr()).ok());
    OptimizeSpec spec = momentOver(bothCounterweights());
    std::vector<double> x{3, -2, 1.5, 4};
    test::expectGradientAt(base, spec, x);
    if (*which) continue;  // the rocker's plane holds nothing there
    std::vector<double> dims;
    OptimizeSpec mixed = test::spaceSpec(base.mechanism(), "shaking:moment<=0", dims);
    for (const OptVariable& v : spec.variables) mixed.variables.push_back(v);
    dims.insert(dims.end(), x.begin(), x.end());
    test::expectGradientAt(base, mixed, dims);
  }
}

// The peak lowered below 0.96 of the bare design's by the two counterweights (their best within
// their bounds, found by every start, is 0.953 of it), and the written design feeling the peak
// reported where it was found.
TEST(OptimizeSpaceMoment, CounterweightsBringThePeakUnderALimit) {
  Kinematics base;
  ASSERT_TRUE(base.load(loadedRssr()).ok());
  OptimizeSpec spec = momentOver(bothCounterweights());
  const Evaluation bare = evaluate(base, spec, {0, 0, 0, 0}, false);
  ASSERT_TRUE(bare.feasible) << bare.why;
  spec.targets[0].limitN = 0.96 * bare.measures[0][0];
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  std::printf("  peak %.6g -> %.6g N m (limit %.6g), %d of %d starts\n", bare.measures[0][0], peak,
              spec.targets[0].limitN, r.foundBest, r.starts);
  EXPECT_LE(peak, spec.targets[0].limitN * (1 + 1e-9));
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  Vec3 F, M;
  shaking(after, F, M);
  EXPECT_NEAR(M.norm(), peak, 1e-9 * peak);
}

}  // namespace
}  // namespace linkage
