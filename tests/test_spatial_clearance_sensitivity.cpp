// A clearance's closest approach on a machine in space differentiated with respect to every
// dimension (linkage/clearance_sensitivity.h: in the world, n . (dA - dB) at the closest crank
// angle): the lockstitch bevel's hook point to the needle's point and to the needle rod,
// against the changed designs' closest approaches (changeDimensions, findClearance again):
// central differences, 1e-6 mm per unit; and its spread under a tolerance (linkage/
// cycle_spread.h), first order from those derivatives.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/space_distance.h"
#include "clearance_checks.h"
#include "examples.h"
#include "linkage/clearance_sensitivity.h"
#include "linkage/cycle_spread.h"
#include "linkage/dimension_change.h"
#include "linkage/io/model_file.h"
#include "linkage/optimize.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

TEST(SpatialClearanceSensitivity, TheHooksClosestApproachesMoveAsChangedDesignsDo) {
  const Mechanism m = test::example("lockstitch-bevel");
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N"),
                A = *m.findPoint("rod.A"), B = *m.findPoint("rod.B");
  test::expectClosestMovesAsChangedDesignsDo(m, {K, ClearancePart::of(N), {}}, 1e-5);
  test::expectClosestMovesAsChangedDesignsDo(m, {K, ClearancePart::segment(A, B), {}}, 1e-5);
}

SlotId slotNamed(const Mechanism& m, const std::string& label) {
  for (const Slot& s : m.slots)
    if (m.slotLabel(s.id) == label) return s.id;
  ADD_FAILURE() << "no slot " << label;
  return {};
}

// A straight slot in space is the segment between its ends: the hook's point K to the ground's
// needle slot (x = 0, z = 0, y from -20 to -170). K = (20 - 25 sin 2phi, -200 + 25 cos 2phi, 0)
// stays below the slot's lower end, so the least distance is to that end (0, -170, 0):
// d^2 = 1925 - 1000 sin 2phi - 1500 cos 2phi, least sqrt(1925 - 500 sqrt 13).
TEST(SpatialClearanceSensitivity, TheHookToTheNeedleSlotAsItsClosedFormAndChangedDesigns) {
  const Mechanism m = test::example("lockstitch-bevel");
  const ClearanceWatch w{
      *m.findPoint("hook.K"), ClearancePart::of(slotNamed(m, "ground.needle")), {}};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const Clearance c = findClearance(k, ClearancePart::of(w.point), w.other);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_NEAR(c.closest.distance, std::sqrt(1925 - 500 * std::sqrt(13.0)), 1e-9);
  EXPECT_NEAR(c.closestOther3.y(), -170, 1e-9);
  test::expectClosestMovesAsChangedDesignsDo(m, w, 1e-5);
}

// A slot on a moving body in a plane turned in its class: a four-bar in the vertical plane V
// whose coupler is in W, parallel to V, 5 mm out, turned 40 degrees in it and shifted; a ground
// point 10 mm out of V watched against the coupler's slot, every dimension (the slot's offset
// and angle in W, both planes' origins) against changed designs.
std::string coupledInTurnedPlane() {
  const double a = 30 * M_PI / 180, turn = 40 * M_PI / 180;
  const Vec3 o(10, 20, 30), X(std::cos(a), std::sin(a), 0), Y(0, 0, 1), n = X.cross(Y);
  const Vec2 shift(7, -3);
  const Vec3 Xw = std::cos(turn) * X + std::sin(turn) * Y,
             Yw = -std::sin(turn) * X + std::cos(turn) * Y;
  const Vec3 ow = o + shift.x() * X + shift.y() * Y + 5 * n;
  auto inW = [&](const Vec2& p) { return Vec2(Rot::of(-turn) * Vec2(p - shift)); };
  auto world = [&](const Vec2& p) { return Vec3(o + p.x() * X + p.y() * Y); };
  const double d = 60, r = 20, b = 70, c = 50, start = 35 * M_PI / 180;
  const Vec2 A = r * Vec2(std::cos(start), std::sin(start)), O4(d, 0), u = O4 - A;
  const double L = u.norm(), along = (b * b - c * c + L * L) / (2 * L);
  const Vec2 B = A + along * u / L + std::sqrt(b * b - along * along) * perp(u) / L;
  const Vec2 Aw = inW(A), Bw = inW(B), e = (Bw - Aw).normalized();
  const Vec2 g0 = Aw + 0.2 * (Bw - Aw) + 8 * perp(e), g1 = Aw + 0.8 * (Bw - Aw) + 8 * perp(e);
  using test::vec;
  using test::vec2;
  return R"({"format": "linkage", "version": 1, "name": "four-bar, coupler in a turned plane",
  "planes": {"v": {"origin": )" +
         vec(o) + R"(, "x_axis": )" + vec(X) + R"(, "y_axis": )" + vec(Y) + R"(},
             "w": {"origin": )" +
         vec(ow) + R"(, "x_axis": )" + vec(Xw) + R"(, "y_axis": )" + vec(Yw) + R"(}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O2": )" +
         vec(world(Vec2::Zero())) + R"(, "O4": )" + vec(world(O4)) + R"(, "Q": )" +
         vec(world(Vec2(-50, 90)) + 10 * n) + R"(}},
    {"name": "crank", "plane": "v", "points": {"O2": [0, 0], "A": )" +
         vec2(A) + R"(}},
    {"name": "coupler", "plane": "w", "points": {"A": )" +
         vec2(Aw) + R"(, "B": )" + vec2(Bw) + R"(}, "slots": {"g": [)" + vec2(g0) + ", " +
         vec2(g1) + R"(]}},
    {"name": "rocker", "plane": "v", "points": {"B": )" +
         vec2(B) + R"(, "O4": )" + vec2(O4) + R"(}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.O2", "b": "crank.O2"},
    {"type": "pin", "a": "crank.A", "b": "coupler.A"},
    {"type": "pin", "a": "coupler.B", "b": "rocker.B"},
    {"type": "pin", "a": "rocker.O4", "b": "ground.O4"}
  ],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}
})";
}

