// linkage-cli sensitivity as a user and a script see it: the header, a row a dimension a step,
// the numbers those of linkage/sensitivity.h to the last bit, and bad input named (exit 2).
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "examples.h"
#include "linkage/force_sensitivity.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/tables/force_table.h"
#include "linkage/transmission_sensitivity.h"
#include "linkage/window_sensitivity.h"
#include "loaded_rssr.h"
#include "mechanisms.h"

namespace linkage {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, sep);) v.push_back(f);
  return v;
}

class SensitivityCli : public test::CliTest {
 protected:
  std::string save(const Mechanism& m) {
    return "'" + writeFile("m.linkage.json", serializeMechanism(m)) + "'";
  }
};

TEST_F(SensitivityCli, ARowADimensionAStepAsTheLibraryComputesThem) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const test::CliResult res = run("sensitivity " + save(f.m) + " --point coupler.P --steps 8");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  const std::vector<Dimension> dims = dimensions(f.m);
  ASSERT_EQ(dims.size(), 9u);
  ASSERT_EQ(lines.size(), 1 + 8 * dims.size()) << res.out;
  EXPECT_EQ(lines[0], "crank_deg,dimension,dx_mm_per_mm,dy_mm_per_mm");
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims).ok());
  for (int step = 0; step < 8; ++step) {
    ASSERT_TRUE(k.moveTo(45.0 * step).ok());
    ASSERT_TRUE(s.at(k).ok());
    for (size_t d = 0; d < dims.size(); ++d) {
      const std::vector<std::string> row = split(lines[1 + step * dims.size() + d], ',');
      ASSERT_EQ(row.size(), 4u);
      EXPECT_EQ(parseNumber(row[0]), 45.0 * step);
      EXPECT_EQ(row[1], dims[d].name);
      const Vec2 want = s.point(k, f.P, static_cast<int>(d));
      EXPECT_EQ(parseNumber(row[2]), want.x()) << row[1];
      EXPECT_EQ(parseNumber(row[3]), want.y()) << row[1];
    }
  }
}

TEST_F(SensitivityCli, VelocityAndAccelerationColumnsWhenAsked) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const test::CliResult res =
      run("sensitivity " + save(f.m) + " --point coupler.P --steps 2 --acceleration --velocity");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 1 + 2 * 9u) << res.out;
  EXPECT_EQ(lines[0],
            "crank_deg,dimension,dx_mm_per_mm,dy_mm_per_mm,dvx_mm_s_per_mm,dvy_mm_s_per_mm,"
            "dax_mm_s2_per_mm,day_mm_s2_per_mm");
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(f.m)).ok());
  ASSERT_TRUE(k.moveTo(180).ok());
  ASSERT_TRUE(s.at(k).ok());
  const std::vector<std::string> row = split(lines[1 + 9 + 4], ',');  // 180 deg, crank.O2-A
  ASSERT_EQ(row.size(), 8u);
  EXPECT_EQ(row[1], "crank.O2-A");
  EXPECT_EQ(parseNumber(row[4]), s.velocity(k, f.P, 4).x());
  EXPECT_EQ(parseNumber(row[5]), s.velocity(k, f.P, 4).y());
  EXPECT_EQ(parseNumber(row[6]), s.acceleration(k, f.P, 4).x());
  EXPECT_EQ(parseNumber(row[7]), s.acceleration(k, f.P, 4).y());
}

// --stroke: a row a dimension, the slider-crank's closed form (tests/test_stroke_sensitivity.cpp
// derives it): dS/dr = (l + r) / Y1 + (l - r) / Y2 for the block on x = e.
TEST_F(SensitivityCli, TheStrokesDerivativesWhenAsked) {
  const double r = 20, l = 70, e = 12;
  const test::SliderCrank sc = test::sliderCrank(r, l, e, 30);
  const test::CliResult res = run("sensitivity " + save(sc.m) + " --point slider.B --stroke");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 1 + dimensions(sc.m).size()) << res.out;
  EXPECT_EQ(lines[0], "dimension,dstroke_mm_per_mm");
  const double Y1 = std::sqrt((l + r) * (l + r) - e * e), Y2 = std::sqrt((l - r) * (l - r) - e * e);
  bool crank = false;
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> row = split(lines[i], ',');
    ASSERT_EQ(row.size(), 2u);
    if (row[0] != "crank.O-A") continue;
    crank = true;
    EXPECT_NEAR(*parseNumber(row[1]), (l + r) / Y1 + (l - r) / Y2, 1e-9);
  }
  EXPECT_TRUE(crank) << res.out;
  EXPECT_NE(res.err.find("stroke "), std::string::npos) << res.err;
}

