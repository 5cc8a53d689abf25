// The design-check commands as a user and a script see them: limits, transmission and study;
// exact headers, the library's numbers, exit statuses and messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
#include "linkage/kinematics.h"
#include "linkage/limits.h"
#include "linkage/transmission.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using test::CliResult;

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> v;
  std::istringstream s(text);
  for (std::string f; std::getline(s, f, sep);) v.push_back(f);
  if (!text.empty() && text.back() == sep) v.push_back("");
  return v;
}

double field(const std::string& text) {
  std::optional<double> v = parseNumber(text);
  EXPECT_TRUE(v.has_value()) << "not a number: '" << text << "'";
  return v.value_or(NAN);
}

using test::example;

struct BadInput {
  std::string args, message;
};

class DesignCli : public test::CliTest {
 protected:
  std::string write(const std::string& name, const Mechanism& m) {
    return "'" + writeFile(name, serializeMechanism(m)) + "'";
  }
  // Each runs to exit status 2, writes nothing on standard output, and says why.
  void expectBadInput(const std::vector<BadInput>& cases) {
    for (const BadInput& c : cases) {
      CliResult r = run(c.args);
      EXPECT_EQ(r.exit, 2) << c.args;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
      EXPECT_TRUE(r.out.empty()) << c.args;
    }
  }
};

TEST_F(DesignCli, LimitsCsvCarriesTheLibrarysExtremes) {
  CliResult r = run("limits wanzer-inversion-2 --point needlebar.G");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 6u) << r.out;
  EXPECT_EQ(lines[0], "event,crank_deg,value");
  const Mechanism m = example("wanzer-inversion-2");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const Limits lim = findLimits(k, LimitMeasure::along(*m.findPoint("needlebar.G"), {0, 1}));
  ASSERT_EQ(lim.extremes.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const std::vector<std::string> f = split(lines[i + 1], ',');
    ASSERT_EQ(f.size(), 3u);
    EXPECT_EQ(f[0], i % 2 ? "max" : "min");
    EXPECT_EQ(field(f[1]), lim.extremes[i].crankDeg);  // 17 digits: the same doubles
    EXPECT_EQ(field(f[2]), lim.extremes[i].value);
  }
  const std::vector<std::string> last = split(lines[5], ',');
  ASSERT_EQ(last.size(), 3u);
  EXPECT_EQ(last[0], "stroke");
  EXPECT_EQ(last[1], "");
  EXPECT_EQ(field(last[2]), lim.stroke);
  // A body's angle, a direction given, and the slot's direction by default.
  r = run("limits four-bar-crank-rocker --body rocker");
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(r.lines().size(), 4u);
  const CliResult along = run("limits slider-crank-22a-lambda-0.5 --point needlebar.B");
  const CliResult down =
      run("limits slider-crank-22a-lambda-0.5 --point needlebar.B --direction 0,-2");
  ASSERT_EQ(along.exit, 0) << along.err;
  ASSERT_EQ(down.exit, 0) << down.err;
  EXPECT_EQ(along.out, "event,crank_deg,value\nmax,0,45\nmin,180,15\nstroke,,30\n");
  EXPECT_EQ(down.out, "event,crank_deg,value\nmin,0,-45\nmax,180,-15\nstroke,,30\n");
}

