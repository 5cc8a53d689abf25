// Dimensions found for targets on machines in space (linkage/optimize.h, docs/optimize.md "In
// space"): the objective's exact gradient (the world's sensitivities, spatial dimensions among
// the variables) against central differences of the objective on the overedge machine and the
// RSSR, the overedge machine's transmission angles; the RSSR's rocker stroke met by its rod's
// length and the lower gripper's transmission angle lifted above a limit, each checked by
// solving the written design again; the targets whose derivatives in space are not there refused
// by name (paths and strokes along other directions: tests/test_optimize_space_path.cpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/limits.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

OptTarget target(const Mechanism& m, const std::string& text) {
  OptTarget t;
  std::string why;
  EXPECT_TRUE(parseOptTarget(m, text, t, why)) << why;
  return t;
}

// The overedge machine's needle: its stroke (along the world's y) and its world x, y, z at a
// crank angle, and the looper's x, y there; over link lengths, a depth, a ball rod's length, a
// ground point's z and a plane's origin.
TEST(OptimizeSpace, TheOveredgeMachinesGradientMatchesCentralDifferences) {
  const Mechanism m = test::example("overedge-machine");
  OptimizeSpec spec;
  for (const char* v : {"main.O-A1", "needlerock.H-B", "needlerock.C.along", "main.A1.depth",
                        "ground.H.z", "ball-rod:main.A1.length", "planes.rocker.origin.z"})
    spec.variables.push_back({v, -1e3, 1e3});
  spec.targets = {target(m, "stroke:needlearm.N=30"),
                  target(m, "position:needlearm.N@40=10,20,30*0.5"),
                  target(m, "position:needlerock.B@200=0,0")};
  ASSERT_TRUE(spec.targets[1].z.has_value());
  test::checkGradient(m, spec, 0.05);
}

TEST(OptimizeSpace, TheRssrsGradientMatchesCentralDifferences) {
  const Mechanism m = test::example("rssr-crank-rocker");
  OptimizeSpec spec;
  for (const char* v : {"crank.O-A", "rocker.H-C", "crank.A.depth", "rocker.C.depth", "ground.H.z",
                        "ball-rod:crank.A.length", "planes.rocker.origin.z"})
    spec.variables.push_back({v, -1e3, 1e3});
  spec.targets = {target(m, "stroke:rocker.C=1"), target(m, "position:rocker.C@100=1,-20,70")};
  test::checkGradient(m, spec, 0.1);
}

// The overedge machine's transmission angles (two dyads in two planes, the needle's rod on its
// ground slot in the inclined rocker plane) over lengths, depths, a ball rod's length, the
// ground slot's offset and angle, a ground point's z and planes' origins.
TEST(OptimizeSpace, TheOveredgeMachinesTransmissionGradientMatchesCentralDifferences) {
  const Mechanism m = test::example("overedge-machine");
  // The slot's angle and offset apart here (together: AGroundSlotsAngleWithItsOffsetHeld).
  for (const char* slot : {"ground.u.angle", "ground.u.offset"}) {
    OptimizeSpec spec;
    for (const char* v : {"lowerlink.Q-M", "lower.K-M", "upper.E.depth", "ball-rod:main.D.length",
                          "ground.K.z", "planes.gripper.origin.x", slot, "needlelink.C-G",
                          "needlerock.H-B", "feedrod.R3-G6", "ground.B.z", "planes.main.origin.y"})
      spec.variables.push_back({v, -1e3, 1e3});
    spec.targets = {target(m, "transmission:mu:lowerlink.M>=62"),
                    target(m, "transmission:mu:needlelink.G>=88"),
                    target(m, "transmission:mu:feedrod.G6>=75*0.5")};
    test::checkGradient(m, spec, 0.05);
  }
}

// The needle's ground slot's angle and offset varied together: each design turns the slot about
// its first end in its block's plane and gives the offset back its value (setDimensions), so the
// angle's gradient is the turn less that offset's change.
TEST(OptimizeSpace, AGroundSlotsAngleWithItsOffsetHeld) {
  const Mechanism m = test::example("overedge-machine");
  OptimizeSpec spec;
  for (const char* v : {"ground.u.angle", "ground.u.offset", "needlerock.H-B"})
    spec.variables.push_back({v, -1e3, 1e3});
  spec.targets = {target(m, "transmission:mu:needlelink.G>=88"),
                  target(m, "position:needlearm.N@40=10,20,30*0.5")};
  test::checkGradient(m, spec, 0.05);
}