// --clearance N: the file's clearance N, the slider-crank's block to a ground point above it
// (tests/test_clearance_sensitivity.cpp derives it): d/dr = -(l + r) / Y1, d/d(Q.y) = 1.
TEST_F(SensitivityCli, TheClosestApproachsDerivativesWhenAsked) {
  const double r = 20, l = 70, e = 12, Y1 = std::sqrt((l + r) * (l + r) - e * e);
  test::SliderCrank sc = test::sliderCrank(r, l, e, 30);
  const PointId Q = sc.m.addPoint(sc.ground, "Q", Vec2(e, 110));
  sc.m.timing.clearances.push_back({sc.B, ClearancePart::of(Q), {}});
  const std::string path = save(sc.m);
  const test::CliResult res = run("sensitivity " + path + " --clearance 0");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0), "dimension,dmin_mm_per_mm");
  int found = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> row = split(lines[i], ',');
    const double want = row[0] == "crank.O-A" ? -(l + r) / Y1 : row[0] == "ground.Q.y" ? 1 : NAN;
    if (std::isnan(want)) continue;
    ++found;
    EXPECT_NEAR(*parseNumber(row[1]), want, 1e-9) << row[0];
  }
  EXPECT_EQ(found, 2) << res.out;
  EXPECT_EQ(run("sensitivity " + path + " --clearance 1").exit, 2);
  EXPECT_EQ(run("sensitivity " + path).exit, 2);
}

// --window NAME: a row a dimension an interval, the library's numbers to the last bit
// (tests/test_window_sensitivity.cpp holds them to the slider-crank's closed form).
TEST_F(SensitivityCli, AWindowsEndsDerivativesWhenAsked) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  sc.m.timing.windows.push_back({"low", LimitMeasure::along(sc.B, Vec2(0, 1)), true, 70});
  const std::string path = save(sc.m);
  const test::CliResult res = run("sensitivity " + path + " --window low");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0), "dimension,interval,dfrom_deg_per_unit,dto_deg_per_unit");
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  const WindowSensitivity w = windowSensitivity(k, "low", dimensions(sc.m));
  ASSERT_EQ(lines.size(), 1 + w.dims.size()) << res.out;
  for (size_t d = 0; d < w.dims.size(); ++d) {
    const std::vector<std::string> row = split(lines[1 + d], ',');
    ASSERT_EQ(row.size(), 4u);
    EXPECT_EQ(row[0], w.dims[d].name);
    EXPECT_EQ(parseNumber(row[2]), w.intervals[0].dFrom[d]);
    EXPECT_EQ(parseNumber(row[3]), w.intervals[0].dTo[d]);
  }
  EXPECT_EQ(run("sensitivity " + path + " --window nope").exit, 2);
}

