// Counterweights and dimensions varied in one search (issue 29): each design is drawn again at
// crank angle 0, so a counterweight fixed in its body's drawing turns with that body's turn from
// there. The objective's gradient against central differences of the objective itself (every
// design solved and drawn again), for the shaking force, its moment and a machine in space; the
// written design (dimensions set, counterweights added as masses) feels the peak reported.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "examples.h"
#include "linkage/dynamics.h"
#include "linkage/optimize.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

// The four-bar example with masses, inertias and gravity (its rocker turns to and fro).
Mechanism fourBar() {
  Mechanism m = test::example("four-bar-crank-rocker");
  m.body(m.bodyNamed("crank")->id)->mass = Mass{0.1, Vec2(5, 8), 20, ""};
  m.body(m.bodyNamed("coupler")->id)->mass = Mass{0.3, Vec2(40, 40), 200, ""};
  m.body(m.bodyNamed("rocker")->id)->mass = Mass{0.2, Vec2(64, 24), 50, ""};
  m.gravity = Vec2(0, -9.81);
  m.driver->rpm = 300;
  return m;
}

// The RSSR with masses on its crank and rocker and gravity across both planes.
Mechanism rssr() {
  Mechanism m = test::rssrWithMasses();
  m.gravityZ = -3.0;
  return m;
}

OptimizeSpec mixed(const std::vector<std::pair<std::string, double>>& dims, bool moment) {
  OptimizeSpec spec;
  for (const auto& [name, at] : dims) spec.variables.push_back({name, at - 10, at + 10});
  for (const char* body : {"crank", "rocker"})
    for (const char* axis : {".counterweight.x", ".counterweight.y"})
      spec.variables.push_back({std::string(body) + axis, -60, 60});
  OptTarget t;
  t.kind = OptTarget::Kind::Shaking;
  t.moment = moment;
  spec.targets = {t};
  spec.steps = 48;  // the rows' gradients are what is checked (the sanitizers' build is slow)
  return spec;
}

// The gradient at x against central differences; then the search, and the written design.
void check(const Mechanism& m, const OptimizeSpec& spec, const std::vector<double>& x) {
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  test::expectGradientAt(k, spec, x);
  OptimizeSpec run = spec;
  run.starts = 1;
  const OptimizeResult r = optimize(k, run);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  std::printf("  peak %.9g -> %.9g, %d of %d starts\n", r.atBefore.measures[0][0], peak,
              r.foundBest, r.starts);
  EXPECT_LT(peak, r.atBefore.measures[0][0]);
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  Vec3 F, M;
  shaking(after, F, M);
  EXPECT_NEAR(spec.targets[0].moment ? std::abs(M.z()) : F.norm(), peak, 1e-9 * peak);
}

TEST(OptimizeMixed, TheShakingForceOverCounterweightsAndDimensions) {
  check(fourBar(), mixed({{"crank.O2-A", 20}, {"rocker.B-O4", 50}, {"ground.O4.x", 60}}, false),
        {21, 48, 61, 3, -2, 1.5, 4});
}

TEST(OptimizeMixed, TheShakingMomentOverCounterweightsAndDimensions) {
  check(fourBar(), mixed({{"crank.O2-A", 20}, {"rocker.B-O4", 50}, {"ground.O4.x", 60}}, true),
        {21, 48, 61, 3, -2, 1.5, 4});
}

TEST(OptimizeMixed, AMachineInSpace) {
  check(rssr(), mixed({{"rocker.H-C", 28.5}, {"crank.A.depth", 5}}, false), {29, 6, 3, -2, 1.5, 4});
}

// A reaction over counterweights and dimensions (each counterweight's share moving with the
// dimensions: counterweightShareChange): the rocker's bearing of the four-bar and of the RSSR,
// over the rocker's counterweight, the gradient against central differences; then the search, the
// written design bearing the peak reported. In space also the bearing's load out of its plane
// (`part`: its normal force or its tilts).
double partOf(const JointReaction& r, OptTarget::Reaction part) {
  return part == OptTarget::Reaction::Normal ? std::abs(r.normalN)
         : part == OptTarget::Reaction::Tilt ? r.tiltNm.norm()
                                             : r.force.norm();
}
void checkReaction(const Mechanism& m, OptimizeSpec spec, size_t joint, std::vector<double> x,
                   OptTarget::Reaction part = OptTarget::Reaction::InPlane) {
  spec.targets[0].kind = OptTarget::Kind::Force;
  spec.targets[0].index = joint;
  spec.targets[0].reaction = part;
  // The driven crank's counterweight loads its own bearing alone: the rocker's is varied.
  for (size_t i = spec.variables.size(); i-- > 0;)
    if (spec.variables[i].name.starts_with("crank.counterweight")) {
      spec.variables.erase(spec.variables.begin() + static_cast<long>(i));
      x.erase(x.begin() + static_cast<long>(i));
    }
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  test::expectGradientAt(k, spec, x);
  spec.starts = 1;
  const OptimizeResult r = optimize(k, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double peak = r.atAfter.measures[0][0];
  EXPECT_LT(peak, r.atBefore.measures[0][0]);
  Kinematics after;
  ASSERT_TRUE(test::atThePeak(r, after));
  EXPECT_NEAR(partOf(computeForces(after).joints[joint], part), peak, 1e-9 * peak);
}

TEST(OptimizeMixed, AReactionOverCounterweightsAndDimensions) {
  checkReaction(fourBar(),
                mixed({{"crank.O2-A", 20}, {"rocker.B-O4", 50}, {"ground.O4.x", 60}}, false), 3,
                {21, 48, 61, 3, -2, 1.5, 4});
}

TEST(OptimizeMixed, AReactionOverCounterweightsAndDimensionsInSpace) {
  checkReaction(rssr(), mixed({{"rocker.H-C", 28.5}, {"crank.A.depth", 5}}, false), 1,
                {29, 6, 3, -2, 1.5, 4});
}

// The RSSR's rocker bearing's load out of its plane over the rocker's counterweight and two
// dimensions, with gravity along the rocker's normal too (the world's x): the counterweight's
// weight then tilts the bearing from where it turns to.
TEST(OptimizeMixed, ABearingsLoadOutOfItsPlaneOverCounterweightsAndDimensions) {
  Mechanism m = rssr();
  m.gravity = Vec2(2.5, -9.81);
  for (OptTarget::Reaction part : {OptTarget::Reaction::Normal, OptTarget::Reaction::Tilt})
    checkReaction(m, mixed({{"rocker.H-C", 28.5}, {"crank.A.depth", 5}}, false), 1,
                  {29, 6, 3, -2, 1.5, 4}, part);
}

}  // namespace
}  // namespace linkage
