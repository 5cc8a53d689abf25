// A clearance's closest approach on a machine in space differentiated with respect to every
// dimension (linkage/clearance_sensitivity.h: in the world, n . (dA - dB) at the closest crank
// angle): the lockstitch bevel's hook point to the needle's point and to the needle rod,
// against the changed designs' closest approaches (changeDimensions, findClearance again):
// central differences, 1e-6 mm per unit; and its spread under a tolerance (linkage/
// cycle_spread.h), first order from those derivatives.
#include <gtest/gtest.h>

#include <cmath>

#include "clearance_checks.h"
#include "examples.h"
#include "linkage/clearance_sensitivity.h"
#include "linkage/cycle_spread.h"
#include "linkage/dimension_change.h"
#include "linkage/optimize.h"

namespace linkage {
namespace {

TEST(SpatialClearanceSensitivity, TheHooksClosestApproachesMoveAsChangedDesignsDo) {
  const Mechanism m = test::example("lockstitch-bevel");
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N"),
                A = *m.findPoint("rod.A"), B = *m.findPoint("rod.B");
  test::expectClosestMovesAsChangedDesignsDo(m, {K, ClearancePart::of(N), {}}, 1e-5);
  test::expectClosestMovesAsChangedDesignsDo(m, {K, ClearancePart::segment(A, B), {}}, 1e-5);
}

// The spread's first order is the derivative times the tolerance, and the samples (tiny
// tolerances) stay within the first-order worst case to second order.
TEST(SpatialClearanceSensitivity, ItsSpreadUnderAToleranceIsFirstOrderForSmallOnes) {
  Mechanism m = test::example("lockstitch-bevel");
  const ClearanceWatch w{
      *m.findPoint("hook.K"), ClearancePart::of(*m.findPoint("needlebar.N")), {}};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  const ClearanceSensitivity s = clearanceSensitivity(k, w, dims);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  size_t d = 0;
  while (d < dims.size() && dims[d].name != "hook.L-K") ++d;
  ASSERT_LT(d, dims.size());
  ToleranceSpec spec;
  const double T = 0.01;
  spec.tolerances = {{"hook.L-K", T, false}};
  spec.samples = 200;
  const SpreadResult r = clearanceSpread(m, spec, w);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.values.size(), 1u);
  EXPECT_NEAR(r.values[0].worst, std::abs(s.derivative[d]) * T, 1e-12);
  EXPECT_GT(r.values[0].worst, 1e-4);
  EXPECT_EQ(r.used, spec.samples);
  EXPECT_GE(r.values[0].lo, r.values[0].nominal - r.values[0].worst - 1e-6);
  EXPECT_LE(r.values[0].hi, r.values[0].nominal + r.values[0].worst + 1e-6);
}

// A clearance in the world as an optimize target: the hook's point kept 3 mm from the needle's
// by the hook's radius, the written design's closest approach measured again.
TEST(SpatialClearanceSensitivity, AGapMetByTheHooksRadius) {
  Mechanism m = test::example("lockstitch-bevel");
  m.timing.clearances = {
      {*m.findPoint("hook.K"), ClearancePart::of(*m.findPoint("needlebar.N")), {}}};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"hook.L-K", 20, 40}};
  OptTarget t;
  t.kind = OptTarget::Kind::Clearance;
  t.index = 0;
  t.gapMm = 3;
  spec.targets = {t};
  spec.starts = 3;
  const OptimizeResult r = optimize(k, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  Kinematics after;
  ASSERT_TRUE(after.load(r.design).ok());
  const Clearance c = findClearance(after, ClearancePart::of(m.timing.clearances[0].point),
                                    m.timing.clearances[0].other);
  ASSERT_TRUE(c.status.ok());
  EXPECT_GE(c.closest.distance, 3 - 1e-6);
  EXPECT_NEAR(r.atAfter.measures.at(0).at(0), c.closest.distance, 1e-9);
}

}  // namespace
}  // namespace linkage