// --transmission N: a row a dimension a step, the library's numbers to the last bit
// (tests/test_transmission_sensitivity.cpp holds them to the four-bar's law of cosines); the
// angle by its index or its name; every kind of angle answered.
TEST_F(SensitivityCli, ATransmissionAnglesDerivativesWhenAsked) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const std::string path = save(f.m);
  const test::CliResult res = run("sensitivity " + path + " --transmission 0 --steps 4");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0), "crank_deg,dimension,dmu_deg_per_unit");
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(f.m)).ok());
  const TransmissionJoint j = transmissionJoints(f.m).at(0);
  const size_t n = s.dims().size();
  ASSERT_EQ(lines.size(), 1 + 4 * n) << res.out;
  for (int step = 0; step < 4; ++step) {
    ASSERT_TRUE(k.moveTo(90.0 * step).ok());
    ASSERT_TRUE(s.at(k).ok());
    const std::vector<double> want = transmissionAngleDerivatives(k, j, s);
    for (size_t d = 0; d < n; ++d) {
      const std::vector<std::string> row = split(lines[1 + step * n + d], ',');
      ASSERT_EQ(row.size(), 3u);
      EXPECT_EQ(parseNumber(row[0]), 90.0 * step);
      EXPECT_EQ(row[1], s.dims()[d].name);
      EXPECT_EQ(parseNumber(row[2]), want[d]) << row[1];
    }
  }
  EXPECT_EQ(run("sensitivity " + path + " --transmission mu:coupler.B --steps 4").out, res.out);
  EXPECT_EQ(run("sensitivity " + path + " --transmission coupler.B --steps 4").out, res.out);
  test::CliResult bad = run("sensitivity " + path + " --transmission 1");
  EXPECT_EQ(bad.exit, 2);
  EXPECT_NE(bad.err.find("no such transmission angle (the model's: 0 mu:coupler.B)"),
            std::string::npos)
      << bad.err;
  // Every kind: a dyad with an arc slot's centre, a rod on a slider.
  for (const char* model : {"curved-guide", "slider-crank-22a-lambda-0.3"}) {
    const test::CliResult r =
        run(std::string("sensitivity ") + model + " --transmission 0 --steps 2");
    EXPECT_EQ(r.exit, 0) << model << ": " << r.err;
    EXPECT_GT(r.lines().size(), 2u) << model;
  }
}

// On a machine in space each angle in its plane (tests/test_spatial_transmission_sensitivity.cpp
// holds the library to closed forms there): the overedge machine's rod on its ground slot in
// the inclined rocker plane, every dimension in space among the rows, the library's to the bit.
TEST_F(SensitivityCli, ATransmissionAnglesDerivativesOnAMachineInSpace) {
  const Mechanism m = test::example("overedge-machine");
  const test::CliResult res =
      run("sensitivity overedge-machine --transmission mu:needlelink.G --steps 2");
  ASSERT_EQ(res.exit, 0) << res.err;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(m), Sensitivity::Space::World).ok());
  const TransmissionJoint j = transmissionJoints(m).at(0);
  ASSERT_EQ(j.label, "mu:needlelink.G");
  const std::vector<std::string> lines = res.lines();
  const size_t n = s.dims().size();
  ASSERT_EQ(lines.size(), 1 + 2 * n) << res.out;
  for (int step = 0; step < 2; ++step) {
    ASSERT_TRUE(k.moveTo(180.0 * step).ok());
    ASSERT_TRUE(s.at(k).ok());
    const std::vector<double> want = transmissionAngleDerivatives(k, j, s);
    for (size_t d = 0; d < n; ++d) {
      const std::vector<std::string> row = split(lines[1 + step * n + d], ',');
      ASSERT_EQ(row.size(), 3u);
      EXPECT_EQ(row[1], s.dims()[d].name);
      EXPECT_EQ(parseNumber(row[2]), want[d]) << row[1];
    }
  }
  EXPECT_NE(res.out.find(",planes.rocker.origin.z,"), std::string::npos);
}

