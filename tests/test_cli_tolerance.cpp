// linkage-cli tolerance as a user and a script see it: the table is linkage/tolerance.h's to the
// last bit, a toggle is said, and bad input is named (exit 2).
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "examples.h"
#include "linkage/cycle_spread.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/tolerance.h"
#include "mechanisms.h"

namespace linkage {
namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, ',');) v.push_back(f);
  if (!text.empty() && text.back() == ',') v.push_back("");
  return v;
}

class ToleranceCli : public test::CliTest {
 protected:
  std::string save(const Mechanism& m) {
    return "'" + writeFile("m.linkage.json", serializeMechanism(m)) + "'";
  }
};

TEST_F(ToleranceCli, TheTableIsTheLibrarysToTheLastBit) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const test::CliResult res =
      run("tolerance " + save(f.m) +
          " --point coupler.P --tol crank.O2-A=0.02 --tol rocker.B-O4=0.05 --play "
          "coupler.B-rocker.B=0.01 --samples 300 --seed 5 --steps 8");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 9u) << res.out;
  EXPECT_EQ(lines[0],
            "crank_deg,x_nominal_mm,y_nominal_mm,x_worst_mm,y_worst_mm,x_rss_mm,y_rss_mm,"
            "x_mc_lo_mm,x_mc_hi_mm,y_mc_lo_mm,y_mc_hi_mm,x_mc_sd_mm,y_mc_sd_mm,first_order");
  ToleranceSpec spec;
  spec.point = f.P;
  spec.tolerances = {{"crank.O2-A", 0.02, false},
                     {"rocker.B-O4", 0.05, false},
                     {"coupler.B-rocker.B", 0.01, true}};
  spec.samples = 300;
  spec.seed = 5;
  spec.steps = 8;
  const ToleranceResult r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok());
  for (int i = 0; i < 8; ++i) {
    const std::vector<std::string> row = split(lines[1 + i]);
    ASSERT_EQ(row.size(), 14u) << lines[1 + i];
    const ToleranceRow& w = r.rows[i];
    const double want[13] = {w.crankDeg, w.nominal.x(), w.nominal.y(), w.worst.x(), w.worst.y(),
                             w.rss.x(),  w.rss.y(),     w.lo.x(),      w.hi.x(),    w.lo.y(),
                             w.hi.y(),   w.sd.x(),      w.sd.y()};
    for (int c = 0; c < 13; ++c) EXPECT_EQ(parseNumber(row[c]), want[c]) << i << " " << c;
    EXPECT_EQ(row[13], "ok");
  }
  EXPECT_NE(res.err.find("300 used"), std::string::npos) << res.err;
  EXPECT_NE(res.err.find("stroke over the samples"), std::string::npos) << res.err;
}

// The crank-rocker 0.5 mm from its Grashof limit (tests/test_tolerance.cpp): the rows at its
// toggle say first order fails, and so does the summary; wider, the failed samples are counted.
TEST_F(ToleranceCli, AToggleIsSaid) {
  const test::FourBar f = test::fourBar(60, 20, 70, 30.5, 60, true, 35, 25);
  const std::string model = save(f.m);
  test::CliResult res = run("tolerance " + model +
                            " --point rocker.B --tol rocker.B-O4=0.45 --tol coupler.A-B=0.04 "
                            "--samples 1000 --seed 7 --steps 72");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 73u);
  EXPECT_EQ(split(lines[1 + 60]).back(), "fails");  // 300 degrees
  EXPECT_EQ(split(lines[1 + 24]).back(), "ok");     // 120 degrees
  EXPECT_NE(res.err.find("first order is not enough at crank angles (deg):"), std::string::npos)
      << res.err;
  res = run("tolerance " + model +
            " --point rocker.B --tol rocker.B-O4=0.8 --tol coupler.A-B=0.04 --samples 200");
  ASSERT_EQ(res.exit, 0) << res.err;
  EXPECT_NE(res.err.find("samples failed (not used)"), std::string::npos) << res.err;
  EXPECT_EQ(res.out.find("nan"), std::string::npos);
}

// --clearance N: a row, the library's spread to the last bit (tests/test_cycle_spread.cpp
// holds it to the slider-crank's closed form).
TEST_F(ToleranceCli, AClosestApproachsSpreadIsTheLibrarys) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  const PointId Q = sc.m.addPoint(sc.ground, "Q", Vec2(12, 110));
  sc.m.timing.clearances.push_back({sc.B, ClearancePart::of(Q), {}});
  const std::string path = save(sc.m);
  const test::CliResult res =
      run("tolerance " + path + " --clearance 0 --tol crank.O-A=0.1 --samples 20 --seed 3");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 2u) << res.out;
  EXPECT_EQ(lines[0], "quantity,nominal,worst,rss,mc_lo,mc_hi,mc_mean,mc_sd");
  ToleranceSpec spec;
  spec.tolerances.push_back({"crank.O-A", 0.1, false});
  spec.samples = 20;
  spec.seed = 3;
  const SpreadResult want = clearanceSpread(sc.m, spec, sc.m.timing.clearances[0]);
  ASSERT_TRUE(want.status.ok());
  const std::vector<std::string> row = split(lines[1]);
  ASSERT_EQ(row.size(), 8u);
  EXPECT_EQ(row[0], "clearance_min_mm");
  const Spread& x = want.values[0];
  const double values[] = {x.nominal, x.worst, x.rss, x.lo, x.hi, x.mean, x.sd};
  for (size_t i = 0; i < 7; ++i) EXPECT_EQ(parseNumber(row[i + 1]), values[i]) << i;
  EXPECT_EQ(run("tolerance " + path + " --clearance 1 --tol crank.O-A=0.1").exit, 2);
  EXPECT_EQ(run("tolerance " + path + " --window none --tol crank.O-A=0.1").exit, 2);
}

