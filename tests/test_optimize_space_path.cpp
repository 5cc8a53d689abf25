// Path targets and strokes along any direction on machines in space (linkage/optimize.h,
// docs/optimize.md "Machines in space"): a path's given points in the world (x,y,z a line, or
// x,y: the world's x, y only), each one's nearest point of the curve over the turn from the
// world's motion, the gradient from the world's sensitivities; a stroke along x, z or any
// direction (`stroke:body.point@z=MM`). The objective's gradient against central differences on
// the RSSR and the overedge machine; a path synthesis in space (the RSSR's rocker point sampled
// at known dimensions, found again from others, checked on the written design solved afresh); a
// stroke along z met and measured again on the written design (and a planar one along x).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/limits.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

OptTarget target(const Mechanism& m, const std::string& text) {
  OptTarget t;
  std::string why;
  EXPECT_TRUE(parseOptTarget(m, text, t, why)) << why;
  return t;
}

// Point `name`'s world place at each crank angle, m solved afresh.
std::vector<Vec3> worldPath(const Mechanism& m, const std::string& name,
                            const std::vector<double>& degs) {
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  std::vector<Vec3> out;
  for (double deg : degs) {
    EXPECT_TRUE(k.moveTo(deg).ok()) << deg;
    out.push_back(k.motionInSpace(*m.findPoint(name)).position);
  }
  return out;
}

// A path file of those points moved by `off` (x,y,z a line, or x,y with `withZ` false).
std::string pathFile(const std::string& name, const std::vector<Vec3>& points, const Vec3& off,
                     bool withZ) {
  const std::string file = ::testing::TempDir() + name;
  std::ofstream out(file);
  out.precision(17);
  out << (withZ ? "x,y,z\n" : "x,y\n");
  for (const Vec3& p : points) {
    const Vec3 q = p + off;
    out << q.x() << "," << q.y();
    if (withZ) out << "," << q.z();
    out << "\n";
  }
  return file;
}

std::vector<double> turn(int n) {
  std::vector<double> degs;
  for (int i = 0; i < n; ++i) degs.push_back(360.0 * i / n + 7);
  return degs;
}

// The RSSR's rocker point: a path in the world (x,y,z) and one in x, y only, each a little off
// the curve, and strokes along z and along a direction with every component; over link lengths,
// depths, the rod, a ground z and a plane's origin.
TEST(OptimizeSpacePath, TheRssrsPathAndStrokeGradientsMatchCentralDifferences) {
  const Mechanism m = test::example("rssr-crank-rocker");
  const std::vector<Vec3> on = worldPath(m, "rocker.C", turn(6));
  OptimizeSpec spec;
  for (const char* v : {"crank.O-A", "rocker.H-C", "crank.A.depth", "rocker.C.depth", "ground.H.z",
                        "ball-rod:crank.A.length", "planes.rocker.origin.z"})
    spec.variables.push_back({v, -1e3, 1e3});
  spec.targets = {
      target(m, "path:rocker.C=" + pathFile("rssr3.csv", on, Vec3(0.3, -0.2, 0.4), true)),
      target(m, "path:rocker.C=" + pathFile("rssr2.csv", on, Vec3(-0.1, 0.25, 0), false) + "*2"),
      target(m, "stroke:rocker.C@z=3"), target(m, "stroke:rocker.C@0.3,-0.5,0.8=2*0.5")};
  ASSERT_EQ(spec.targets[0].pathZ.size(), 6u);
  ASSERT_TRUE(spec.targets[1].pathZ.empty());
  ASSERT_EQ(spec.targets[2].direction, Vec3(0, 0, 1));
  test::checkGradient(m, spec, 0.1);
}

// The overedge machine's needle (a path in the world) and its looper (in x, y), the needle's
// stroke along x; over link lengths, a depth, a ball rod, a ground z and a plane's origin.
TEST(OptimizeSpacePath, TheOveredgeMachinesPathGradientMatchesCentralDifferences) {
  const Mechanism m = test::example("overedge-machine");
  OptimizeSpec spec;
  for (const char* v : {"main.O-A1", "needlerock.H-B", "needlerock.C.along", "main.A1.depth",
                        "ground.H.z", "ball-rod:main.A1.length", "planes.rocker.origin.z"})
    spec.variables.push_back({v, -1e3, 1e3});
  const std::vector<Vec3> needle = worldPath(m, "needlearm.N", turn(5)),
                          rock = worldPath(m, "needlerock.B", turn(4));
  spec.targets = {
      target(m, "path:needlearm.N=" + pathFile("needle3.csv", needle, Vec3(0.2, 0.3, -0.3), true)),
      target(m, "path:needlerock.B=" + pathFile("rock2.csv", rock, Vec3(0.2, -0.2, 0), false)),
      target(m, "stroke:needlearm.N@x=1")};
  test::checkGradient(m, spec, 0.05);
}

