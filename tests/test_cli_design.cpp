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

}  // namespace
}  // namespace linkage
#endif