TEST_F(DesignCli, LimitsBadInputAndALockedCrank) {
  expectBadInput({
      {"limits", "no MODEL given"},
      {"limits four-bar-crank-rocker",
       "give one of --point body.point, --body NAME or --output OUTPUT"},
      {"limits four-bar-crank-rocker --point coupler.P --body rocker", "give one of"},
      {"limits four-bar-crank-rocker --body rocker --direction 0,1", "goes with --point"},
      {"limits four-bar-crank-rocker --point coupler.Q", "no point \"Q\" on body"},
      {"limits four-bar-crank-rocker --body nobody", "--body nobody: no body"},
      {"limits four-bar-crank-rocker --point coupler.P --direction 0,0", "must not be 0,0"},
      {"limits four-bar-crank-rocker --point coupler.P --direction 1", "not two numbers"},
      {"limits four-bar-crank-rocker --point coupler.P --direction 1,x", "not a number"},
      {"limits four-bar-crank-rocker --point coupler.P --steps 3", "from 4 to 1000000"},
      {"limits four-bar-crank-rocker --point coupler.P --steps", "needs a value"},
      {"limits four-bar-crank-rocker --point coupler.P --frob", "unknown option --frob"},
      {"limits nosuchfile --point a.b", "no such file"},
  });
  const test::FourBar locked = test::fourBar(60, 40, 50, 45, 70);
  CliResult r = run("limits " + write("locked.linkage.json", locked.m) + " --point coupler.B");
  EXPECT_EQ(r.exit, 3);
  EXPECT_NE(r.err.find("crank angle"), std::string::npos) << r.err;
  EXPECT_EQ(run("limits --help").exit, 0);
}

TEST_F(DesignCli, TransmissionCsvHeaderRowsAndSummary) {
  CliResult r = run("transmission needle-876-alpha-35 --steps 72");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 74u);
  EXPECT_EQ(lines[0], "crank_deg,mu:coupler.B,mu:link.E,mu:rod.G");
  Kinematics k;
  ASSERT_TRUE(k.load(example("needle-876-alpha-35")).ok());
  TransmissionOptions opt;
  opt.steps = 72;
  const TransmissionSweep s = sweepTransmission(k, opt);
  ASSERT_TRUE(s.status.ok());
  for (size_t i = 0; i < s.crankDeg.size(); ++i) {
    const std::vector<std::string> f = split(lines[i + 1], ',');
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(field(f[0]), s.crankDeg[i]);
    for (size_t j = 0; j < 3; ++j) EXPECT_EQ(field(f[j + 1]), s.values[j][i]);  // 17 digits
  }
  EXPECT_NE(r.err.find("mu:link.E (dyad link-rocker): min 32.6775 at 0, max 78.4892 at 180.107 "
                       "deg of crank; within 30 to 150 degrees\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("mu:rod.G (rod-slider rod in ground.guide): min 71.4959"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("every transmission angle stays within 30 to 150 degrees"),
            std::string::npos);
}

