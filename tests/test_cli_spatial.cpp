// Spatial machines' bad input as a user or a script meets it (issue 27): linkage-cli refuses the
// file with exit status 2 and one line naming the place (`joints[5].slot: ...`,
// `planes.rocker.y_axis: ...`), and writes nothing on standard output: nothing half-loaded.
// Each file is an example (overedge-machine, lockstitch-bevel) with one thing wrong.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cli_harness.h"
#include "linkage/io/numbers.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::CliResult;

class SpatialCli : public test::CliTest {
 protected:
  using Edits = std::vector<std::pair<std::string, std::string>>;
  // The example's text with each `from` (which must be there, once) replaced by its `to`, saved.
  std::string variant(const std::string& example, const Edits& edits) {
    std::string text =
        test::slurp(std::string(LINKAGE_EXAMPLES_DIR) + "/" + example + ".linkage.json");
    for (const auto& [from, to] : edits) {
      const size_t at = text.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
      if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    return writeFile("bad.linkage.json", text);
  }
  // Each command refuses the file alike.
  void expectRefused(const std::string& path, const std::string& why) {
    for (const char* command : {"analyze", "info"}) {
      const CliResult r = run(std::string(command) + " '" + path + "'");
      EXPECT_EQ(r.exit, 2) << command << ": " << r.err;
      EXPECT_EQ(r.err, "linkage-cli: " + path + ": " + why + "\n") << command;
      EXPECT_EQ(r.out, "") << command;
    }
  }
};

TEST_F(SpatialCli, TheExamplesAreRead) {
  for (const char* name : {"overedge-machine", "lockstitch-bevel"}) {
    const CliResult r = run(std::string("analyze ") + name + " --steps 4");
    EXPECT_EQ(r.exit, 0) << name << ": " << r.err;
    EXPECT_EQ(r.lines().size(), 6u) << name;
    EXPECT_EQ(r.err, "") << name;
  }
}

// dynamics on a machine in space: the world's shaking force and moment, each bearing's load out
// of its plane, the rod's tension (the RSSR's rocker alone has a mass: its inertia about its own
// axis, so the rod's pull is all the rocker's bearing takes in the rocker's plane and out of it);
// what it leaves out said on standard error.
TEST_F(SpatialCli, DynamicsInSpaceGivesTheRodsTensionAndTheBearingsLoadsOutOfTheirPlanes) {
  const std::string rssr = variant("rssr-crank-rocker", {{R"("plane": "rocker",
      "number": 3,)",
                                                          R"("plane": "rocker",
      "number": 3, "mass": {"kg": 0.3, "com": [0, 0], "j_kg_mm2": 2500},)"}});
  CliResult r = run("dynamics '" + rssr + "' --steps 8");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines[0],
            "t_s,crank_deg,driver_torque_Nm,shaking_fx_N,shaking_fy_N,shaking_fz_N,shaking_mx_Nm,"
            "shaking_my_Nm,shaking_mz_Nm,pin:ground.O.fx_N,pin:ground.O.fy_N,pin:ground.O.fn_N,"
            "pin:ground.O.mx_Nm,pin:ground.O.my_Nm,pin:ground.H.fx_N,pin:ground.H.fy_N,"
            "pin:ground.H.fn_N,pin:ground.H.mx_Nm,pin:ground.H.my_Nm,ball-rod:crank.A.axial_N");
  for (size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> v;
    for (size_t at = 0; at != std::string::npos;) {
      const size_t comma = lines[i].find(',', at);
      v.push_back(std::stod(lines[i].substr(at, comma - at)));
      at = comma == std::string::npos ? comma : comma + 1;
    }
    ASSERT_EQ(v.size(), 20u) << lines[i];
    // The rocker's centre of mass is still: the shaking force is nil, and the rocker's bearing
    // carries the rod's pull, its size the tension.
    EXPECT_NEAR(std::hypot(v[3], v[4], v[5]), 0, 1e-9 * std::abs(v[19]) + 1e-12) << lines[i];
    EXPECT_NEAR(std::hypot(v[14], v[15], v[16]), std::abs(v[19]), 1e-9 * std::abs(v[19]))
        << lines[i];
  }
  r = run("dynamics lockstitch-bevel --steps 4");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.err.find("note: the bevel pair joints[5] (gear armshaft.O - vshaft.V) transmits "
                       "the couple about each axis (its m_Nm column); its tooth forces' other "
                       "components (radial, axial) are left out"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.lines()[0].find(",gear:armshaft.O.fx_N,gear:armshaft.O.fy_N,gear:armshaft.O.m_Nm,"),
            std::string::npos);
  // The rocker's centre of mass on its axis: nothing shakes, nothing to balance.
  r = run("balance '" + rssr + "' --counterweight crank --minimize force");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.out.find("counterweight,crank,0,0\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("peak_before,,0,"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("note: the shaking force is nil over the whole cycle: nothing to balance, "
                       "no counterweight placed"),
            std::string::npos)
      << r.err;
}