// The shaking force's derivatives (tests/test_optimize_shaking.cpp holds the library to a
// slider-crank's closed form): the drop feed's rows are the library's to the bit, and moving the
// machine's frame point by point changes what the frame feels as the sum says.
TEST_F(SensitivityCli, TheShakingForcesDerivativesWhenAsked) {
  const test::CliResult res = run("sensitivity drop-feed --shaking --steps 3");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0), "crank_deg,dimension,dfx_N_per_unit,dfy_N_per_unit,dm_Nm_per_unit");
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("drop-feed")).ok());
  k.setAccelerations(true);
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dimensions(k.mechanism())).ok());
  const size_t n = s.dims().size();
  ASSERT_EQ(lines.size(), 1 + 3 * n) << res.out;
  double largest = 0;
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(k.moveTo(120.0 * step).ok());
    ASSERT_TRUE(s.at(k).ok());
    for (size_t d = 0; d < n; ++d) {
      const Vec2 want = shakingForceSensitivity(k, s, static_cast<int>(d));
      const std::vector<std::string> row = split(lines[1 + step * n + d], ',');
      ASSERT_EQ(row.size(), 5u);
      EXPECT_EQ(row[1], s.dims()[d].name);
      EXPECT_EQ(parseNumber(row[2]), want.x()) << row[1];
      EXPECT_EQ(parseNumber(row[3]), want.y()) << row[1];
      EXPECT_EQ(parseNumber(row[4]), shakingMomentSensitivity(k, s, static_cast<int>(d))) << row[1];
      largest = std::max(largest, want.norm());
    }
  }
  EXPECT_GT(largest, 0.1);  // the drop feed's dimensions do move its shaking force
  // A machine in space: in the world, with its z, and the world's moment: the library's
  // (tests/test_spatial_force_sensitivity.cpp holds it to the changed designs).
  const test::CliResult space = run("sensitivity rssr-crank-rocker --shaking --steps 2");
  ASSERT_EQ(space.exit, 0) << space.err;
  const std::vector<std::string> sl = space.lines();
  EXPECT_EQ(sl.at(0),
            "crank_deg,dimension,dfx_N_per_unit,dfy_N_per_unit,dfz_N_per_unit,dmx_Nm_per_unit,"
            "dmy_Nm_per_unit,dmz_Nm_per_unit");
  Kinematics ks;
  ASSERT_TRUE(ks.load(test::example("rssr-crank-rocker")).ok());
  ks.setAccelerations(true);
  Sensitivity ss;
  ASSERT_TRUE(ss.prepare(ks, dimensions(ks.mechanism()), Sensitivity::Space::World).ok());
  const size_t ns = ss.dims().size();
  ASSERT_EQ(sl.size(), 1 + 2 * ns) << space.out;
  for (int step = 0; step < 2; ++step) {
    ASSERT_TRUE(ks.moveTo(*parseNumber(split(sl[1 + step * ns], ',')[0])).ok() && ss.at(ks).ok());
    for (size_t d = 0; d < ns; ++d) {
      const std::vector<std::string> row = split(sl[1 + step * ns + d], ',');
      ASSERT_EQ(row.size(), 8u);
      const Vec3 m = shakingMomentSensitivity3(ks, ss, static_cast<int>(d));
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(*parseNumber(row[5 + c]), m[c], 1e-9 * (1 + m.norm())) << row[1];
    }
  }
}

// A pin's reaction's derivatives (tests/test_force_sensitivity.cpp holds the library to a
// slider-crank's Newton-Euler closed form): the drop feed's rows are the library's to the bit,
// and moving the whole frame (every ground point's x, or y) moves no force, its gear included.
TEST_F(SensitivityCli, APinsReactionsDerivativesWhenAsked) {
  const test::CliResult res = run("sensitivity drop-feed --force pin:ground.L --steps 4");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0), "crank_deg,dimension,dfx_N_per_unit,dfy_N_per_unit");
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("drop-feed")).ok());
  const Mechanism& m = k.mechanism();
  const size_t n = dimensions(m).size();
  ASSERT_EQ(lines.size(), 1 + 4 * n) << res.out;
  for (int step = 0; step < 4; ++step) {
    ASSERT_TRUE(k.moveTo(90.0 * step).ok());
    const JointForceSensitivity f = jointForceSensitivity(k, m.joints[1].id, dimensions(m));
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    Vec2 sum = Vec2::Zero(), size = Vec2::Zero();
    for (size_t d = 0; d < n; ++d) {
      const std::vector<std::string> row = split(lines[1 + step * n + d], ',');
      ASSERT_EQ(row.size(), 4u);
      EXPECT_EQ(row[1], f.dims[d].name);
      EXPECT_EQ(parseNumber(row[2]), f.derivative[d].x()) << row[1];
      EXPECT_EQ(parseNumber(row[3]), f.derivative[d].y()) << row[1];
      const std::string& name = f.dims[d].name;
      if (name.rfind("ground.", 0) == 0 && name.size() > 2) {
        const int axis = name.back() == 'x' ? 0 : 1;
        sum[axis] += f.derivative[d][axis];
        size[axis] += std::abs(f.derivative[d][axis]);
      }
    }
    EXPECT_GT(size.norm(), 0.1);
    EXPECT_NEAR(sum.x(), 0, 1e-12 * size.x()) << step;
    EXPECT_NEAR(sum.y(), 0, 1e-12 * size.y()) << step;
  }
  test::CliResult bad = run("sensitivity drop-feed --force pin:nothing.X");
  EXPECT_EQ(bad.exit, 2);
  EXPECT_NE(bad.err.find("no such joint (the model's: pin:ground.M, pin:ground.L"),
            std::string::npos)
      << bad.err;
}