std::string dataFile(const std::string& name) {
  std::ifstream in(std::string(LINKAGE_TEST_DATA_DIR) + "/" + name, std::ios::binary);
  std::stringstream read;
  read << in.rdbuf();
  return read.str();
}

// A planar machine's table and notes byte for byte as before machines in space were taken
// (tests/data/tolerance-wanzer-planar.*: written by the linkage-cli of commit 66823d1).
TEST_F(ToleranceCli, APlanarMachinesOutputIsAsBefore) {
  const test::CliResult res =
      run("tolerance wanzer-inversion-2 --point needlebar.G --tol triangle.E-F=0.05 --tol "
          "disk.B.angle=0.2 --tol ground.A.x=0.03 --play triangle.E-slider4.E=0.01 --samples 200 "
          "--seed 3 --steps 24 --threads 2");
  ASSERT_EQ(res.exit, 0) << res.err;
  EXPECT_EQ(res.out, dataFile("tolerance-wanzer-planar.csv"));
  EXPECT_EQ(res.err, dataFile("tolerance-wanzer-planar.err"));
}

// A machine in space: z's columns after y's in each group, the library's numbers to the last
// bit, the stroke said to be of the world's y.
TEST_F(ToleranceCli, AMachineInSpaceHasZColumns) {
  const test::CliResult res =
      run("tolerance rssr-crank-rocker --point rocker.C --tol rocker.C.depth=0.05 --tol "
          "ball-rod:crank.A.length=0.1 --tol planes.rocker.origin.z=0.1 --samples 50 --seed 2 "
          "--steps 8");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 9u) << res.out;
  EXPECT_EQ(lines[0],
            "crank_deg,x_nominal_mm,y_nominal_mm,z_nominal_mm,x_worst_mm,y_worst_mm,z_worst_mm,"
            "x_rss_mm,y_rss_mm,z_rss_mm,x_mc_lo_mm,x_mc_hi_mm,y_mc_lo_mm,y_mc_hi_mm,z_mc_lo_mm,"
            "z_mc_hi_mm,x_mc_sd_mm,y_mc_sd_mm,z_mc_sd_mm,first_order");
  ToleranceSpec spec;
  const Mechanism m = test::example("rssr-crank-rocker");
  spec.point = *m.findPoint("rocker.C");
  spec.tolerances = {{"rocker.C.depth", 0.05, false},
                     {"ball-rod:crank.A.length", 0.1, false},
                     {"planes.rocker.origin.z", 0.1, false}};
  spec.samples = 50;
  spec.seed = 2;
  spec.steps = 8;
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.space);
  for (int i = 0; i < 8; ++i) {
    const std::vector<std::string> row = split(lines[1 + i]);
    ASSERT_EQ(row.size(), 20u) << lines[1 + i];
    const ToleranceRow& w = r.rows[i];
    std::vector<double> want = {w.crankDeg};
    for (const Vec3* v : {&w.nominal, &w.worst, &w.rss})
      for (int c = 0; c < 3; ++c) want.push_back((*v)[c]);
    for (int c = 0; c < 3; ++c) {
      want.push_back(w.lo[c]);
      want.push_back(w.hi[c]);
    }
    for (int c = 0; c < 3; ++c) want.push_back(w.sd[c]);
    for (int c = 0; c < 19; ++c) EXPECT_EQ(parseNumber(row[c]), want[c]) << i << " " << c;
    EXPECT_EQ(row[19], "ok");
  }
  EXPECT_NE(res.err.find("stroke of the world's y"), std::string::npos) << res.err;
  EXPECT_NE(res.err.find("50 used"), std::string::npos) << res.err;
}

TEST_F(ToleranceCli, BadInputIsNamed) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const std::string model = save(f.m);
  test::CliResult res = run("tolerance " + model + " --point coupler.Q --tol crank.O2-A=1");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("no point \"Q\" on body \"coupler\""), std::string::npos) << res.err;
  res = run("tolerance " + model + " --point coupler.P --tol crank.O2-B=1");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("unknown dimension crank.O2-B"), std::string::npos) << res.err;
  res = run("tolerance " + model + " --point coupler.P --tol crank.O2-A");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("DIM=T"), std::string::npos) << res.err;
  res = run("tolerance " + model + " --point coupler.P --play coupler.A-rocker.B=0.1");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("no pin joint coupler.A-rocker.B"), std::string::npos) << res.err;
}

}  // namespace
}  // namespace linkage
#endif