// balance on a machine in space (tests/test_spatial_balance.cpp has the hand derivations): two
// cranks on crossed shafts, the counterweight on the first, in the drawing plane, leaves the
// second's force along z, K = m2 r2 w^2 = 0.2 kg x 15 mm x (20 pi / s)^2: the note names the
// normal and gives K; with a counterweight on each, the planes span space.
TEST_F(SpatialCli, BalanceInSpaceSaysWhatItLeavesOut) {
  const std::string path =
      "'" + writeFile("crossed.linkage.json", test::crossed_cranks::text()) + "'";
  const double w = 20 * M_PI, K = 0.2 * 15 * w * w / 1000;
  CliResult r = run("balance " + path + " --counterweight one --minimize force");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.err.find("note: every counterweight turns in a plane of normal (0, 0, 1) (world): "
                       "the shaking force along it is beyond their reach (only their weight "
                       "adds to it): its peak " +
                       formatShown(K) + " N at crank "),
            std::string::npos)
      << r.err << K;
  EXPECT_NE(r.err.find("(before: " + formatShown(K) + " N)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("note: peak " + formatShown(K) + " N"), std::string::npos) << r.err;
  r = run("balance " + path + " --counterweight one --counterweight two --minimize fz");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.err.find("note: peak 0 N (cancelled over the whole cycle)"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("note: the counterweights' planes are not all parallel: every direction "
                       "of the shaking force is within their reach"),
            std::string::npos)
      << r.err;
  r = run("balance slider-crank-22a-masses --counterweight crank --minimize fz");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("fz is the shaking force along the drawing's normal"), std::string::npos)
      << r.err;
}

TEST_F(SpatialCli, APinOrASliderAcrossPlanesIsRefusedNamingTheJoint) {
  expectRefused(variant("overedge-machine", {{R"("type": "ball-rod",
      "a": "main.A1")",
                                              R"("type": "pin",
      "a": "main.A1")"}}),
                "joints[2].b: a pin joins bodies of parallel planes only: \"main\" moves in "
                "plane \"main\", \"needlerock\" in \"rocker\" (a ball rod joins any planes)");
  // The needle bar's block in a slot of the vertical shaft, whose plane is across the needle's.
  expectRefused(
      variant("lockstitch-bevel", {{R"("plane": "vertical",
      "number": 5,)",
                                    R"("plane": "vertical",
      "number": 5,
      "slots": {"s": [[0, 0], [10, 0]]},)"},
                                   {R"("slot": "ground.needle")", R"("slot": "vshaft.s")"}}),
      "joints[3].slot: a slider joins bodies of parallel planes only: \"needlebar\" "
      "moves in plane \"needle\", \"vshaft\" in \"vertical\" (a ball rod joins any "
      "planes)");
}

TEST_F(SpatialCli, AGroundSlotAcrossItsBlocksPlaneIsRefusedNamingIt) {
  const std::string why =
      "joints[3].slot: the ground's slot ground.needle is not parallel to "
      "plane \"needle\" of its block (to 1e-9)";
  expectRefused(
      variant("lockstitch-bevel", {{"[[0, -20, 0], [0, -170, 0]]", "[[0, -20], [10, -170]]"}}),
      why);
  expectRefused(variant("lockstitch-bevel",
                        {{"[[0, -20, 0], [0, -170, 0]]", "[[0, -20, 0], [1e-6, -170, 0]]"}}),
                why);
  expectRefused(variant("overedge-machine", {{"[70, 97.6798058619024, 69.12924513957095]",
                                              "[70, 97.6798058619024, 69.1300]"}}),
                "joints[5].slot: the ground's slot ground.u is not parallel to plane \"rocker\" of "
                "its block (to 1e-9)");
}