// The RSSR's rocker point sampled at 8 crank angles at known dimensions (its arm and the rocker's
// ground pivot's y and z fix its circle in its plane, so the points fix them); the search starts
// from other dimensions and finds them again, the path met to 1e-6 mm; the written design, read and
// solved afresh, places the point on each given point at its crank angle.
TEST(OptimizeSpacePath, ThePathsPointsInTheWorldAreMetFromOtherDimensions) {
  const Mechanism truth = test::example("rssr-crank-rocker");
  const std::vector<double> degs = turn(8);
  const std::vector<Vec3> points = worldPath(truth, "rocker.C", degs);
  const std::vector<std::pair<std::string, double>> known = {
      {"rocker.H-C", test::dimensionValue(truth, "rocker.H-C")},
      {"ground.H.y", test::dimensionValue(truth, "ground.H.y")},
      {"ground.H.z", test::dimensionValue(truth, "ground.H.z")}};
  Mechanism start = truth;
  const Status moved = setDimensions(start, {{"rocker.H-C", known[0].second + 2},
                                             {"ground.H.y", known[1].second - 1.5},
                                             {"ground.H.z", known[2].second + 2.5}});
  ASSERT_TRUE(moved.ok()) << moved.message;
  Kinematics base;
  ASSERT_TRUE(base.load(start).ok());
  OptimizeSpec spec;
  for (const auto& [name, value] : known) spec.variables.push_back({name, value - 4, value + 4});
  spec.targets = {
      target(start, "path:rocker.C=" + pathFile("rssr8.csv", points, Vec3::Zero(), true))};
  spec.starts = 4;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_GT(r.atBefore.measures[0][0], 0.5);
  EXPECT_LT(r.atAfter.measures[0][0], 1e-6);
  EXPECT_LT(r.atAfter.measures[0][1], 1e-6);
  for (size_t i = 0; i < known.size(); ++i)
    EXPECT_NEAR(r.after[i], known[i].second, 1e-5) << known[i].first;
  const LoadResult written = parseMechanism(serializeMechanism(r.design));
  ASSERT_TRUE(written.mechanism) << written.error;
  const std::vector<Vec3> again = worldPath(*written.mechanism, "rocker.C", degs);
  for (size_t i = 0; i < degs.size(); ++i)
    EXPECT_LT((again[i] - points[i]).norm(), 1e-5) << degs[i];
}

// A two-column file on a machine in space is the world's x, y: the curve's points with their z
// moved 5 mm are met in x, y, and not in the world with the z given.
TEST(OptimizeSpacePath, ATwoColumnPathInSpaceIsTheWorldsXAndY) {
  const Mechanism m = test::example("rssr-crank-rocker");
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  const std::vector<Vec3> on = worldPath(m, "rocker.C", turn(5));
  OptimizeSpec spec;
  spec.variables = {{"rocker.H-C", 20, 40}};
  spec.targets = {target(m, "path:rocker.C=" + pathFile("xy.csv", on, Vec3(0, 0, 5), false)),
                  target(m, "path:rocker.C=" + pathFile("xyz.csv", on, Vec3(0, 0, 5), true))};
  const Evaluation e = evaluate(base, spec, {test::dimensionValue(m, "rocker.H-C")});
  ASSERT_TRUE(e.feasible) << e.why;
  EXPECT_LT(e.measures[0][1], 1e-9);
  EXPECT_GT(e.measures[1][0], 1);
}

// The RSSR's rocker point's stroke along the world's z met by the crank's length alone: the
// target is the stroke of the design with an 8.5 mm crank (changed and measured apart); the
// written design, solved afresh, has it along z to 1e-9 mm, and its crank is 8.5 mm.
TEST(OptimizeSpacePath, AStrokeAlongZIsMetAndMeasuredOnTheWrittenDesign) {
  const Mechanism m = test::example("rssr-crank-rocker");
  auto strokeZ = [](const Mechanism& design) {
    Kinematics k;
    EXPECT_TRUE(k.load(design).ok());
    const PointId c = *design.findPoint("rocker.C");
    const Limits l = findLimits(k, LimitMeasure::alongInSpace(c, Vec3(0, 0, 1)));
    EXPECT_TRUE(l.status.ok()) << l.status.message;
    return l.stroke;
  };
  Mechanism changed = m;
  ASSERT_TRUE(setDimension(changed, "crank.O-A", 8.5).ok());
  const double wanted = strokeZ(changed);
  ASSERT_GT(std::abs(wanted - strokeZ(m)), 0.05);
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O-A", 6.5, 9.5}};
  spec.targets = {target(m, "stroke:rocker.C@z=" + formatNumber(wanted))};
  spec.starts = 3;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const LoadResult written = parseMechanism(serializeMechanism(r.design));
  ASSERT_TRUE(written.mechanism) << written.error;
  EXPECT_NEAR(strokeZ(*written.mechanism), wanted, 1e-9);
  EXPECT_NEAR(test::dimensionValue(*written.mechanism, "crank.O-A"), 8.5, 1e-6);
}

