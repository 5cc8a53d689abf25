// linkage-cli as a user and a script see it: output, exit status, messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

namespace fs = std::filesystem;

using CliRun = test::CliResult;
using test::slurp;

class Cli : public test::CliTest {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return writeFile(name, text);
  }
};

std::vector<double> fields(const std::string& row) {
  std::vector<double> v;
  std::istringstream s(row);
  for (std::string f; std::getline(s, f, ',');) {
    std::optional<double> x = parseNumber(f);
    EXPECT_TRUE(x.has_value()) << "not a number: '" << f << "' in " << row;
    v.push_back(x.value_or(NAN));
  }
  return v;
}

TEST_F(Cli, HelpForEveryCommand) {
  for (const char* a : {"--help", "analyze --help", "info --help", "examples --help"}) {
    CliRun r = run(a);
    EXPECT_EQ(r.exit, 0) << a;
    EXPECT_NE(r.out.find("usage: linkage-cli"), std::string::npos) << a;
  }
  EXPECT_EQ(run("").exit, 2);
  EXPECT_EQ(run("frobnicate").exit, 2);
}

TEST_F(Cli, VersionIsTheProjects) {
  CliRun r = run("--version");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(r.out, "linkage-cli " LINKAGE_VERSION "\n");
  EXPECT_EQ(r.err, "");
  EXPECT_NE(run("--help").out.find("--version"), std::string::npos);
}

TEST_F(Cli, InstalledProgramFindsTheExamplesInstalledWithIt) {
  // An installed layout, <prefix>/bin/linkage-cli and <prefix>/share/linkage/examples, with an
  // example the source tree does not have; the program started through PATH from another
  // directory (argv[0] a bare name), as a user starts it.
  const fs::path prefix = dir_ / "prefix", examples = prefix / "share" / "linkage" / "examples";
  fs::create_directories(prefix / "bin");
  fs::create_directories(examples);
  fs::copy_file(LINKAGE_CLI, prefix / "bin" / "linkage-cli");
  fs::copy_file(fs::path(LINKAGE_EXAMPLES_DIR) / "four-bar-crank-rocker.linkage.json",
                examples / "only-installed.linkage.json");
  fs::create_directories(dir_ / "elsewhere");
  auto runInstalled = [&](const std::string& args) {
    const std::string cmd = "cd '" + (dir_ / "elsewhere").string() + "' && PATH='" +
                            (prefix / "bin").string() + "':/usr/bin:/bin linkage-cli " + args +
                            " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    std::string out;
    char buf[256];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int status = p ? ::pclose(p) : -1;
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, out);
  };
  const auto [listed, names] = runInstalled("examples");
  EXPECT_EQ(listed, 0);
  EXPECT_EQ(names, "only-installed\n");
  const auto [opened, info] = runInstalled("info only-installed");
  EXPECT_EQ(opened, 0) << info;
  EXPECT_NE(info.find("degrees of freedom: 1"), std::string::npos) << info;
}

TEST_F(Cli, ExamplesAreListedAndOpenByName) {
  CliRun r = run("examples");
  EXPECT_EQ(r.exit, 0);
  for (const char* n : {"wanzer-inversion-1", "wanzer-inversion-2", "slider-crank-22a-lambda-0.5",
                        "slider-crank-22a-lambda-0.3", "four-bar-crank-rocker"})
    EXPECT_NE(r.out.find(n), std::string::npos) << n;
  CliRun info = run("info wanzer-inversion-2");
  EXPECT_EQ(info.exit, 0) << info.err;
  EXPECT_NE(info.out.find("degrees of freedom: 1"), std::string::npos) << info.out;
}

