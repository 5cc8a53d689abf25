// A clearance to a slot differentiated (linkage/clearance_sensitivity.h) where no test had
// looked: to an ARC slot (its point between the ends, which moves radially with the centre and
// the radius, and its end, which moves as the arc does), and to a slot on a MOVING body (a
// slotted lever). Each derivative is that of the least distance over the turn (the envelope
// theorem: the closest crank angle moves too, and does not count to first order), checked
// against the changed designs' own least distances (changeDimensions, solved again,
// findClearance again: central differences, 1e-6 per unit) for every dimension, and for the arc
// against closed forms by the complex step.
#include <gtest/gtest.h>

#include <cmath>

#include "clearance_checks.h"
#include "complex_step.h"
#include "linkage/clearance_sensitivity.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;

double of(const ClearanceSensitivity& s, const std::string& name) {
  for (size_t i = 0; i < s.dims.size(); ++i)
    if (s.dims[i].name == name) return s.derivative[i];
  ADD_FAILURE() << "no dimension " << name;
  return NAN;
}

Vec2 on(const Vec2& c, double radius, double deg) {
  return c + radius * Vec2(std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180));
}

// A crank O-A (r = 20) drives a block in a ground arc slot "guide" (centre G = (5, -110),
// radius 70, from 30 to 150 degrees about G) by a rod of 80; a second ground arc "stop" (centre
// S = (60, 40), radius 25, from 250 to 330 degrees) takes no joint.
//  - The crank pin to the guide: its circle outside the guide's, the closest approach is where
//    A points at G, the nearest point of the arc between its ends: |G - O| - r - rho.
//  - The crank pin to the stop: the stop's points nearest O lie towards O from S (213.7
//    degrees), outside its ends, so its end E = S + rho2 u (u at 250 degrees) is nearest:
//    |E - O| - r.
struct ArcCase {
  Mechanism m;
  PointId A;
  SlotId guide, stop;
};

const Vec2 kG(5, -110), kS(60, 40);
constexpr double kR = 20, kL = 80, kRho = 70, kRho2 = 25;

ArcCase arcCase() {
  ArcCase a;
  Mechanism& m = a.m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod"),
               block = m.addBody("block");
  const Vec2 O(0, 0), A(kR, 0);
  // B on the guide's circle, kL from A, on the right.
  const Vec2 AG = kG - A;
  const double d = AG.norm(), x = (kL * kL - kRho * kRho + d * d) / (2 * d);
  const Vec2 u = AG / d, B = A + x * u - std::sqrt(kL * kL - x * x) * perp(u);
  a.guide = m.addArcSlot(g, "guide", on(kG, kRho, 30), on(kG, kRho, 90), on(kG, kRho, 150));
  a.stop = m.addArcSlot(g, "stop", on(kS, kRho2, 250), on(kS, kRho2, 290), on(kS, kRho2, 330));
  const JointId drive = m.addPin(m.addPoint(g, "O", O), m.addPoint(crank, "O", O));
  a.A = m.addPoint(crank, "A", A);
  m.addPin(a.A, m.addPoint(rod, "A", A));
  const PointId bB = m.addPoint(block, "B", B);
  m.addPin(m.addPoint(rod, "B", B), bB);
  m.addSlider(bB, a.guide);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  return a;
}

// The closed forms over complex numbers, by name: O, r, the guide's centre and radius, the
// stop's (its first end at 250 degrees about its centre).
C arcClosedForm(const std::string& stepped, bool toStop) {
  const char* names[] = {"ground.O.x",
                         "ground.O.y",
                         "crank.O-A",
                         "ground.guide.centre.x",
                         "ground.guide.centre.y",
                         "ground.guide.radius",
                         "ground.stop.centre.x",
                         "ground.stop.centre.y",
                         "ground.stop.radius"};
  C x[] = {0, 0, kR, kG.x(), kG.y(), kRho, kS.x(), kS.y(), kRho2};
  for (int i = 0; i < 9; ++i)
    if (stepped == names[i]) x[i] += C(0, test::kH);
  const CVec O{x[0], x[1]};
  const double t = 250 * M_PI / 180;
  const CVec far =
      toStop ? CVec{x[6] + x[8] * std::cos(t), x[7] + x[8] * std::sin(t)} : CVec{x[3], x[4]};
  const C reach = std::sqrt(test::dot(far - O, far - O));
  return toStop ? reach - x[2] : reach - x[2] - x[5];
}

