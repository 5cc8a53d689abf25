// A closest approach's derivatives by the envelope theorem (linkage/clearance_sensitivity.h)
// against the offset slider-crank's closed form: the block on x = e rises to
// Y1 = sqrt((l + r)^2 - e^2); a ground point Q = (e, h) above it is h - Y1 away at the top, so
//   d/dr = d/dl = -(l + r) / Y1,  d/d(Q.y) = 1,  d/d(Q.x) = 0 (the top is straight below Q);
// a ground segment from Q1 = (e - a, h) to Q2 = (e + b, h) over it is as far, the nearest point
// at t = a / (a + b): d/d(Q1.y) = 1 - t, d/d(Q2.y) = t.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/clearance_sensitivity.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "mechanisms.h"

namespace linkage {
namespace {

struct Case {
  test::SliderCrank sc;
  PointId Q, Q1, Q2;
};

Case withGround(double r, double l, double e, double h) {
  Case c{test::sliderCrank(r, l, e, 30), {}, {}, {}};
  c.Q = c.sc.m.addPoint(c.sc.ground, "Q", Vec2(e, h));
  c.Q1 = c.sc.m.addPoint(c.sc.ground, "Q1", Vec2(e - 10, h));
  c.Q2 = c.sc.m.addPoint(c.sc.ground, "Q2", Vec2(e + 30, h));
  return c;
}

double of(const ClearanceSensitivity& s, const std::string& name) {
  for (size_t i = 0; i < s.dims.size(); ++i)
    if (s.dims[i].name == name) return s.derivative[i];
  ADD_FAILURE() << "no dimension " << name;
  return NAN;
}

TEST(ClearanceSensitivity, TheSliderCranksClosedForm) {
  const double r = 20, l = 70, e = 12, h = 110, Y1 = std::sqrt((l + r) * (l + r) - e * e);
  const Case c = withGround(r, l, e, h);
  Kinematics k;
  ASSERT_TRUE(k.load(c.sc.m).ok());
  const ClearanceSensitivity p =
      clearanceSensitivity(k, {c.sc.B, ClearancePart::of(c.Q), {}}, dimensions(c.sc.m));
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  EXPECT_NEAR(p.clearance.closest.distance, h - Y1, 1e-9);
  EXPECT_NEAR(of(p, "crank.O-A"), -(l + r) / Y1, 1e-9);
  EXPECT_NEAR(of(p, "rod.A-B"), -(l + r) / Y1, 1e-9);
  EXPECT_NEAR(of(p, "ground.Q.y"), 1, 1e-9);
  EXPECT_NEAR(of(p, "ground.Q.x"), 0, 1e-9);
  const ClearanceSensitivity seg =
      clearanceSensitivity(k, {c.sc.B, ClearancePart::segment(c.Q1, c.Q2), {}}, dimensions(c.sc.m));
  ASSERT_TRUE(seg.status.ok()) << seg.status.message;
  EXPECT_NEAR(seg.clearance.closest.distance, h - Y1, 1e-9);
  EXPECT_NEAR(of(seg, "crank.O-A"), -(l + r) / Y1, 1e-9);
  EXPECT_NEAR(of(seg, "ground.Q1.y"), 0.75, 1e-9);
  EXPECT_NEAR(of(seg, "ground.Q2.y"), 0.25, 1e-9);
}

// A distance is a length: scaling every length of the drawing by 1 + t scales it by as much
// (Euler: the lengths times their derivatives add up to the least distance; angles and ratios do
// not scale). The lockstitch machines' hook point to the needle's point N (their watched
// clearance, to the needle's segment, is 0 where the hook's point crosses the needle's line as
// drawn: that has no derivative, and says so).
TEST(ClearanceSensitivity, LengthsTimesTheirDerivativesAddUpToTheDistance) {
  for (const char* name : {"lockstitch-machine", "lockstitch-arm-shaft"}) {
    const LoadResult l = loadMechanismFile(*resolveModel(name));
    ASSERT_TRUE(l.mechanism) << l.error;
    const Mechanism& m = *l.mechanism;
    ASSERT_EQ(m.timing.clearances.size(), 1u);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const ClearanceSensitivity touch =
        clearanceSensitivity(k, m.timing.clearances[0], dimensions(m));
    EXPECT_NE(touch.status.message.find("touch"), std::string::npos) << touch.status.message;
    const ClearanceWatch w{
        *m.findPoint("hook.K"), ClearancePart::of(*m.findPoint("needlebar.N")), {}};
    const ClearanceSensitivity s = clearanceSensitivity(k, w, dimensions(m));
    ASSERT_TRUE(s.status.ok()) << name << ": " << s.status.message;
    ASSERT_GT(s.clearance.closest.distance, 1);
    double euler = 0;
    for (size_t d = 0; d < s.dims.size(); ++d)
      if (s.dims[d].unit == Dimension::Unit::Mm) euler += s.dims[d].value * s.derivative[d];
    EXPECT_NEAR(euler, s.clearance.closest.distance, 1e-9 * std::max(1.0, euler)) << name;
  }
}

// To a slot: the offset slider-crank's crank pin A to its own ground slot, the line through
// P0 = (e, -50) at angle alpha, which the crank circle does not reach (e > r): the closest is
// h - r, h = |cross(d, O - P0)| = 50 cos(alpha) + 30 sin(alpha) with O the crank pivot, so
// d/dr = -1, d/d(O.x) = -1 (towards the slot), d/d(O.y) = 0, d/d(offset) = -1 (its normal is -x),
// d/d(angle) = (-50 sin(alpha) + 30 cos(alpha)) pi / 180 = -50 pi / 180, d/d(rod) = 0.
TEST(ClearanceSensitivity, ToASlotByTheDistanceFromItsLine) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 30, 30);
  sc.m.slots[0].p0 = Vec2(30, -50);
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  PointId A;
  for (const Point& p : sc.m.points)
    if (p.body == sc.crank && p.name == "A") A = p.id;
  const ClearanceSensitivity s =
      clearanceSensitivity(k, {A, ClearancePart::of(sc.m.slots[0].id), {}}, dimensions(sc.m));
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_NEAR(s.clearance.closest.distance, 10, 1e-9);
  EXPECT_NEAR(of(s, "crank.O-A"), -1, 1e-10);
  EXPECT_NEAR(of(s, "ground.O.x"), -1, 1e-10);
  EXPECT_NEAR(of(s, "ground.O.y"), 0, 1e-10);
  EXPECT_NEAR(of(s, "ground.guide.offset"), -1, 1e-10);
  EXPECT_NEAR(of(s, "ground.guide.angle"), -50 * M_PI / 180, 1e-10);
  EXPECT_NEAR(of(s, "rod.A-B"), 0, 1e-10);
  // The whole frame moved by dx (the pivot and the slot, whose normal is -x) changes nothing.
  EXPECT_NEAR(of(s, "ground.O.x") - of(s, "ground.guide.offset"), 0, 1e-12);
}

TEST(ClearanceSensitivity, WhatHasNoDerivativeIsSaid) {
  const Case c = withGround(20, 70, 12, 110);
  Kinematics k;
  ASSERT_TRUE(k.load(c.sc.m).ok());
  const ClearanceSensitivity slot = clearanceSensitivity(
      k, {c.sc.A, ClearancePart::of(c.sc.m.slots[0].id), {}}, dimensions(c.sc.m));
  EXPECT_FALSE(slot.status.ok());
  // The crank pin crosses the slot's line: they touch, no derivative.
  EXPECT_NE(slot.status.message.find("touch"), std::string::npos) << slot.status.message;
}

}  // namespace
}  // namespace linkage