TEST_F(SpatialCli, BadAxesAnUnknownPlaneAndBadRodsAreRefusedNamingThePlace) {
  expectRefused(variant("overedge-machine", {{"0.39073112848927377]", "0.390731138]"}}),
                "planes.rocker.y_axis: not a unit vector (to 1e-9)");
  expectRefused(variant("overedge-machine", {{R"("x_axis": [1, 0, 0],
      "y_axis": [0, -0.92)",
                                              R"("x_axis": [1, 0, 5e-9],
      "y_axis": [0, -0.92)"}}),
                "planes.rocker.y_axis: not perpendicular to x_axis (to 1e-9)");
  expectRefused(variant("overedge-machine", {{R"("name": "needlelink",
      "plane": "rocker")",
                                              R"("name": "needlelink",
      "plane": "rocket")"}}),
                "bodies[3].plane: no plane \"rocket\"");
  expectRefused(variant("overedge-machine", {{R"("b": "upper.E")", R"("b": "main.A1")"}}),
                "joints[7]: both sides are on body \"main\"");
  // The upper gripper's rod from the crank pin D to a point drawn on it: no length.
  expectRefused(variant("overedge-machine", {{R"("V": [70, 105, -14])", R"("V": [70, 105, -14],
        "Z": [0, 65, 6])"},
                                             {R"("b": "upper.E")", R"("b": "upper.Z")"}}),
                "joints[7].b: the ends are closer than 1e-9 mm: a rod of no length keeps nothing");
  expectRefused(variant("lockstitch-bevel", {{R"("b": "hook.L",
      "ratio": 2)",
                                              R"("b": "hook.L",
      "ratio": 2,
      "carrier": "rod")"}}),
                "joints[7].carrier: a bevel pair (bodies of planes that are not parallel) turns "
                "about the ground only, and a carrier joins bodies of its own plane");
}

// limits --output: a world coordinate of a machine in space (the vertical shaft's point M is at
// z = -12 sin phi: test_spatial_timing.cpp), and an output that is not one, exit 2 naming it.
TEST_F(SpatialCli, LimitsOfAWorldCoordinate) {
  const CliResult r = run("limits lockstitch-bevel --output vshaft.M:z");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> rows = r.lines();
  ASSERT_EQ(rows.size(), 4u) << r.out;
  EXPECT_EQ(rows[0], "event,crank_deg,value");
  EXPECT_EQ(rows[1].substr(0, 7), "min,90,");
  EXPECT_EQ(rows[2].substr(0, 8), "max,270,");
  EXPECT_EQ(rows[3], "stroke,,24");
  const CliResult bad = run("limits lockstitch-bevel --output vshaft.M:w");
  EXPECT_EQ(bad.exit, 2);
  EXPECT_EQ(bad.err.substr(0, 46), "linkage-cli: --output vshaft.M:w: \"w\" after \"v");
  // --direction with a DZ: the same extremes as the output along it (any length); a DZ on a
  // planar machine, or a direction of zeros, refused.
  const CliResult along = run("limits lockstitch-bevel --point vshaft.M --direction 0,0,-3");
  ASSERT_EQ(along.exit, 0) << along.err;
  EXPECT_EQ(along.lines().back(), "stroke,,24");
  const CliResult same = run("limits lockstitch-bevel --output vshaft.M:0,0,-1");
  ASSERT_EQ(same.exit, 0) << same.err;
  EXPECT_EQ(along.out, same.out);
  const CliResult planar = run("limits four-bar-crank-rocker --point coupler.P --direction 0,1,1");
  EXPECT_EQ(planar.exit, 2);
  EXPECT_NE(planar.err.find("a DZ is of a machine in space"), std::string::npos) << planar.err;
  const CliResult zeros = run("limits lockstitch-bevel --point vshaft.M --direction 0,0,0");
  EXPECT_EQ(zeros.exit, 2);
  EXPECT_NE(zeros.err.find("must not be 0,0,0"), std::string::npos) << zeros.err;
  const CliResult word = run("limits lockstitch-bevel --point vshaft.M --direction 0,0,up");
  EXPECT_EQ(word.exit, 2);
  EXPECT_NE(word.err.find("\"up\" is not a number"), std::string::npos) << word.err;
}

}  // namespace
}  // namespace linkage
#endif