TEST_F(Cli, DefaultTableIsTheSpecsFormatAndMatchesTheSolver) {
  CliRun r = run("analyze wanzer-inversion-2");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 362u);  // header + 0..360 by 1 degree, both ends
  EXPECT_EQ(lines[0],
            "t_s,crank_deg,needlebar.G.x_mm,needlebar.G.y_mm,needlebar.G.vx_mm_s,"
            "needlebar.G.vy_mm_s,needlebar.G.ax_mm_s2,needlebar.G.ay_mm_s2");
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
  EXPECT_EQ(r.out.find("inf"), std::string::npos);
  LoadResult m =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/wanzer-inversion-2.linkage.json");
  ASSERT_TRUE(m.mechanism);
  Kinematics k;
  ASSERT_TRUE(k.load(*m.mechanism).ok());
  const PointId G = m.mechanism->outputs[0];
  // Same path as the command (1 degree steps), so the same doubles, bit for bit.
  for (int i = 0; i <= 360; ++i) {
    const std::vector<double> f = fields(lines[i + 1]);
    ASSERT_EQ(f.size(), 8u);
    ASSERT_TRUE(k.moveTo(i).ok());
    EXPECT_EQ(f[1], i);
    EXPECT_DOUBLE_EQ(f[0], i / (6.0 * 240));
    // 17 significant digits: the table carries the solver's doubles exactly.
    EXPECT_EQ(f[3], k.position(G).y());
    EXPECT_EQ(f[5], k.velocity(G).y());
    EXPECT_EQ(f[7], k.acceleration(G).y());
  }
}

TEST_F(Cli, StepsRevsRpmPointsAndOut) {
  CliRun r =
      run("analyze slider-crank-22a-lambda-0.5 --steps 36 --revs 2 --rpm 500 "
          "--point needlebar.B --point crank.A");
  ASSERT_EQ(r.exit, 0) << r.err;
  std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 74u);
  EXPECT_EQ(fields(lines.back())[1], 720);
  EXPECT_EQ(fields(lines[1]).size(), 14u);
  EXPECT_NE(lines[0].find("crank.A.ay_mm_s2"), std::string::npos);
  // Half the file's 1000 rpm: velocities halve, accelerations quarter, t doubles.
  CliRun fast = run("analyze slider-crank-22a-lambda-0.5 --steps 36 --revs 2");
  ASSERT_EQ(fast.lines().size(), 74u);
  const std::vector<double> slow = fields(lines[5]), quick = fields(fast.lines()[5]);
  EXPECT_NEAR(slow[0], 2 * quick[0], 1e-15);
  EXPECT_NEAR(slow[5], quick[5] / 2, 1e-9 * std::abs(quick[5]));
  EXPECT_NEAR(slow[7], quick[7] / 4, 1e-9 * std::abs(quick[7]));

  const std::string out = (dir_ / "table.csv").string();
  CliRun toFile = run("analyze four-bar-crank-rocker --steps 10 --out '" + out + "'");
  EXPECT_EQ(toFile.exit, 0) << toFile.err;
  EXPECT_TRUE(toFile.out.empty());
  const std::string written = slurp(out);
  EXPECT_EQ(std::count(written.begin(), written.end(), '\n'), 12);
}

TEST_F(Cli, OneAngle) {
  CliRun r = run("analyze wanzer-inversion-2 --angle 30");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(fields(lines[1])[1], 30);
  CliRun table = run("analyze wanzer-inversion-2 --steps 12");
  EXPECT_EQ(table.lines()[2], lines[1]);
  EXPECT_EQ(run("analyze wanzer-inversion-2 --angle 30 --steps 12").exit, 2);
}