TEST(SpatialClearanceSensitivity, ASlotOnABodyInATurnedPlaneAsChangedDesignsDo) {
  const LoadResult r = parseMechanism(coupledInTurnedPlane());
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  const ClearanceWatch w{
      *m.findPoint("ground.Q"), ClearancePart::of(slotNamed(m, "coupler.g")), {}};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  // The slot's ends in the world where the coupler's points carry them: at every crank angle
  // each end keeps its distances from the coupler's A and B as drawn.
  const Slot& slot = *m.slot(w.other.slot);
  SpaceMotion ends[2];
  for (double deg : {0.0, 120.0, 250.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    slotEndsInSpace(k, slot, ends);
    const Vec3 A = k.motionInSpace(*m.findPoint("coupler.A")).position,
               B = k.motionInSpace(*m.findPoint("coupler.B")).position;
    const Vec2 drawn[2] = {slot.p0, slot.p1};
    for (int e = 0; e < 2; ++e) {
      EXPECT_NEAR((ends[e].r - A).norm(),
                  (drawn[e] - m.point(*m.findPoint("coupler.A"))->pos).norm(), 1e-9);
      EXPECT_NEAR((ends[e].r - B).norm(),
                  (drawn[e] - m.point(*m.findPoint("coupler.B"))->pos).norm(), 1e-9);
    }
  }
  test::expectClosestMovesAsChangedDesignsDo(m, w, 1e-5);
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

// A clearance to a slot in space as an optimize target: the hook's point kept 13 mm from the
// needle slot's lower end by the hook's radius rho; the least distance is sqrt(1300) - rho
// (K's circle about L = (20, -200, 0) passes the end (0, -170, 0) at |L - end| - rho), so rho
// goes to at most sqrt(1300) - 13; the written design's closest approach measured again.
TEST(SpatialClearanceSensitivity, AGapToTheNeedleSlotMetByTheHooksRadius) {
  Mechanism m = test::example("lockstitch-bevel");
  m.timing.clearances = {
      {*m.findPoint("hook.K"), ClearancePart::of(slotNamed(m, "ground.needle")), {}}};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"hook.L-K", 20, 40}};
  OptTarget t;
  t.kind = OptTarget::Kind::Clearance;
  t.index = 0;
  t.gapMm = 13;
  spec.targets = {t};
  spec.starts = 3;
  const OptimizeResult r = optimize(k, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.after[0], std::sqrt(1300.0) - 13 + 1e-6);
  Kinematics after;
  ASSERT_TRUE(after.load(r.design).ok());
  const Clearance c = findClearance(after, ClearancePart::of(m.timing.clearances[0].point),
                                    m.timing.clearances[0].other);
  ASSERT_TRUE(c.status.ok());
  EXPECT_GE(c.closest.distance, 13 - 1e-6);
  EXPECT_NEAR(c.closest.distance, std::sqrt(1300.0) - r.after[0], 1e-9);
  EXPECT_NEAR(r.atAfter.measures.at(0).at(0), c.closest.distance, 1e-9);
}

}  // namespace
}  // namespace linkage