// Every kind's reaction: a column a column of its kind in `dynamics` (tests/
// test_force_sensitivity*.cpp and test_cam_force_sensitivity.cpp hold the library to closed
// forms), the library's to the bit; moving the whole drop feed (every ground point's x, or y)
// moves neither its gear's tooth force nor its pivots' reactions.
TEST_F(SensitivityCli, EveryKindsReactionDerivativesInItsColumns) {
  const struct {
    const char *model, *joint, *header;
  } cases[] = {
      {"drop-feed", "gear:armshaft.M", "dfx_N_per_unit,dfy_N_per_unit"},
      {"slider-crank-22a-masses", "slider:needlebar.B",
       "dfx_N_per_unit,dfy_N_per_unit,dm_Nm_per_unit"},
      {"cam-translating-roller", "cam:cam.O",
       "dfx_N_per_unit,dfy_N_per_unit,dm_Nm_per_unit,dcontact_N_per_unit"},
      {"overedge-machine", "ball-rod:main.A1", "daxial_N_per_unit"},  // in space
  };
  for (const auto& c : cases) {
    const test::CliResult res =
        run(std::string("sensitivity ") + c.model + " --force " + c.joint + " --steps 3");
    ASSERT_EQ(res.exit, 0) << res.err;
    const std::vector<std::string> lines = res.lines();
    EXPECT_EQ(lines.at(0), std::string("crank_deg,dimension,") + c.header);
    Kinematics k;
    ASSERT_TRUE(k.load(test::example(c.model)).ok());
    const Mechanism& m = k.mechanism();
    const std::vector<Dimension> dims = dimensions(m);
    const Joint* joint = nullptr;
    for (const Joint& j : m.joints)
      if (std::string(kindOf(j).name) + ":" + m.pointLabel(j.a) == c.joint) joint = &j;
    ASSERT_TRUE(joint) << c.joint;
    const auto columns = kindOf(*joint).reactionColumns;
    ASSERT_EQ(lines.size(), 1 + 3 * dims.size()) << res.out;
    for (int step = 0; step < 3; ++step) {
      ASSERT_TRUE(k.moveTo(120.0 * step).ok());
      const JointForceSensitivity f = jointForceSensitivity(k, joint->id, dims);
      ASSERT_TRUE(f.status.ok()) << f.status.message;
      Vec2 sum[2] = {Vec2::Zero(), Vec2::Zero()}, size = Vec2::Zero();
      for (size_t d = 0; d < dims.size(); ++d) {
        const std::vector<std::string> row = split(lines[1 + step * dims.size() + d], ',');
        ASSERT_EQ(row.size(), 2 + columns.size());
        EXPECT_EQ(row[1], dims[d].name);
        for (size_t col = 0; col < columns.size(); ++col)
          EXPECT_EQ(parseNumber(row[2 + col]), reactionValue(f.change[d], columns[col], false))
              << c.joint << " " << row[1] << " " << columns[col];
        const std::string& name = dims[d].name;
        if (name.rfind("ground.", 0) == 0 && name.size() > 2) {
          sum[name.back() == 'x' ? 0 : 1] += f.change[d].force;
          size += f.change[d].force.cwiseAbs();
        }
      }
      if (std::string(c.model) == "drop-feed") {
        EXPECT_GT(size.norm(), 1e-3);
        for (const Vec2& s : sum) EXPECT_LT(s.norm(), 1e-12 * size.norm()) << step;
      }
    }
  }
}

