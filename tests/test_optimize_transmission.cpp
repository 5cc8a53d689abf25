// A transmission-angle target (linkage/optimize.h) on the angles that are not a dyad's: a rod's
// on a slider (the offset slider-crank: its rod makes mu = acos(|cross(d, A - P0)| / l) with the
// slot) and a rod's on a block in an arc slot (the angle at B between the rod and the arc's
// radius). The objective's gradient (exact: the angle's derivative at its extreme, the envelope
// theorem) against central differences of the objective itself, and a search that lifts the
// angle's least value over the turn above a limit, the written design swept again
// (linkage/transmission.h).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "linkage/kinematics.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission.h"
#include "mechanisms.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

// The crank O-A (15) drives a block in the arc slot of the curved-guide example (centre
// (-100, 45), radius 100) by a rod of about 45: the angle at B runs from about 70 to 113 degrees.
Mechanism curvedGuide() {
  const Vec2 A0(0, 15), B0(-1.1292513648949634, 59.98582878368345);
  Mechanism m;
  const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod"),
               block = m.addBody("block");
  const SlotId guide = m.addArcSlot(g, "guide", Vec2(-4, 17), Vec2(0, 45), Vec2(-4, 73));
  const JointId drive =
      m.addPin(m.addPoint(g, "O", Vec2(0, 0)), m.addPoint(crank, "O", Vec2(0, 0)));
  m.addPin(m.addPoint(crank, "A", A0), m.addPoint(rod, "A", A0));
  const PointId bB = m.addPoint(block, "B", B0);
  m.addPin(m.addPoint(rod, "B", B0), bB);
  m.addSlider(bB, guide);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  m.outputs = {bB};
  return m;
}

struct Case {
  Mechanism m;
  std::vector<OptVariable> variables;
  double limit;
};

// The slider-crank (r 20, rod 50, offset 12): the rod's least angle acos(32 / 50) = 50.2; the
// curved guide's 70.1 and largest 113: a limit of 60 (78) leaves them outside.
std::vector<Case> cases() {
  return {{test::sliderCrank(20, 50, 12, 30).m,
           {{"rod.A-B", 40, 120},
            {"crank.O-A", 10, 30},
            {"ground.guide.offset", -30, 30},
            {"ground.guide.angle", 60, 120},
            {"ground.O.x", -10, 10}},
           60},
          {curvedGuide(),
           {{"rod.A-B", 30, 120},
            {"crank.O-A", 10, 20},
            {"ground.guide.radius", 60, 300},
            {"ground.guide.centre.x", -300, -50},
            {"ground.guide.centre.y", 0, 90}},
           78}};
}

TEST(OptimizeTransmission, GradientMatchesCentralDifferencesOnASliderAndAnArcSlot) {
  for (const Case& c : cases()) {
    Kinematics base;
    ASSERT_TRUE(base.load(c.m).ok());
    const std::vector<TransmissionJoint> js = transmissionJoints(c.m);
    ASSERT_EQ(js.size(), 1u);
    OptimizeSpec spec;
    spec.variables = c.variables;
    OptTarget mu{OptTarget::Kind::Transmission, c.m.outputs.at(0)};
    mu.limitDeg = c.limit;
    spec.targets = {mu};
    std::vector<double> x;
    for (const OptVariable& v : spec.variables) x.push_back(test::dimensionValue(c.m, v.name));
    const Evaluation e = evaluate(base, spec, x);
    ASSERT_TRUE(e.feasible) << e.why;
    ASSERT_LT(e.measures[0][0], c.limit) << js[0].label;  // the residual is active
    double largest = 0;
    for (size_t i = 0; i < x.size(); ++i) {
      const double fd = test::centralDifference(base, spec, x, i, 1e-6);
      largest = std::max(largest, std::abs(fd));
      EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd)))
          << js[0].label << " " << spec.variables[i].name;
    }
    EXPECT_GT(largest, 1) << js[0].label;
  }
}

TEST(OptimizeTransmission, TheLeastAngleIsLiftedAboveItsLimit) {
  for (const Case& c : cases()) {
    Kinematics base;
    ASSERT_TRUE(base.load(c.m).ok());
    const TransmissionSweep before = sweepTransmission(base);
    ASSERT_TRUE(before.status.ok());
    ASSERT_LT(before.summaries[0].min, c.limit - 5);
    OptimizeSpec spec;
    spec.variables = c.variables;
    OptTarget mu{OptTarget::Kind::Transmission, c.m.outputs.at(0)};
    mu.limitDeg = c.limit;
    spec.targets = {mu};
    spec.starts = 4;
    const OptimizeResult r = optimize(base, spec);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    Kinematics again;
    ASSERT_TRUE(again.load(r.design).ok());
    const TransmissionSweep after = sweepTransmission(again);
    ASSERT_TRUE(after.status.ok()) << after.status.message;
    const std::string label = after.joints.at(0).label;
    std::cout << label << ": least " << before.summaries[0].min << " -> " << after.summaries[0].min
              << ", largest " << before.summaries[0].max << " -> " << after.summaries[0].max << " ("
              << r.foundBest << " of " << r.starts << " starts, " << r.evaluations << " designs)\n";
    for (size_t i = 0; i < c.variables.size(); ++i)
      std::cout << "  " << c.variables[i].name << " " << r.before[i] << " -> " << r.after[i]
                << "\n";
    EXPECT_GE(after.summaries[0].min, c.limit - 1e-6) << label;
    EXPECT_LE(after.summaries[0].max, 180 - c.limit + 1e-6) << label;
    EXPECT_NEAR(r.atAfter.measures[0][0], after.summaries[0].min, 1e-9) << label;
    for (size_t i = 0; i < c.variables.size(); ++i)
      EXPECT_NEAR(test::dimensionValue(r.design, c.variables[i].name), r.after[i], 1e-9) << label;
  }
}

}  // namespace
}  // namespace linkage
