// linkage-cli ics as a user and a script see it: the CSV of the issue, JSON, the velocity chain,
// exit statuses and messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "examples.h"
#include "linkage/instant_centres.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, sep);) v.push_back(f);
  if (!text.empty() && text.back() == sep && sep == ',') v.push_back("");
  return v;
}

using test::CliResult;
using test::slurp;

class InstantCentresCli : public test::CliTest {
 protected:
  std::string write(const std::string& name, const Mechanism& m) {
    return "'" + writeFile(name, serializeMechanism(m)) + "'";
  }
};

using test::example;

double field(const std::string& text) {
  std::optional<double> v = parseNumber(text);
  EXPECT_TRUE(v.has_value()) << "not a number: '" << text << "'";
  return v.value_or(NAN);
}

TEST_F(InstantCentresCli, CsvIsTheIssuesFormatAndCarriesTheLibrarysNumbers) {
  CliResult r = run("ics wanzer-inversion-2 --angle 30");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = split(r.out, '\n');
  ASSERT_EQ(lines.size(), 16u);  // header + 15 pairs
  EXPECT_EQ(lines[0], "crank_deg,i,j,body_i,body_j,x_mm,y_mm,at_infinity,dir_x,dir_y,status");
  Kinematics k;
  ASSERT_TRUE(k.load(example("wanzer-inversion-2")).ok());
  ASSERT_TRUE(k.moveTo(30).ok());  // the command's path, so the same doubles
  const InstantCentres ics = computeInstantCentres(k);
  int atInfinity = 0;
  std::pair<int, int> last{0, 0};
  for (size_t row = 1; row < lines.size(); ++row) {
    const std::vector<std::string> f = split(lines[row], ',');
    ASSERT_EQ(f.size(), 11u) << lines[row];
    EXPECT_EQ(f[0], "30");
    const std::pair<int, int> ij{std::stoi(f[1]), std::stoi(f[2])};
    EXPECT_LT(ij.first, ij.second);
    EXPECT_LT(last, ij) << "rows sorted by (i, j)";
    last = ij;
    const InstantCentre& c = *ics.find(ij.first, ij.second);
    EXPECT_EQ(f[10], toString(c.status));
    EXPECT_TRUE(f[10] == "primary" || f[10] == "kennedy") << lines[row];
    if (f[7] == "1") {
      ++atInfinity;
      EXPECT_TRUE(f[5].empty() && f[6].empty()) << lines[row];
      const double dx = field(f[8]), dy = field(f[9]);
      EXPECT_NEAR(std::hypot(dx, dy), 1, 1e-15);
      EXPECT_EQ(dx, c.h.x());
      EXPECT_EQ(dy, c.h.y());
    } else {
      EXPECT_EQ(f[7], "0");
      EXPECT_TRUE(f[8].empty() && f[9].empty()) << lines[row];
      EXPECT_EQ(field(f[5]), c.h.x());
      EXPECT_EQ(field(f[6]), c.h.y());
    }
  }
  EXPECT_EQ(atInfinity, 4);  // IC(1,6), IC(2,4), IC(2,5) of the sliders, and IC(4,5)
  EXPECT_EQ(lines[1], "30,1,2,ground,disk,0,0,0,,,primary");
  EXPECT_EQ(lines[5], "30,1,6,ground,needlebar,,,1,1,0,primary");
  EXPECT_TRUE(r.err.empty()) << r.err;
  // The same to a file, atomically; nothing on standard output.
  const std::string out = (dir_ / "ics.csv").string();
  CliResult toFile = run("ics wanzer-inversion-2 --angle 30 --out '" + out + "'");
  EXPECT_EQ(toFile.exit, 0) << toFile.err;
  EXPECT_TRUE(toFile.out.empty());
  EXPECT_EQ(slurp(out), r.out);
  // Whatever the locale.
  EXPECT_EQ(run("ics wanzer-inversion-2 --angle 30", "LC_ALL=de_DE.UTF-8 LANG=de_DE.UTF-8").out,
            r.out);
}