TEST_F(DesignCli, TransmissionOutOfBandIsExitFourWithTheRowsWritten) {
  // mu_2 of the needle mechanism at alpha = 35 falls to 32.68 degrees at crank 0.
  CliResult r = run("transmission needle-876-alpha-35 --steps 36 --band 35,150");
  EXPECT_EQ(r.exit, 4) << r.err;
  EXPECT_EQ(r.lines().size(), 38u);
  EXPECT_NE(r.err.find("mu:link.E (dyad link-rocker): min 32.6775 at 0, max 78.4892 at 180.107 "
                       "deg of crank; below 35 from "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("some transmission angles leave 35 to 150 degrees"), std::string::npos);
  // No joint to check: the crank angles only, and a note.
  r = run("transmission wanzer-inversion-2 --steps 4");
  EXPECT_EQ(r.exit, 0);
  EXPECT_EQ(r.out, "crank_deg\n0\n90\n180\n270\n360\n");
  EXPECT_NE(r.err.find("nothing to check"), std::string::npos);
  // A crank that stops: the rows reached, then the reason, exit 3.
  const test::FourBar locked = test::fourBar(60, 40, 50, 45, 70);
  r = run("transmission " + write("locked.linkage.json", locked.m) + " --steps 36");
  EXPECT_EQ(r.exit, 3);
  EXPECT_GT(r.lines().size(), 2u);
  EXPECT_LT(r.lines().size(), 38u);
  EXPECT_EQ(r.lines()[0], "crank_deg,mu:coupler.B");
  EXPECT_NE(r.err.find("crank angle"), std::string::npos) << r.err;
}

TEST_F(DesignCli, TransmissionBadInput) {
  expectBadInput({
      {"transmission", "no MODEL given"},
      {"transmission four-bar-crank-rocker --band 150,30", "low end must be below"},
      {"transmission four-bar-crank-rocker --band 30", "not two numbers"},
      {"transmission four-bar-crank-rocker --band a,b", "not a number"},
      {"transmission four-bar-crank-rocker --steps 0", "from 4 to 1000000"},
      {"transmission four-bar-crank-rocker --steps 1.5", "not a whole number"},
      {"transmission four-bar-crank-rocker --point x", "unknown option --point"},
      {"transmission four-bar-crank-rocker four-bar-crank-rocker", "more than one MODEL"},
      {"transmission nosuchfile", "no such file"},
  });
  EXPECT_EQ(run("transmission --help").exit, 0);
}

TEST_F(DesignCli, StudyHeaderAndThePapersAdjustment) {
  CliResult r =
      run("study needle-876-alpha-0 --move ground.F --about 43,137.05539931644228 --angle -1 "
          "--from 0 --to 35 --steps 8 --point needlebar.G --body lever --threads 2");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[0],
            "t,turns,lock_deg,needlebar.G.min_mm,needlebar.G.max_mm,needlebar.G.stroke_mm,"
            "needlebar.G.peak_speed_mm_s,needlebar.G.peak_accel_mm_s2,lever.swing_deg,"
            "mu:coupler.B.min_deg,mu:coupler.B.max_deg,mu:link.E.min_deg,mu:link.E.max_deg,"
            "mu:rod.G.min_deg,mu:rod.G.max_deg");
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> f = split(lines[i], ',');
    ASSERT_EQ(f.size(), 15u);
    EXPECT_EQ(field(f[0]), 5.0 * (i - 1));
    EXPECT_EQ(f[1], "1");
    EXPECT_EQ(f[2], "");
    EXPECT_NEAR(field(f[3]), 107.4750004009442, 1e-12);  // the lowest position stays
  }
  // The last row is the alpha = 35 example's limits, to rounding of the moved pivot.
  CliResult lim = run("limits needle-876-alpha-35 --point needlebar.G");
  ASSERT_EQ(lim.exit, 0);
  EXPECT_NEAR(field(split(lines[8], ',')[5]), field(split(lim.lines()[3], ',')[2]), 1e-9);
}

TEST_F(DesignCli, StudyRowsEqualSeparateRunsOfTheMovedModels) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const std::string base = write("base.linkage.json", f.m);
  CliResult r = run("study " + base +
                    " --move ground.O4 --by 1,0.5 --from -2 --to 2 --steps 5 --point coupler.P");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 6u);
  for (size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> row = split(lines[i], ',');
    ASSERT_EQ(row.size(), 10u);
    const double t = field(row[0]);
    EXPECT_EQ(t, -3.0 + i);
    // The moved model: the ground's O4 and the rocker's O4 pinned there, moved by t (1, 0.5).
    Mechanism moved = f.m;
    for (Point& p : moved.points)
      if (p.name == "O4") p.pos += t * Vec2(1, 0.5);
    const std::string file = write("moved" + std::to_string(i) + ".linkage.json", moved);
    CliResult a = run("analyze " + file + " --point coupler.P");
    ASSERT_EQ(a.exit, 0) << a.err;
    double speed = 0, accel = 0, lo = INFINITY, hi = -INFINITY;
    const std::vector<std::string> table = a.lines();
    ASSERT_EQ(table.size(), 362u);
    for (size_t k = 1; k < table.size(); ++k) {
      const std::vector<std::string> c = split(table[k], ',');
      speed = std::max(speed, std::hypot(field(c[4]), field(c[5])));
      accel = std::max(accel, std::hypot(field(c[6]), field(c[7])));
      lo = std::min(lo, field(c[3]));
      hi = std::max(hi, field(c[3]));
    }
    EXPECT_EQ(field(row[6]), speed);  // the same samples, the same doubles
    EXPECT_EQ(field(row[7]), accel);
    // The exact extremes lie beyond the samples' by less than a degree's worth.
    EXPECT_LE(field(row[3]), lo);
    EXPECT_GT(field(row[3]), lo - 1e-2);
    EXPECT_GE(field(row[4]), hi);
    EXPECT_LT(field(row[4]), hi + 1e-2);
    CliResult l = run("limits " + file + " --point coupler.P");
    ASSERT_EQ(l.exit, 0) << l.err;
    EXPECT_EQ(field(row[5]), field(split(l.lines().back(), ',')[2]));
  }
}

