// The machine commands as a user and a script see them: slots, clearance, timing; exact
// headers, numbers against closed forms, exit statuses and the place named in messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_harness.h"
#include "linkage/io/model_file.h"
#include "linkage/io/numbers.h"
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

class MachineCli : public test::CliTest {
 protected:
  std::string save(const Mechanism& m, const std::string& name = "m.linkage.json") {
    return "'" + writeFile(name, serializeMechanism(m)) + "'";
  }
};

TEST_F(MachineCli, SlotsOfASliderCrankAgainstItsClosedForm) {
  const double r = 20, l = 60, e = 8;
  const test::SliderCrank s = test::sliderCrank(r, l, e, 30);
  const CliResult res = run("slots " + save(s.m));
  ASSERT_EQ(res.exit, 0) << res.err;
  const std::vector<std::string> lines = res.lines();
  ASSERT_EQ(lines.size(), 2u) << res.out;
  EXPECT_EQ(lines[0], "joint,min_mm,max_mm,slot_from_mm,slot_to_mm,inside");
  const std::vector<std::string> f = split(lines[1], ',');
  ASSERT_EQ(f.size(), 6u);
  EXPECT_EQ(f[0], "slider.B");
  EXPECT_NEAR(field(f[1]), std::sqrt((l - r) * (l - r) - e * e), 1e-9 * l);
  EXPECT_NEAR(field(f[2]), std::sqrt((l + r) * (l + r) - e * e), 1e-9 * l);
  EXPECT_EQ(field(f[3]), 0);
  EXPECT_NEAR(field(f[4]), r + l, 1e-12);
  EXPECT_EQ(f[5], "yes");
  const CliResult info = run("info " + save(s.m));
  EXPECT_NE(info.out.find("slot travel: slider.B in ground.guide: "), std::string::npos)
      << info.out;
}

TEST_F(MachineCli, SlotsExitFourWhenABlockLeavesItsSlot) {
  test::SliderCrank s = test::sliderCrank(20, 60, 0, 30);
  s.m.slots.front().p1 = Vec2(0, 70);  // the block rises to 80
  const CliResult res = run("slots " + save(s.m));
  EXPECT_EQ(res.exit, 4) << res.err;
  ASSERT_EQ(res.lines().size(), 2u);
  EXPECT_EQ(split(res.lines()[1], ',')[5], "no");
  EXPECT_NE(res.err.find("10 mm past its end"), std::string::npos) << res.err;
  EXPECT_NE(run("info " + save(s.m)).out.find("(leaves the slot)"), std::string::npos);
}

TEST_F(MachineCli, SlotsBadInput) {
  EXPECT_EQ(run("slots").exit, 2);
  const CliResult r = run("slots slider-crank-22a-lambda-0.3 --steps 2");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--steps"), std::string::npos) << r.err;
  EXPECT_EQ(run("slots slider-crank-22a-lambda-0.3 --bogus").exit, 2);
  EXPECT_EQ(run("slots --help").exit, 0);
}

// Two points on one crank and a belted shaft: the closest approach against the closed form of
// the distance (the same formula as tests/test_clearance.cpp, sampled finely and bisected).
TEST_F(MachineCli, ClearanceOfTwoShaftsAgainstTheClosedForm) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), c1 = m.addBody("main"), c2 = m.addBody("hook");
  const double D = 30, r1 = 12, r2 = 9, a2 = 2.0;
  const PointId g1 = m.addPoint(g, "O1", Vec2(0, 0)), g2 = m.addPoint(g, "O2", Vec2(D, 0));
  const PointId m1 = m.addPoint(c1, "O", Vec2(0, 0)), h2 = m.addPoint(c2, "O", Vec2(D, 0));
  m.addPoint(c1, "P", Vec2(r1, 0));
  m.addPoint(c2, "P", Vec2(D + r2 * std::cos(a2), r2 * std::sin(a2)));
  const JointId drive = m.addPin(g1, m1);
  m.addPin(g2, h2);
  m.addGear(m1, h2, 2);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  auto dist = [&](long double phi) {
    const long double t1 = phi * M_PIl / 180, t2 = a2 + 2 * t1;
    return hypotl(D + r2 * cosl(t2) - r1 * cosl(t1), r2 * sinl(t2) - r1 * sinl(t1));
  };
  // The closest by golden-section search around the best of a fine grid.
  long double best = 0;
  for (int i = 0; i < 36000; ++i)
    if (dist(i / 100.0L) < dist(best)) best = i / 100.0L;
  long double a = best - 0.01L, b = best + 0.01L;
  for (int i = 0; i < 200; ++i) {
    const long double x = a + (b - a) * 0.382L, y = a + (b - a) * 0.618L;
    (dist(x) < dist(y) ? b : a) = (dist(x) < dist(y) ? y : x);
  }
  const double closest = static_cast<double>(dist((a + b) / 2));
  const std::string file = save(m);
  CliResult r = run("clearance " + file + " --between main.P hook.P");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "event,crank_deg,distance_mm");
  for (size_t i = 1; i + 1 < lines.size(); ++i) EXPECT_EQ(split(lines[i], ',')[0], "min");
  const std::vector<std::string> f = split(lines.back(), ',');
  ASSERT_EQ(f[0], "closest");
  EXPECT_NEAR(field(f[2]), closest, 1e-9 * D);
  EXPECT_NEAR(field(f[1]), static_cast<double>((a + b) / 2), 1e-6);  // a flat minimum
  r = run("clearance " + file + " --between main.P hook.P --min " + std::to_string(closest + 0.01));
  EXPECT_EQ(r.exit, 4);
  EXPECT_NE(r.err.find("under --min"), std::string::npos) << r.err;
  EXPECT_EQ(r.lines().size(), lines.size());
  EXPECT_EQ(
      run("clearance " + file + " --between main.P hook.P --min " + std::to_string(closest - 0.01))
          .exit,
      0);
}

TEST_F(MachineCli, ClearanceBadInputNamesTheArgument) {
  const std::string ex = "lockstitch-arm-shaft";
  CliResult r = run("clearance " + ex + " --between hook.X needlebar.N");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--between hook.X"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between hook.K");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--between"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between ground.needle ground.needle");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("two slots"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between hook.K needlebar.N --min x");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--min"), std::string::npos) << r.err;
  EXPECT_EQ(run("clearance " + ex).exit, 2);
  EXPECT_EQ(run("clearance --help").exit, 0);
}

}  // namespace
}  // namespace linkage
#endif