// A planar machine's stroke along a direction in its plane: the four-bar's coupler point along
// x met by its crank, the written design's limits along (1, 0) measured again.
TEST(OptimizeSpacePath, APlanarStrokeAlongXIsMet) {
  const Mechanism m = test::example("four-bar-crank-rocker");
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  OptimizeSpec spec;
  spec.variables = {{"crank.O2-A", 10, 30}};
  spec.targets = {target(m, "stroke:coupler.P@x=40")};
  spec.starts = 2;
  const OptimizeResult r = optimize(base, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  Kinematics k;
  ASSERT_TRUE(k.load(r.design).ok());
  const Limits l = findLimits(k, LimitMeasure::along(*r.design.findPoint("coupler.P"), Vec2(1, 0)));
  ASSERT_TRUE(l.status.ok()) << l.status.message;
  EXPECT_GT(std::abs(r.atBefore.measures[0][0] - 40), 1);
  EXPECT_NEAR(l.stroke, 40, 1e-9);
}

// The direction's text: the axes, three numbers, two (z 0); not 0, not a word; named back in
// the output; a planar machine's stroke out of its plane, a path's z on a planar machine and a
// file mixing two and three columns said by name.
TEST(OptimizeSpacePath, DirectionsAndPathFilesReadAndRefused) {
  const Mechanism m = test::example("rssr-crank-rocker");
  EXPECT_EQ(parseDirection("x"), Vec3(1, 0, 0));
  EXPECT_EQ(parseDirection("1,2"), Vec3(1, 2, 0));
  EXPECT_EQ(parseDirection("1,-2,3"), Vec3(1, -2, 3));
  EXPECT_FALSE(parseDirection("0,0,0"));
  EXPECT_FALSE(parseDirection("up"));
  EXPECT_FALSE(parseDirection("1e308,1e308,1e308"));
  EXPECT_EQ(optTargetName(m, target(m, "stroke:rocker.C@z=3")), "rocker.C@z");
  EXPECT_EQ(optTargetName(m, target(m, "stroke:rocker.C@1,-2,3=3")), "rocker.C@1,-2,3");
  EXPECT_EQ(optTargetName(m, target(m, "stroke:rocker.C=3")), "rocker.C");
  OptTarget t;
  std::string why;
  EXPECT_FALSE(parseOptTarget(m, "stroke:rocker.C@0,0=3", t, why));
  EXPECT_NE(why.find("expected stroke:body.point@DIR=MM"), std::string::npos) << why;
  const std::string mixed = ::testing::TempDir() + "mixed.csv";
  std::ofstream(mixed) << "x,y,z\n1,2,3\n4,5\n";
  EXPECT_FALSE(parseOptTarget(m, "path:rocker.C=" + mixed, t, why));
  EXPECT_NE(why.find(mixed + ":3: not three numbers x,y,z"), std::string::npos) << why;

  const Mechanism planar = test::example("drop-feed");
  Kinematics flat;
  ASSERT_TRUE(flat.load(planar).ok());
  OptimizeSpec spec;
  spec.variables = {{dimensions(planar).front().name, -1e3, 1e3}};
  const std::string xyz = pathFile("planar3.csv", {Vec3(1, 2, 3)}, Vec3::Zero(), true);
  for (const auto& [text, said] :
       {std::pair<std::string, std::string>{"path:feedbar.D=" + xyz, "a path's z is of a machine"},
        {"stroke:feedbar.D@0,1,1=2", "a stroke's direction out of the plane"}}) {
    spec.targets = {target(planar, text)};
    const OptimizeResult r = optimize(flat, spec);
    EXPECT_EQ(r.status.code, StatusCode::BadModel) << text;
    EXPECT_NE(r.status.message.find(said), std::string::npos) << r.status.message;
  }
}

}  // namespace
}  // namespace linkage