TEST_F(Cli, BadInputExitsTwoWithTheCauseAndPlace) {
  struct Case {
    std::string args, expect;
  };
  const std::string badJson = write("bad.linkage.json", "{\n  \"format\": \"linkage\",\n  oops\n}");
  const std::vector<Case> cases = {
      {"analyze no-such-model", "no such file, and no example of that name"},
      {"analyze '" + badJson + "'", "line 3"},
      {"analyze wanzer-inversion-2 --point needlebar.Q", "no point \"Q\" on body \"needlebar\""},
      {"analyze wanzer-inversion-2 --point nobody.G", "no body \"nobody\""},
      {"analyze wanzer-inversion-2 --steps 0", "--steps"},
      {"analyze wanzer-inversion-2 --steps ten", "not a whole number"},
      {"analyze wanzer-inversion-2 --steps 3 --revs 0.5", "not a whole number of steps"},
      {"analyze wanzer-inversion-2 --rpm -5", "--rpm"},
      {"analyze wanzer-inversion-2 --rpm 1,5", "not a number"},
      {"analyze wanzer-inversion-2 --bogus", "unknown option --bogus"},
      {"analyze", "no MODEL"},
      {"analyze wanzer-inversion-2 --steps", "needs a value"},
  };
  for (const Case& c : cases) {
    CliRun r = run(c.args);
    EXPECT_EQ(r.exit, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
}

TEST_F(Cli, UnreachableAngleWritesRowsUpToThereThenExitsThree) {
  auto f = test::fourBar(100, 60, 40, 70, 30);  // non-Grashof: locks 52.819 degrees on
  const std::string path = write("nongrashof.linkage.json", serializeMechanism(f.m));
  CliRun r = run("analyze '" + path + "'");
  EXPECT_EQ(r.exit, 3) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 54u);  // header + 0..52
  EXPECT_EQ(fields(lines.back())[1], 52);
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
  EXPECT_NE(r.err.find("cannot reach crank angle 53 deg"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("locks at crank angle 52.81"), std::string::npos) << r.err;
  // The same with --out: the partial table is written, atomically.
  const std::string out = (dir_ / "partial.csv").string();
  EXPECT_EQ(run("analyze '" + path + "' --out '" + out + "'").exit, 3);
  EXPECT_EQ(slurp(out), r.out);
  // And one angle past the limit.
  CliRun one = run("analyze '" + path + "' --angle 60");
  EXPECT_EQ(one.exit, 3);
  EXPECT_EQ(one.lines().size(), 1u);
}

TEST_F(Cli, UndeterminedPointAndNoDriverAreBadInput) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  f.m.driver.reset();
  CliRun noDriver =
      run("analyze '" + write("nodriver.linkage.json", serializeMechanism(f.m)) + "'");
  EXPECT_EQ(noDriver.exit, 2);
  EXPECT_NE(noDriver.err.find("no driver"), std::string::npos) << noDriver.err;
}

TEST_F(Cli, HandDrawnSketchIsAssembledWithANote) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  for (Point& p : f.m.points)
    if (p.body == f.rocker && p.name == "B") p.pos += Vec2(0.2, 0.1);
  CliRun r =
      run("analyze '" + write("sketch.linkage.json", serializeMechanism(f.m)) + "' --steps 4");
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.err.find("note: the drawing does not close exactly"), std::string::npos) << r.err;
}

TEST_F(Cli, OutputIgnoresTheLocale) {
  CliRun c = run("analyze wanzer-inversion-2 --steps 8");
  CliRun de = run("analyze wanzer-inversion-2 --steps 8", "LC_ALL=de_DE.UTF-8 LANG=de_DE.UTF-8");
  EXPECT_EQ(de.exit, 0);
  EXPECT_EQ(c.out, de.out);
}

TEST_F(Cli, InfoClassifiesEveryFourBarLoop) {
  CliRun r = run("info four-bar-crank-rocker");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.out.find("\nfour-bar loop ground-crank-coupler-rocker: frame 60, input 20, coupler "
                       "70, output 50 mm: crank-rocker (s + l = 90 < p + q = 110)\n"),
            std::string::npos)
      << r.out;
  r = run("info needle-876-alpha-0");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_NE(r.out.find("\nfour-bar loop ground-crank-coupler-lever: frame 175.923, input 15, "
                       "coupler 175, output 25 mm: crank-rocker (s + l = 190.923 < p + q = 200)\n"
                       "four-bar loop ground-lever-link-rocker: frame 37.9446, input 17, coupler "
                       "30, output 25 mm: crank-rocker (s + l = 54.9446 < p + q = 55)\n"),
            std::string::npos)
      << r.out;
  // Before the loops: the groups of the structure (seed 001's), as the closed form solves them.
  const std::string groups =
      "assembly: moved up to 0 mm\ngroup 1: crank crank\ngroup 2: RRR coupler lever\n"
      "group 3: RRR link rocker\ngroup 4: RRP rod needlebar\nsolve: in closed form, group by "
      "group\n";
  EXPECT_EQ(r.out.find("four-bar"), r.out.find(groups) + groups.size()) << r.out;
  auto f = test::fourBar(60, 20, 60, 20, 70);  // a parallelogram
  r = run("info '" + write("p.linkage.json", serializeMechanism(f.m)) + "'");
  EXPECT_NE(r.out.find(": change point (s + l = 80 = p + q = 80)\n"), std::string::npos) << r.out;
  f = test::fourBar(60, 40, 50, 45, 70);
  r = run("info '" + write("n.linkage.json", serializeMechanism(f.m)) + "'");
  EXPECT_NE(r.out.find(": double-rocker (non-Grashof) (s + l = 100 > p + q = 95)\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(run("info wanzer-inversion-2").out.find("four-bar"), std::string::npos);
}

}  // namespace
}  // namespace linkage
#endif