TEST(SlotClearanceSensitivity, ToAnArcSlotByItsClosedFormsByTheComplexStep) {
  const ArcCase a = arcCase();
  Kinematics k;
  ASSERT_TRUE(k.load(a.m).ok());
  for (bool toStop : {false, true}) {
    const ClearanceWatch w{a.A, ClearancePart::of(toStop ? a.stop : a.guide), {}};
    const ClearanceSensitivity s = clearanceSensitivity(k, w, dimensions(a.m));
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    EXPECT_NEAR(s.clearance.closest.distance, arcClosedForm("", toStop).real(), 1e-9) << toStop;
    // At the closest approach the nearest point is where the cases above put it.
    const Vec2 toward = toStop ? on(kS, kRho2, 250) : kG;
    const Vec2 nearest = toStop ? toward : Vec2(kG + kRho * (Vec2(0, 0) - kG).normalized());
    EXPECT_NEAR((s.clearance.closestPoint - kR * toward.normalized()).norm(), 0, 1e-6);
    EXPECT_NEAR((s.clearance.closestOther - nearest).norm(), 0, 1e-6);
    double scale = 0;
    for (const Dimension& d : s.dims) {
      const double want = arcClosedForm(d.name, toStop).imag() / test::kH;
      scale = std::max(scale, std::abs(want));
      EXPECT_NEAR(of(s, d.name), want, 1e-9) << d.name << (toStop ? " to the stop" : "");
    }
    EXPECT_GT(scale, 0.5);
  }
}

TEST(SlotClearanceSensitivity, ToAnArcSlotMovesAsChangedDesignsDo) {
  const ArcCase a = arcCase();
  test::expectClosestMovesAsChangedDesignsDo(a.m, {a.A, ClearancePart::of(a.guide), {}}, 1e-6);
  test::expectClosestMovesAsChangedDesignsDo(a.m, {a.A, ClearancePart::of(a.stop), {}}, 1e-6);
}

// A slotted lever (the inverted slider-crank of a quick return): the crank O-A (20) with its pin
// in a slot of the lever pivoted at Q = (50, 10), the slot 3 mm off the lever's line through Q,
// from 5 to 90 mm along it. The lever swings between about 168 and 214 degrees (from Q); a ground
// point Z beyond its lower extreme is nearest the slot between its ends, and a ground point Z2
// beyond its upper extreme and past the slot's far end is nearest that end; each closest where
// the lever turns back.
struct Lever {
  Mechanism m;
  PointId Z, Z2;
  SlotId slot;
};

Lever lever() {
  Lever l;
  Mechanism& m = l.m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"),
               lever = m.addBody("lever");
  const Vec2 O(0, 0), A0(20, 0), Q(50, 10);
  const JointId drive = m.addPin(m.addPoint(g, "O", O), m.addPoint(crank, "O", O));
  m.addPin(m.addPoint(g, "Q", Q), m.addPoint(lever, "Q", Q));
  const Vec2 d = (A0 - Q).normalized(), off = 3 * perp(d);
  l.slot = m.addSlot(lever, "slot", Q + off + 5 * d, Q + off + 90 * d);
  m.addPinInSlot(m.addPoint(crank, "A", A0 + off), l.slot);
  l.Z = m.addPoint(g, "Z", on(Q, 40, 235));
  l.Z2 = m.addPoint(g, "Z2", on(Q, 100, 150));
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  return l;
}

TEST(SlotClearanceSensitivity, ToASlottedLeverMovesAsChangedDesignsDo) {
  const Lever l = lever();
  Kinematics k;
  ASSERT_TRUE(k.load(l.m).ok());
  for (PointId p : {l.Z, l.Z2}) {
    const ClearanceWatch w{p, ClearancePart::of(l.slot), {}};
    const Clearance c = findClearance(k, ClearancePart::of(p), w.other);
    ASSERT_TRUE(c.status.ok()) << c.status.message;
    // Z's nearest point lies between the slot's ends, Z2's is its far end.
    ASSERT_EQ(c.closestPart.size(), 2u);
    const Vec2 far = c.closestPart.back(), near = c.closestPart.front();
    if (p == l.Z) {
      EXPECT_GT((c.closestOther - far).norm(), 10);
      EXPECT_GT((c.closestOther - near).norm(), 10);
    } else {
      EXPECT_NEAR((c.closestOther - far).norm(), 0, 1e-9);
    }
    test::expectClosestMovesAsChangedDesignsDo(l.m, w, 1e-6);
  }
}

// The same clearance as an optimize target (linkage/optimize.h, clearance:N>=GAP): the
// objective's gradient, from these derivatives, against central differences of the objective.
// The slot's angle and offset varied together: a design turns the slot about its first end and
// gives the offset back its value (setDimensions), here a turn of the whole lever about Q that
// moves nothing (the gradient was the turn's alone, -0.295 where the objective stays).
TEST(SlotClearanceSensitivity, ASlottedLeversGapTargetsGradientMatchesCentralDifferences) {
  Lever l = lever();
  l.m.timing.clearances = {{l.Z, ClearancePart::of(l.slot), {}}};
  Kinematics base;
  ASSERT_TRUE(base.load(l.m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O-A", 10, 30},
                    {"ground.Q.x", 40, 60},
                    {"lever.slot.offset", -10, 10},
                    {"lever.slot.angle", 150, 250},
                    {"ground.Z.y", -40, 0}};
  OptTarget gap;
  gap.kind = OptTarget::Kind::Clearance;
  gap.gapMm = 20;  // more than it has: the residual is active
  spec.targets = {gap};
  std::vector<double> x;
  for (const OptVariable& v : spec.variables) x.push_back(test::dimensionValue(l.m, v.name));
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  ASSERT_LT(e.measures[0][0], 20);
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = test::centralDifference(base, spec, x, i, 1e-6);
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
  }
}

}  // namespace
}  // namespace linkage