// On a machine in space a bearing's derivatives include what it bears out of its plane (tests/
// test_spatial_force_sensitivity.cpp holds the library to the changed designs): the loaded
// RSSR's crank pin, the library's to the bit.
TEST_F(SensitivityCli, ABearingsOutOfPlaneDerivativesInSpace) {
  const Mechanism m = test::loadedRssr();
  const test::CliResult res = run("sensitivity " + save(m) + " --force pin:ground.O --steps 3");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines.at(0),
            "crank_deg,dimension,dfx_N_per_unit,dfy_N_per_unit,dfn_N_per_unit,dmx_Nm_per_unit,"
            "dmy_Nm_per_unit");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<Dimension> dims = dimensions(m);
  ASSERT_EQ(lines.size(), 1 + 3 * dims.size()) << res.out;
  const char* const columns[] = {"fx_N", "fy_N", "fn_N", "mx_Nm", "my_Nm"};
  double largest = 0;
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(k.moveTo(120.0 * step).ok());
    const JointForceSensitivity f = jointForceSensitivity(k, m.joints[0].id, dims);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    for (size_t d = 0; d < dims.size(); ++d) {
      const std::vector<std::string> row = split(lines[1 + step * dims.size() + d], ',');
      ASSERT_EQ(row.size(), 7u);
      EXPECT_EQ(row[1], dims[d].name);
      for (size_t col = 0; col < 5; ++col)
        EXPECT_EQ(parseNumber(row[2 + col]), reactionValue(f.change[d], columns[col], false))
            << row[1] << " " << columns[col];
      largest =
          std::max({largest, std::abs(f.change[d].normalN), std::abs(f.change[d].tiltNm.x())});
    }
  }
  EXPECT_GT(largest, 1e-3);
}

TEST_F(SensitivityCli, BadInputIsNamed) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const std::string model = save(f.m);
  test::CliResult res = run("sensitivity " + model + " --point coupler.Q");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("no point \"Q\" on body \"coupler\""), std::string::npos) << res.err;
  res = run("sensitivity " + model);
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("--point"), std::string::npos) << res.err;
  res = run("sensitivity " + model + " --point coupler.P --steps 0");
  EXPECT_EQ(res.exit, 2);
  EXPECT_NE(res.err.find("--steps"), std::string::npos) << res.err;
}

// A machine in space: the stroke along the world's +y (as `limits` measures it there), a row a
// dimension, the library's strokeSensitivity to the last bit (tests/test_stroke_sensitivity_space
// checks that against the RSSR's closed form), its rod and plane among the dimensions.
TEST_F(SensitivityCli, AMachineInSpacesStrokeIsAlongTheWorldsY) {
  const test::CliResult res = run("sensitivity rssr-crank-rocker --point rocker.C --stroke");
  ASSERT_EQ(res.exit, 0) << res.err;
  const Mechanism m =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/rssr-crank-rocker.linkage.json")
          .mechanism.value();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const StrokeSensitivity s =
      strokeSensitivity(k, *m.findPoint("rocker.C"), Vec3(0, 1, 0), dimensions(m));
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 1 + s.dims.size()) << res.out;
  EXPECT_EQ(lines[0], "dimension,dstroke_mm_per_mm");
  bool rod = false;
  for (size_t d = 0; d < s.dims.size(); ++d) {
    const std::vector<std::string> row = split(lines[1 + d], ',');
    ASSERT_EQ(row.size(), 2u);
    EXPECT_EQ(row[0], s.dims[d].name);
    EXPECT_EQ(parseNumber(row[1]), s.derivative[d]) << row[0];
    rod = rod || (row[0] == "ball-rod:crank.A.length" && s.derivative[d] != 0);
  }
  EXPECT_TRUE(rod);
  EXPECT_NE(res.err.find("stroke " + formatNumber(s.limits.stroke) + " mm"), std::string::npos)
      << res.err;
}

