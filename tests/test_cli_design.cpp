// The design-check commands as a user and a script see them: limits, transmission and study;
// exact headers, the library's numbers, exit statuses and messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
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

Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

class DesignCli : public test::CliTest {
 protected:
  std::string write(const std::string& name, const Mechanism& m) {
    return "'" + writeFile(name, serializeMechanism(m)) + "'";
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
  struct Case {
    std::string args, message;
  };
  for (const Case& c : std::vector<Case>{
           {"limits", "no MODEL given"},
           {"limits four-bar-crank-rocker", "give either --point body.point or --body NAME"},
           {"limits four-bar-crank-rocker --point coupler.P --body rocker", "give either"},
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
       }) {
    CliResult r = run(c.args);
    EXPECT_EQ(r.exit, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
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
  struct Case {
    std::string args, message;
  };
  for (const Case& c : std::vector<Case>{
           {"transmission", "no MODEL given"},
           {"transmission four-bar-crank-rocker --band 150,30", "low end must be below"},
           {"transmission four-bar-crank-rocker --band 30", "not two numbers"},
           {"transmission four-bar-crank-rocker --band a,b", "not a number"},
           {"transmission four-bar-crank-rocker --steps 0", "from 4 to 1000000"},
           {"transmission four-bar-crank-rocker --steps 1.5", "not a whole number"},
           {"transmission four-bar-crank-rocker --point x", "unknown option --point"},
           {"transmission four-bar-crank-rocker four-bar-crank-rocker", "more than one MODEL"},
           {"transmission nosuchfile", "no such file"},
       }) {
    CliResult r = run(c.args);
    EXPECT_EQ(r.exit, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args;
  }
  EXPECT_EQ(run("transmission --help").exit, 0);
}

}  // namespace
}  // namespace linkage
#endif