TEST_F(InstantCentresCli, JsonHasTheLinesEachCentreWasFoundFrom) {
  CliResult r = run("ics wanzer-inversion-2 --angle 0 --json");
  ASSERT_EQ(r.exit, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["crank_deg"], 0);
  EXPECT_EQ(j["bodies"].size(), 6u);
  EXPECT_EQ(j["bodies"][5]["name"], "needlebar");
  ASSERT_EQ(j["centres"].size(), 15u);
  EXPECT_TRUE(j["disagreements"].empty());
  for (const auto& c : j["centres"]) {
    const std::string status = c["status"];
    EXPECT_TRUE(c["determined"].get<bool>());
    EXPECT_TRUE(c.contains(c["at_infinity"].get<bool>() ? "dir_x" : "x_mm"));
    if (status == "kennedy") {
      ASSERT_EQ(c["lines"].size(), 2u);
      EXPECT_GE(c["round"].get<int>(), 1);
    }
    if (status == "primary") EXPECT_TRUE(c.contains("joint"));
    EXPECT_LE(c["check"]["difference"].get<double>(), c["check"]["tolerance"].get<double>());
  }
  // The homework's "2,4 and 3,4 intersect 2,3; 2,5 and 3,5 intersect 2,3".
  const auto& c23 = j["centres"][5];
  ASSERT_EQ(c23["i"], 2);
  ASSERT_EQ(c23["j"], 3);
  std::set<std::vector<std::vector<int>>> lines;
  for (const auto& l : c23["lines"])
    lines.insert(l["through"].get<std::vector<std::vector<int>>>());
  EXPECT_EQ(lines, (std::set<std::vector<std::vector<int>>>{{{2, 4}, {3, 4}}, {{2, 5}, {3, 5}}}));
}

TEST_F(InstantCentresCli, PointPrintsTheChainWithTheSolversVelocity) {
  CliResult direct = run("ics wanzer-inversion-2 --angle 0 --point needlebar.G");
  ASSERT_EQ(direct.exit, 0) << direct.err;
  for (const char* s :
       {"P = IC(2,6) = (15.2041, 0)", "|IC(1,2) P| = 15.2041 mm",
        "IC(1,6) is at infinity: body 6 translates", "v_P = omega2 x (P - IC(1,2)) = (0, -382.12)",
        "solver:       v = (0, -382.1198801230", "omega2 = -25.1327 rad/s (240 rpm cw)"})
    EXPECT_NE(direct.out.find(s), std::string::npos) << s << "\n" << direct.out;
  const size_t chain = direct.out.find("by the chain: v = (");
  ASSERT_NE(chain, std::string::npos);
  EXPECT_EQ(direct.out.find("-382.119880123", chain),
            direct.out.find(", -382.119880123", chain) + 2);
  CliResult via = run("ics wanzer-inversion-2 --angle 0 --point needlebar.G --via 3");
  ASSERT_EQ(via.exit, 0) << via.err;
  for (const char* s : {"P = IC(2,3)", "IC(1,3) = (-46.6837, -41.2603)",
                        "omega3 = -8.1853 rad/s (cw)", "P = IC(3,6)", "-382.119880123"})
    EXPECT_NE(via.out.find(s), std::string::npos) << s << "\n" << via.out;
  CliResult json = run("ics wanzer-inversion-2 --angle 0 --point needlebar.G --via 3 --json");
  ASSERT_EQ(json.exit, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["steps"].size(), 2u);
  EXPECT_EQ(j["steps"][0]["centre"]["j"], 3);
  EXPECT_EQ(j["steps"][1]["to_motion"]["motion"], "translates");
  EXPECT_NEAR(j["velocity_mm_s"][1].get<double>(), -382.119880123099209519, 1e-9 * 382);
  EXPECT_NEAR(j["solver_velocity_mm_s"][1].get<double>(), -382.119880123099209519, 1e-9 * 382);
  // --rpm scales the chain.
  CliResult slow = run("ics wanzer-inversion-2 --angle 0 --point needlebar.G --rpm 120 --json");
  ASSERT_EQ(slow.exit, 0) << slow.err;
  EXPECT_NEAR(nlohmann::json::parse(slow.out)["velocity_mm_s"][1].get<double>(),
              -382.119880123099209519 / 2, 1e-9 * 382);
}

