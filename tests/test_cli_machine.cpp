// The machine commands as a user and a script see them: slots, clearance, timing; exact
// headers, numbers against closed forms, exit statuses and the place named in messages.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
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
  EXPECT_NE(r.err.find("two segments or slots"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between hook.K needlebar.N --min x");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--min"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between hook.K hook.K");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("a point's clearance to itself"), std::string::npos) << r.err;
  r = run("clearance " + ex + " --between hook.K needlebar.N --min -1");
  EXPECT_EQ(r.exit, 2);
  EXPECT_NE(r.err.find("--min: must be 0 or more"), std::string::npos) << r.err;
  EXPECT_EQ(run("clearance " + ex).exit, 2);
  EXPECT_EQ(run("clearance --help").exit, 0);
}

// Issue 26: the part is named as the designer sees it (the needle between its point N and the
// bar's pin B), the result says what was measured and where the hook point meets the needle,
// and the help says what the program does beyond a part's ends (the nearer end; it said the
// line went on).
TEST_F(MachineCli, ClearanceToASegmentSaysWhatItMeasuredAndWhereTheyMeet) {
  const CliResult r = run("clearance lockstitch-arm-shaft --between hook.K needlebar.N-B");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[3].substr(0, 10), "closest,20");
  EXPECT_EQ(lines[3].substr(lines[3].size() - 2), ",0");
  EXPECT_EQ(lines[2], "min" + lines[3].substr(7));  // the closest is one of the minima
  EXPECT_NE(r.err.find("from the point hook.K to the segment needlebar.N-B"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("meets the segment needlebar.N-B at crank 206.565 deg, 4.7383 mm from "
                       "needlebar.N"),
            std::string::npos)
      << r.err;
  const CliResult help = run("clearance --help");
  EXPECT_NE(help.out.find("beyond them to the nearer"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("continued beyond"), std::string::npos) << help.out;
  // A block's point in its own guide: the distance is 0 on the guide, and the closest is the
  // minimum where it comes onto it, not crank 0.
  const CliResult along = run("clearance lockstitch-arm-shaft --between needlebar.N ground.needle");
  ASSERT_EQ(along.exit, 0) << along.err;
  ASSERT_EQ(along.lines().size(), 3u) << along.out;
  EXPECT_EQ(along.lines()[2], "closest" + along.lines()[1].substr(3));
  EXPECT_NE(along.err.find("runs along the line of the slot ground.needle: on it (distance 0) "
                           "from crank 281.462 to 78.538 (through 360) deg"),
            std::string::npos)
      << along.err;
}

// Where the offset slider-crank's block height crosses V (closed form, bisected).
std::vector<double> heightCrossings(double r, double l, double e, double theta0, double V) {
  auto g = [&](long double phi) {
    const long double t = (theta0 + phi) * M_PIl / 180, c = e - r * cosl(t);
    return r * sinl(t) + sqrtl(l * l - c * c) - V;
  };
  std::vector<double> out;
  for (int i = 0; i < 3600; ++i) {
    long double a = i / 10.0L, b = (i + 1) / 10.0L;
    if ((g(a) < 0) == (g(b) < 0)) continue;
    const bool up = g(a) < 0;
    for (int k = 0; k < 100; ++k) ((g((a + b) / 2) < 0) == up ? a : b) = (a + b) / 2;
    out.push_back(static_cast<double>((a + b) / 2));
  }
  return out;
}

TEST_F(MachineCli, TimingWindowsWrapAndConflict) {
  const test::SliderCrank s = test::sliderCrank(20, 60, 8, 100);
  const std::vector<double> x60 = heightCrossings(20, 60, 8, 100, 60);
  const std::vector<double> x70 = heightCrossings(20, 60, 8, 100, 70);
  ASSERT_EQ(x60.size(), 2u);
  ASSERT_EQ(x70.size(), 2u);
  const std::string file = save(s.m);
  CliResult r =
      run("timing " + file + " --window 'low=slider.B:y<60' --window 'top=slider.B:y>70'");
  ASSERT_EQ(r.exit, 0) << r.err;
  std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(lines[0], "window,from_deg,to_deg");
  std::vector<std::string> f = split(lines[1], ',');
  EXPECT_EQ(f[0], "low");
  EXPECT_NEAR(field(f[1]), x60[0], 1e-9);
  EXPECT_NEAR(field(f[2]), x60[1], 1e-9);
  f = split(lines[2], ',');  // the top wraps through crank 0
  EXPECT_EQ(f[0], "top");
  EXPECT_NEAR(field(f[1]), x70[1], 1e-9);
  EXPECT_NEAR(field(f[2]), 360 + x70[0], 1e-9);
  // low and y > 55 overlap on the way down and on the way up: exit 4, the rows still written.
  const std::vector<double> x55 = heightCrossings(20, 60, 8, 100, 55);
  r = run("timing " + file +
          " --window 'low=slider.B:y<60' --window 'mid=slider.B:y>55' --conflict low,mid");
  EXPECT_EQ(r.exit, 4) << r.err;
  lines = r.lines();
  ASSERT_EQ(lines.size(), 5u) << r.out;  // low, mid (one interval, wrapping), two overlaps
  f = split(lines[3], ',');
  EXPECT_EQ(f[0], "conflict:low+mid");
  EXPECT_NEAR(field(f[1]), x60[0], 1e-9);
  EXPECT_NEAR(field(f[2]), x55[0], 1e-9);
  f = split(lines[4], ',');
  EXPECT_NEAR(field(f[1]), x55[1], 1e-9);
  EXPECT_NEAR(field(f[2]), x60[1], 1e-9);
}

TEST_F(MachineCli, TimingBadInputNamesThePlace) {
  const std::string ex = "slider-crank-22a-lambda-0.3 ";
  struct Bad {
    std::string args, says;
  };
  for (const Bad& b :
       {Bad{"--window 'n=needlebar.X:y<3'", "--window n=needlebar.X:y<3: no point \"needlebar.X\""},
        Bad{"--window 'n=needlebar.B:y<3mm'", "\"3mm\" after '<' is not a number"},
        Bad{"--window 'n=needlebar.B:w<3'", "\"w\" after \"needlebar.B:\""},
        Bad{"--window 'n=needlebar.B:y'", "no '<' or '>'"},
        Bad{"--window 'needlebar.B:y<3'", "NAME=OUTPUT<VALUE"},
        Bad{"--window 'n=needlebar.B:y<3' --conflict n", "--conflict n: not two window names"},
        Bad{"--window 'n=needlebar.B:y<3' --conflict n,m", "no window named m"},
        Bad{"--window 'n=needlebar.B:y<3' --window 'n=needlebar.B:y>3'", "window n is given twice"},
        Bad{"--window 'n=needlebar.B:y<3' --conflict n,n", "cannot conflict with itself"},
        Bad{"--window 'a\nfake=needlebar.B:y<55'", "NAME=OUTPUT<VALUE"},
        Bad{"--window 'a\"b=needlebar.B:y<55'", "NAME=OUTPUT<VALUE"},
        Bad{"--window 'n=needlebar.B:y<3' --out f.txt", "--out f.txt: the name must end in"},
        Bad{"", "give at least one --window"}}) {
    const CliResult r = run("timing " + ex + b.args);
    EXPECT_EQ(r.exit, 2) << b.args;
    EXPECT_NE(r.err.find(b.says), std::string::npos) << b.args << ": " << r.err;
  }
  EXPECT_EQ(run("timing --help").exit, 0);
}

// Without --window, the windows, conflicts and rows the file keeps (what the editor's Cycle
// dock keeps): the same rows as the same windows typed; --conflict adds to the file's.
TEST_F(MachineCli, TimingOfTheFilesTiming) {
  const test::SliderCrank s = test::sliderCrank(20, 60, 8, 100);
  std::string text = serializeMechanism(s.m);
  text = text.substr(0, text.rfind('}')) +
         R"(, "timing": {"windows": ["low=slider.B:y<60", "mid=slider.B:y>55"],
                         "outputs": ["slider.B:x"]}})";
  const std::string file = "'" + writeFile("t.linkage.json", text) + "'";
  const CliResult kept = run("timing " + file);
  ASSERT_EQ(kept.exit, 0) << kept.err;
  const CliResult typed =
      run("timing " + file + " --window 'low=slider.B:y<60' --window 'mid=slider.B:y>55'");
  ASSERT_EQ(typed.exit, 0) << typed.err;
  EXPECT_EQ(kept.out, typed.out);
  const CliResult conflict = run("timing " + file + " --conflict low,mid");
  EXPECT_EQ(conflict.exit, 4) << conflict.err;
  EXPECT_EQ(conflict.lines().size(), 5u) << conflict.out;
  // A file without windows, and no --window: the message says what to give.
  const CliResult none = run("timing " + save(s.m));
  EXPECT_EQ(none.exit, 2);
  EXPECT_NE(none.err.find("keep windows in the file's \"timing\""), std::string::npos) << none.err;
}