// The lower gripper's transmission angle lifted from 57 to at least 62 degrees by its two
// lengths; the written design's angles measured again.
TEST(OptimizeSpace, TheLowerGrippersTransmissionAngleIsLiftedAboveALimit) {
  const Mechanism m = test::example("overedge-machine");
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"lowerlink.Q-M", 35, 50}, {"lower.K-M", 18, 26}};
  spec.targets = {target(m, "transmission:mu:lowerlink.M>=62")};
  spec.starts = 2;
  const TransmissionSweep before = sweepTransmission(base);
  ASSERT_TRUE(before.status.ok());
  ASSERT_LT(before.summaries[1].min, 58);
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const LoadResult written = parseMechanism(serializeMechanism(r.design));
  ASSERT_TRUE(written.mechanism) << written.error;
  Kinematics k;
  ASSERT_TRUE(k.load(*written.mechanism).ok());
  const TransmissionSweep after = sweepTransmission(k);
  ASSERT_TRUE(after.status.ok()) << after.status.message;
  ASSERT_EQ(after.joints[1].label, "mu:lowerlink.M");
  EXPECT_GE(after.summaries[1].min, 62 - 1e-6);
  EXPECT_LE(after.summaries[1].max, 180 - 62 + 1e-6);
  EXPECT_NEAR(r.atAfter.measures[0][0], after.summaries[1].min, 1e-9);
}

// The rocker's stroke (along the world's y) met by the rod's length alone: the design written
// and read again, solved afresh, has that stroke to 1e-9 mm.
TEST(OptimizeSpace, TheRssrsRockerStrokeIsMetByTheRodsLength) {
  const Mechanism m = test::example("rssr-crank-rocker");
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"ball-rod:crank.A.length", 78, 86}};
  spec.targets = {target(m, "stroke:rocker.C=0.3")};
  spec.starts = 4;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_GT(std::abs(r.after[0] - r.before[0]), 0.5);
  const LoadResult written = parseMechanism(serializeMechanism(r.design));
  ASSERT_TRUE(written.mechanism) << written.error;
  EXPECT_NEAR(test::dimensionValue(*written.mechanism, "ball-rod:crank.A.length"), r.after[0],
              1e-9);
  Kinematics k;
  ASSERT_TRUE(k.load(*written.mechanism).ok());
  const Limits l = findLimits(
      k, LimitMeasure::alongInSpace(*written.mechanism->findPoint("rocker.C"), Vec3(0, 1, 0)));
  ASSERT_TRUE(l.status.ok()) << l.status.message;
  EXPECT_NEAR(l.stroke, 0.3, 1e-9);
}

// The overedge machine's needle rocker has C on its line H->B (measured along and across it): a
// change of H-B keeps C's along and across, as the derivatives take it (dimensions()), where its
// distances from H and B could not meet again (C beyond H: |CB| - |CH| is |HB|).
TEST(OptimizeSpace, ABodysBaseLengthKeepsAPointOnItsLineWhereItIs) {
  Mechanism m = test::example("overedge-machine");
  const double along = test::dimensionValue(m, "needlerock.C.along"),
               across = test::dimensionValue(m, "needlerock.C.across");
  ASSERT_TRUE(setDimension(m, "needlerock.H-B", 25).ok());
  EXPECT_NEAR(test::dimensionValue(m, "needlerock.H-B"), 25, 1e-12);
  EXPECT_NEAR(test::dimensionValue(m, "needlerock.C.along"), along, 1e-12);
  EXPECT_NEAR(test::dimensionValue(m, "needlerock.C.across"), across, 1e-12);
  // And the optimiser moves it: the needle's stroke found by H-B alone.
  Kinematics base;
  ASSERT_TRUE(base.load(test::example("overedge-machine")).ok());
  OptimizeSpec spec;
  spec.variables = {{"needlerock.H-B", 20, 40}};
  spec.targets = {target(base.mechanism(), "stroke:needlearm.N=21")};
  spec.starts = 2;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.atAfter.measures[0][0], 21, 1e-9);
}

// A position's z is a machine in space's (a path's: tests/test_optimize_space_path.cpp).
TEST(OptimizeSpace, APlanarMachinesZIsRefusedByName) {
  const Mechanism planar = test::example("drop-feed");
  Kinematics flat;
  ASSERT_TRUE(flat.load(planar).ok());
  OptimizeSpec withZ;
  withZ.variables = {{dimensions(planar).front().name, -1e3, 1e3}};
  withZ.targets = {target(planar, "position:feedbar.D@0=1,2,3")};
  const OptimizeResult r = optimize(flat, withZ);
  EXPECT_EQ(r.status.code, StatusCode::BadModel);
  EXPECT_NE(r.status.message.find("a position's z is of a machine in space"), std::string::npos)
      << r.status.message;
}

}  // namespace
}  // namespace linkage