// The Watt six-bar of test_instant_centres.cpp at the position where Kennedy cannot fix IC(2,6):
// a note says so, the row is marked velocity; IC(3,5) has no centre (no relative motion) and
// leaves all four coordinates empty.
TEST_F(InstantCentresCli, CentresKennedyCannotFixAreMarkedNotInvented) {
  const Mechanism m = test::wattSixBar().m;
  CliResult r = run("ics " + write("watt.linkage.json", m) + " --angle 0");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = split(r.out, '\n');
  ASSERT_EQ(lines.size(), 16u);
  const std::vector<std::string> f = split(lines[9], ',');
  ASSERT_EQ(f.size(), 11u);
  EXPECT_EQ(f[1] + f[2] + f[7] + f[8] + f[9] + f[10], "260velocity");
  EXPECT_NEAR(field(f[5]), -250, 1e-9 * 250);
  EXPECT_NEAR(field(f[6]), 0, 1e-9 * 250);
  EXPECT_EQ(lines[11], "0,3,5,coupler,link,,,0,,,velocity");
  EXPECT_NE(r.err.find("note: IC(2,6) is not determined by Kennedy's theorem here"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("taken from the solved velocities"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST_F(InstantCentresCli, BadInputExitsTwoUnreachableAngleThree) {
  Mechanism ground2 = example("wanzer-inversion-2");
  ground2.bodies[0].number = 2;
  ground2.bodies[1].number = 7;
  const std::string badNumbers = write("numbers.linkage.json", ground2);
  struct Case {
    std::string args, expect;
  };
  const std::vector<Case> cases = {
      {"ics wanzer-inversion-2", "--angle DEG is required"},
      {"ics wanzer-inversion-2 --angle x", "not a number"},
      {"ics wanzer-inversion-2 --angle", "needs a value"},
      {"ics wanzer-inversion-2 --angle 0 --bogus", "unknown option --bogus"},
      {"ics --angle 0", "no MODEL"},
      {"ics no-such-model --angle 0", "no such file"},
      {"ics wanzer-inversion-2 --angle 0 --point needlebar.Q", "no point \"Q\""},
      {"ics wanzer-inversion-2 --angle 0 --point needlebar.G --via 9", "no body numbered 9"},
      {"ics wanzer-inversion-2 --angle 0 --point needlebar.G --via 1", "through the ground"},
      {"ics wanzer-inversion-2 --angle 0 --point needlebar.G --via x", "not a whole number"},
      {"ics wanzer-inversion-2 --angle 0 --via 3", "--via needs --point"},
      {"ics wanzer-inversion-2 --angle 0 --rpm 0", "--rpm"},
      {"ics " + badNumbers + " --angle 0", "is the ground, which is number 1"},
  };
  for (const Case& c : cases) {
    CliResult r = run(c.args);
    EXPECT_EQ(r.exit, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
  auto f = test::fourBar(100, 60, 40, 70, 30);  // non-Grashof: locks 52.819 degrees on
  CliResult r = run("ics " + write("nongrashof.linkage.json", f.m) + " --angle 60");
  EXPECT_EQ(r.exit, 3) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("cannot reach crank angle 60 deg"), std::string::npos) << r.err;
  CliResult help = run("ics --help");
  EXPECT_EQ(help.exit, 0);
  EXPECT_NE(help.out.find("usage: linkage-cli ics MODEL --angle DEG"), std::string::npos);
  EXPECT_NE(run("--help").out.find("ics MODEL"), std::string::npos);
}

// A machine in space: the centres of each plane class in its frame, named in the last column;
// none between the crank (drawing plane) and the rocker (inclined plane); a chain of centres
// that would cross them is refused naming the pair.
TEST_F(InstantCentresCli, AMachineInSpaceHasCentresWithinPlanesAndNoneAcross) {
  CliResult r = run("ics rssr-crank-rocker --angle 40");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 4u) << r.out;  // header + 3 pairs
  EXPECT_EQ(lines[0], "crank_deg,i,j,body_i,body_j,x_mm,y_mm,at_infinity,dir_x,dir_y,status,plane");
  EXPECT_EQ(lines[1], "40,1,2,ground,crank,0,0,0,,,primary,drawing");
  EXPECT_EQ(lines[2], "40,1,3,ground,rocker,0,0,0,,,primary,rocker");
  EXPECT_EQ(lines[3], "40,2,3,crank,rocker,,,0,,,across-planes,");
  EXPECT_EQ(r.err, "");  // no note of a centre Kennedy missed: there is none to find
  CliResult chain = run("ics rssr-crank-rocker --angle 40 --point rocker.C");
  EXPECT_EQ(chain.exit, 2);
  EXPECT_NE(chain.err.find("IC(2,3) does not exist: bodies 2 and 3 move in planes that are not "
                           "parallel"),
            std::string::npos)
      << chain.err;
}

}  // namespace
}  // namespace linkage
#endif