// --stroke along --direction: the RSSR's rocker point along z and along a direction with every
// component, the library's strokeSensitivity along that unit direction to the last bit (checked
// against the closed form in tests/test_stroke_sensitivity_space.cpp); refused without --stroke,
// for a zero or a word, and out of a planar machine's plane.
TEST_F(SensitivityCli, AStrokeAlongAGivenDirection) {
  const Mechanism m =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/rssr-crank-rocker.linkage.json")
          .mechanism.value();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  for (const auto& [text, u] : {std::pair<std::string, Vec3>{"z", Vec3(0, 0, 1)},
                                {"0.3,-0.5,0.8", Vec3(0.3, -0.5, 0.8).normalized()}}) {
    const test::CliResult res =
        run("sensitivity rssr-crank-rocker --point rocker.C --stroke --direction " + text);
    ASSERT_EQ(res.exit, 0) << res.err;
    const StrokeSensitivity s = strokeSensitivity(k, *m.findPoint("rocker.C"), u, dimensions(m));
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    const std::vector<std::string> lines = res.lines();
    ASSERT_EQ(lines.size(), 1 + s.dims.size()) << res.out;
    double largest = 0;
    for (size_t d = 0; d < s.dims.size(); ++d) {
      const std::vector<std::string> row = split(lines[1 + d], ',');
      ASSERT_EQ(row.size(), 2u);
      EXPECT_EQ(row[0], s.dims[d].name);
      EXPECT_EQ(parseNumber(row[1]), s.derivative[d]) << row[0];
      largest = std::max(largest, std::abs(s.derivative[d]));
    }
    EXPECT_GT(largest, 1e-3);
    EXPECT_NE(res.err.find("stroke " + formatNumber(s.limits.stroke) + " mm"), std::string::npos)
        << res.err;
  }
  const std::string model = "sensitivity rssr-crank-rocker --point rocker.C ";
  for (const auto& [args, said] : {std::pair<std::string, std::string>{
                                       model + "--direction z", "--direction goes with --stroke"},
                                   {model + "--stroke --direction 0,0,0", "expected x, y, z"},
                                   {model + "--stroke --direction up", "expected x, y, z"},
                                   {"sensitivity four-bar-crank-rocker --point coupler.P --stroke "
                                    "--direction 0,1,1",
                                    "out of the plane"}}) {
    const test::CliResult res = run(args);
    EXPECT_EQ(res.exit, 2) << args;
    EXPECT_NE(res.err.find(said), std::string::npos) << res.err;
  }
}

// A machine in space: the point's world x, y, z (and their rates') derivatives, the library's
// point3(), velocity3() and acceleration3() to the last bit, its rods and planes among the
// dimensions.
TEST_F(SensitivityCli, AMachineInSpaceGetsTheDzColumns) {
  const test::CliResult res =
      run("sensitivity rssr-crank-rocker --point rocker.C --steps 4 --velocity --acceleration");
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  EXPECT_EQ(lines[0],
            "crank_deg,dimension,dx_mm_per_mm,dy_mm_per_mm,dz_mm_per_mm,dvx_mm_s_per_mm,"
            "dvy_mm_s_per_mm,dvz_mm_s_per_mm,dax_mm_s2_per_mm,day_mm_s2_per_mm,"
            "daz_mm_s2_per_mm");
  const Mechanism m =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/rssr-crank-rocker.linkage.json")
          .mechanism.value();
  const std::vector<Dimension> dims = dimensions(m);
  ASSERT_EQ(lines.size(), 1 + 4 * dims.size()) << res.out;
  const PointId C = *m.findPoint("rocker.C");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  ASSERT_TRUE(k.moveTo(90).ok());
  ASSERT_TRUE(s.at(k).ok());
  bool rod = false;
  for (size_t d = 0; d < dims.size(); ++d) {
    const std::vector<std::string> row = split(lines[1 + dims.size() + d], ',');
    ASSERT_EQ(row.size(), 11u);
    EXPECT_EQ(row[0], "90");
    EXPECT_EQ(row[1], dims[d].name);
    rod = rod || row[1] == "ball-rod:crank.A.length";
    const int i = static_cast<int>(d);
    const Vec3 want[3] = {s.point3(k, C, i), s.velocity3(k, C, i), s.acceleration3(k, C, i)};
    for (int o = 0; o < 3; ++o)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(parseNumber(row[2 + 3 * o + c]), want[o][c]) << row[1];
  }
  EXPECT_TRUE(rod);
}

}  // namespace
}  // namespace linkage
#endif