// --out: the figure by linkage-plot when it was built next to linkage-cli (LINKAGE_BUILD_UI),
// with the CSV and the exit status unchanged; else exit 1 saying what is missing.
TEST_F(MachineCli, TimingFigure) {
  const std::filesystem::path plot =
      std::filesystem::path(LINKAGE_CLI).parent_path() / "linkage-plot";
  const std::string fig = (dir_ / "cycle.svg").string();
  const CliResult r =
      run("timing lockstitch-arm-shaft --window 'needle=needlebar.N:y<-170' "
          "--window 'eye=takeup.E:y>78' --conflict needle,eye --out '" +
          fig + "'");
  ASSERT_EQ(r.lines().size(), 3u) << r.out;
  if (!std::filesystem::exists(plot)) {
    EXPECT_EQ(r.exit, 1);
    EXPECT_NE(r.err.find("linkage-plot is not there"), std::string::npos) << r.err;
    return;
  }
  EXPECT_EQ(r.exit, 0) << r.err;
  const std::string svg = test::slurp(fig);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("needlebar.N:y"), std::string::npos);  // a row's name, as text
  // Run as root on a server (no XDG_RUNTIME_DIR): standard error holds what the program says,
  // not Qt's note that it chose a runtime folder (issue 26).
  const CliResult quiet =
      run("timing lockstitch-arm-shaft --window 'needle=needlebar.N:y<-170' "
          "--out '" +
              fig + "'",
          "env -u XDG_RUNTIME_DIR");
  EXPECT_EQ(quiet.exit, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "") << quiet.err;
}

}  // namespace
}  // namespace linkage
#endif