TEST_F(DesignCli, StudyReportsWhereTheCrankStops) {
  // The rocker pivot moved up towards B: from some t on, the rocker is the shortest link.
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60);
  CliResult r = run("study " + write("f.linkage.json", f.m) +
                    " --move ground.O4 --by 0,1 --from 0 --to 40 --steps 3 --point coupler.B");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(split(lines[1], ',')[1], "1");
  const std::vector<std::string> last = split(lines[3], ',');
  ASSERT_EQ(last.size(), 10u);
  EXPECT_EQ(last[0], "40");
  EXPECT_EQ(last[1], "0");
  for (size_t k = 3; k < last.size(); ++k) EXPECT_EQ(last[k], "") << k;
  EXPECT_NE(r.err.find("t = 40: "), std::string::npos) << r.err;
  // analyze on the moved model stops at the same place.
  Mechanism moved = f.m;
  for (Point& p : moved.points)
    if (p.name == "O4") p.pos += Vec2(0, 40);
  CliResult a = run("analyze " + write("moved.linkage.json", moved) + " --steps 3600");
  EXPECT_EQ(a.exit, 3);
  const double reached = field(split(a.lines().back(), ',')[1]);
  EXPECT_GE(field(last[2]), reached);
  EXPECT_LT(field(last[2]), reached + 0.1);
}

TEST_F(DesignCli, StudyBadInputAndThreads) {
  const std::string ok =
      "study four-bar-crank-rocker --move ground.O4 --by 1,0 --from 0 --to 1 "
      "--steps 3 --point coupler.P";
  CliResult one = run(ok + " --threads 1"), three = run(ok + " --threads 3");
  ASSERT_EQ(one.exit, 0) << one.err;
  EXPECT_EQ(one.out, three.out);
  const std::string m = "study four-bar-crank-rocker ";
  expectBadInput({
      {"study", "no MODEL given"},
      {m + "--by 1,0 --from 0 --to 1 --steps 3 --point coupler.P", "--move is required"},
      {m + "--move ground.O4 --by 1,0 --to 1 --steps 3 --point coupler.P", "--from is required"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --point coupler.P", "--steps is required"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 3", "--point is required"},
      {m + "--move ground.O4 --from 0 --to 1 --steps 3 --point coupler.P", "either --by"},
      {m + "--move ground.O4 --by 1,0 --about 0,0 --angle 5 --from 0 --to 1 --steps 3 "
           "--point coupler.P",
       "either --by"},
      {m + "--move ground.O4 --about 0,0 --from 0 --to 1 --steps 3 --point coupler.P",
       "--about and --angle go together"},
      {m + "--move ground.Q --by 1,0 --from 0 --to 1 --steps 3 --point coupler.P",
       "no point \"Q\" on body \"ground\""},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 0 --point coupler.P",
       "--steps: must be from 1"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 3 --point coupler.P "
           "--crank-steps 2",
       "--crank-steps: must be from 4"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to x --steps 3 --point coupler.P", "not a number"},
      {m + "--move ground.O4 --by 1 --from 0 --to 1 --steps 3 --point coupler.P",
       "not two numbers"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 3 --point coupler.P "
           "--body nobody",
       "--body nobody: no body"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 3 --point coupler.P "
           "--direction 0,0",
       "must not be 0,0"},
      {m + "--move ground.O4 --by 1,0 --from 0 --to 1 --steps 3 --point coupler.P --frob 1",
       "unknown option --frob"},
  });
  EXPECT_EQ(run("study --help").exit, 0);
}

}  // namespace
}  // namespace linkage
#endif
