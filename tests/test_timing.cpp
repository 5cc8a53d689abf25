// The cycle diagram (linkage/timing.h) against closed forms: an offset slider-crank's block
// height y(theta) = r sin theta + sqrt(l^2 - (e - r cos theta)^2), whose windows y < V and
// y > V end where y = V (bisected in long double from the formula, not the solver) to 1e-9
// degree; a window that wraps through crank angle 0; the overlap of two windows; its dead
// centres and a dwell; the parser's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "examples.h"
#include "linkage/timing.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using LD = long double;

constexpr double R = 20, L = 60, E = 8;

// Sign changes of g over crank angles [0, 360), bisected.
template <class G>
std::vector<double> rootsOf(G g) {
  std::vector<double> out;
  for (int i = 0; i < 3600; ++i) {
    LD a = i / 10.0L, b = (i + 1) / 10.0L;
    if ((g(a) < 0) == (g(b) < 0)) continue;
    const bool up = g(a) < 0;
    for (int k = 0; k < 100; ++k) {
      const LD c = (a + b) / 2;
      ((g(c) < 0) == up ? a : b) = c;
    }
    out.push_back(static_cast<double>((a + b) / 2));
  }
  return out;
}

// Crank angles in [0, 360) of the drawn crank at theta0 degrees where y crosses V.
std::vector<double> crossingsOf(double theta0, double V) {
  return rootsOf([&](LD phi) {
    const LD t = (theta0 + phi) * M_PIl / 180;
    return R * sinl(t) + sqrtl(L * L - (E - R * cosl(t)) * (E - R * cosl(t))) - V;
  });
}

// dy/dphi in mm per degree of crank.
LD slopeOf(double theta0, LD phi) {
  const LD t = (theta0 + phi) * M_PIl / 180, c = E - R * cosl(t);
  return (R * cosl(t) - c * R * sinl(t) / sqrtl(L * L - c * c)) * M_PIl / 180;
}

struct Fixture {
  test::SliderCrank s;
  Kinematics k;
  explicit Fixture(double drawnDeg) : s(test::sliderCrank(R, L, E, drawnDeg)) {
    EXPECT_TRUE(k.load(s.m).ok());
  }
  CycleWindow window(const std::string& text) {
    std::string why;
    std::optional<CycleWindow> w = parseWindow(s.m, text, &why);
    EXPECT_TRUE(w.has_value()) << why;
    return w.value_or(CycleWindow{});
  }
};

TEST(Timing, WindowsOfASliderCrankAgainstItsClosedForm) {
  Fixture f(100);  // at crank 0 the block is high and falling: y < 60 starts mid-cycle
  const CycleDiagram d = cycleDiagram(f.k, {}, {f.window("low=slider.B:y<60")}, {});
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  const std::vector<double> x = crossingsOf(100, 60);
  ASSERT_EQ(x.size(), 2u);
  ASSERT_EQ(d.windows.size(), 1u);
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[0].intervals[0].fromDeg, x[0], 1e-9);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, x[1], 1e-9);
  EXPECT_EQ(d.windows[0].name, "low");
  EXPECT_FALSE(d.anyConflict());
}

TEST(Timing, AWindowWrapsThroughZero) {
  Fixture f(100);
  const CycleDiagram d = cycleDiagram(f.k, {}, {f.window("high=slider.B:y>60")}, {});
  ASSERT_TRUE(d.status.ok());
  const std::vector<double> x = crossingsOf(100, 60);
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[0].intervals[0].fromDeg, x[1], 1e-9);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, 360 + x[0], 1e-9);
  // With the same direction as a vector, and a level it never reaches.
  const CycleDiagram all = cycleDiagram(f.k, {}, {f.window("all=slider.B:0,2>-5")}, {});
  ASSERT_EQ(all.windows[0].intervals.size(), 1u);
  EXPECT_EQ(all.windows[0].intervals[0].fromDeg, 0);
  EXPECT_EQ(all.windows[0].intervals[0].toDeg, 360);
  const CycleDiagram none = cycleDiagram(f.k, {}, {f.window("none=slider.B:y>500")}, {});
  EXPECT_TRUE(none.windows[0].intervals.empty());
}

// low = y < 70 and high = y > 55 overlap where 55 < y < 70: from the crossing of 55 on the way
// up to that of 70, and from 70 back down to 55.
TEST(Timing, ConflictIsTheOverlap) {
  Fixture f(100);
  const CycleDiagram d =
      cycleDiagram(f.k, {}, {f.window("low=slider.B:y<70"), f.window("high=slider.B:y>55")},
                   {{"low", "high"}, {"high", "low"}});
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.conflicts.size(), 2u);
  EXPECT_TRUE(d.anyConflict());
  const std::vector<double> x55 = crossingsOf(100, 55), x70 = crossingsOf(100, 70);
  ASSERT_EQ(x55.size(), 2u);
  ASSERT_EQ(x70.size(), 2u);
  // Falling from the top through 70 then 55, rising through 55 then 70.
  const std::vector<AngleInterval>& o = d.conflicts[0].overlaps;
  ASSERT_EQ(o.size(), 2u);
  EXPECT_NEAR(o[0].fromDeg, x70[0], 1e-9);
  EXPECT_NEAR(o[0].toDeg, x55[0], 1e-9);
  EXPECT_NEAR(o[1].fromDeg, x55[1], 1e-9);
  EXPECT_NEAR(o[1].toDeg, x70[1], 1e-9);
  EXPECT_EQ(d.conflicts[1].overlaps.size(), 2u);
  EXPECT_EQ(d.conflicts[0].first, "low");
}

TEST(Timing, RowEventsDeadCentresAndExactRange) {
  Fixture f(30);
  std::string why;
  const CycleOutput y = *parseOutput(f.s.m, "slider.B:y", &why);
  const CycleDiagram d = cycleDiagram(f.k, {y}, {}, {});
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.rows.size(), 1u);
  const CycleRow& r = d.rows[0];
  EXPECT_NEAR(r.max, std::sqrt((R + L) * (R + L) - E * E), 1e-9 * L);
  EXPECT_NEAR(r.min, std::sqrt((L - R) * (L - R) - E * E), 1e-9 * L);
  ASSERT_EQ(r.extremes.size(), 2u);
  EXPECT_EQ(r.normalised.size(), r.value.size());
  for (double v : r.normalised) EXPECT_TRUE(v >= 0 && v <= 1);
  EXPECT_TRUE(r.dwells.empty());  // a slider-crank's block does not dwell 10 degrees
  // A threshold of 0.05 mm per degree: the speed is under it around both dead centres, between
  // the roots of y'(phi) = +-0.05 (the formula's derivative, bisected).
  CycleOptions near;
  near.dwellSpeed = 0.05;
  near.dwellMinDeg = 0;
  const CycleDiagram dc = cycleDiagram(f.k, {y}, {}, {}, near);
  std::vector<double> ends;
  for (double sgn : {1.0, -1.0})
    for (double x : rootsOf([&](LD phi) { return slopeOf(30, phi) - sgn * 0.05; }))
      ends.push_back(x);
  std::sort(ends.begin(), ends.end());
  ASSERT_EQ(ends.size(), 4u);
  const std::vector<AngleInterval>& dw = dc.rows[0].dwells;
  ASSERT_EQ(dw.size(), 2u);
  EXPECT_NEAR(dw[0].fromDeg, ends[0], 1e-9);
  EXPECT_NEAR(dw[0].toDeg, ends[1], 1e-9);
  EXPECT_NEAR(dw[1].fromDeg, ends[2], 1e-9);
  EXPECT_NEAR(dw[1].toDeg, ends[3], 1e-9);
  // A threshold above its peak speed: it "dwells" the whole cycle.
  CycleOptions slow;
  slow.dwellSpeed = 10;  // mm per degree; the peak is under 0.4
  const CycleDiagram all = cycleDiagram(f.k, {y}, {}, {}, slow);
  ASSERT_EQ(all.rows[0].dwells.size(), 1u);
  EXPECT_EQ(all.rows[0].dwells[0].toDeg - all.rows[0].dwells[0].fromDeg, 360);
}

// The crank's angle, whole turns counted: angle < 90 holds for the first 90 degrees only (it
// does not repeat, so nothing wraps).
TEST(Timing, BodyAngleWindow) {
  Fixture f(30);
  const CycleDiagram d = cycleDiagram(f.k, {}, {f.window("a=crank:angle<90")}, {});
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_EQ(d.windows[0].intervals[0].fromDeg, 0);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, 90, 1e-9);
  EXPECT_FALSE(d.rows[0].periodic);
}

TEST(Timing, OverlapOfWrappingIntervals) {
  const std::vector<AngleInterval> a = {{300, 420}}, b = {{0, 360}};
  std::vector<AngleInterval> o = overlapOf(a, b, true);
  ASSERT_EQ(o.size(), 1u);
  EXPECT_EQ(o[0].fromDeg, 300);
  EXPECT_EQ(o[0].toDeg, 420);
  o = overlapOf(a, {{50, 310}}, true);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_EQ(o[0].fromDeg, 50);
  EXPECT_EQ(o[0].toDeg, 60);
  EXPECT_EQ(o[1].fromDeg, 300);
  EXPECT_EQ(o[1].toDeg, 310);
  EXPECT_TRUE(overlapOf(a, {{100, 200}}, true).empty());
}

TEST(Timing, BadExpressionsSayWhere) {
  Fixture f(30);
  struct Bad {
    const char* text;
    const char* says;
  };
  for (const Bad& b :
       {Bad{"slider.B:y<3", "NAME=OUTPUT"}, Bad{"=slider.B:y<3", "NAME=OUTPUT"},
        Bad{"a+b=slider.B:y<3", "NAME=OUTPUT"}, Bad{"w=slider.B:y", "no '<'"},
        Bad{"w=slider.B:y<x3", "\"x3\" after '<' is not a number"},
        Bad{"w=slider.Q:y<3", "no point \"slider.Q\""},
        Bad{"w=slider.B:z<3", "\"z\" after \"slider.B:\""},
        Bad{"w=slider.B:0,0<3", "\"0,0\" after"}, Bad{"w=sled:angle<3", "no body \"sled\""},
        Bad{"w=slider.B<3", "is not body.point:y"}}) {
    std::string why;
    EXPECT_FALSE(parseWindow(f.s.m, b.text, &why).has_value()) << b.text;
    EXPECT_NE(why.find(b.says), std::string::npos) << b.text << ": " << why;
  }
  const CycleWindow w = f.window("w=slider.B:y<60");
  EXPECT_EQ(cycleDiagram(f.k, {}, {w, w}, {}).status.code, StatusCode::BadModel);
  const CycleDiagram d = cycleDiagram(f.k, {}, {w}, {{"w", "v"}});
  EXPECT_EQ(d.status.code, StatusCode::BadModel);
  EXPECT_NE(d.status.message.find("no window named v"), std::string::npos);
  EXPECT_EQ(cycleDiagram(Kinematics(), {}, {w}, {}).status.code, StatusCode::BadModel);
}

// The 30-body machine on one shaft (tests/mechanisms.h): its block 0 is a radial slider-crank
// along +x with its pin at phase 0, s = r cos phi + sqrt(l^2 - r^2 sin^2 phi), so s > 45 holds
// where cos phi > (45^2 - l^2 + r^2) / (90 r), a window that wraps through 0; its hook turns
// twice a cycle, and an edit of one mechanism re-solves only its own groups.
TEST(Timing, WindowOnAMachineOfFourteenMechanisms) {
  const Mechanism m = test::shaftMachine(14);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  EXPECT_TRUE(k.closedForm());
  EXPECT_EQ(m.bodies.size(), 31u);
  std::string why;
  const CycleWindow w = *parseWindow(m, "b0=block0.B:1,0>45", &why);
  const CycleWindow h = *parseWindow(m, "h=hook:angle<360", &why);
  const CycleDiagram d = cycleDiagram(k, {}, {w, h}, {});
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  const double a = std::acos((45.0 * 45 - 1600 + 100) / 900) * 180 / M_PI;
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[0].intervals[0].fromDeg, 360 - a, 1e-9);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, 360 + a, 1e-9);
  ASSERT_EQ(d.windows[1].intervals.size(), 1u);  // the hook's first turn: half the cycle
  EXPECT_NEAR(d.windows[1].intervals[0].toDeg, 180, 1e-9);
  // Another mechanism made longer: only its group is solved again, block 0 moves as before.
  Mechanism edited = m;
  Point* c = edited.point(*edited.findPoint("rocker3.G"));
  c->pos *= 1.01;
  edited.point(*edited.findPoint("ground.G3"))->pos = c->pos;
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_EQ(k.lastEditGroups(), 1);
  const CycleDiagram again = cycleDiagram(k, {}, {w}, {});
  EXPECT_NEAR(again.windows[0].intervals[0].fromDeg, 360 - a, 1e-9);
}

// The lockstitch example's needle (a central slider-crank hanging from the arm shaft: crank 16,
// rod 45, the point 131 below the rod's pin, drawn at its top) is below a throat plate at
// y = -185 where 16 cos t - sqrt(45^2 - 16^2 sin^2 t) - 131 < -185, that is cos t <
// (45^2 - 16^2 - 54^2) / (108 16): from acos of that to its mirror.
TEST(Timing, LockstitchNeedleBelowTheThroatPlate) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-arm-shaft")).ok());
  std::string why;
  const CycleWindow w = *parseWindow(k.mechanism(), "needle=needlebar.N:y<-185", &why);
  const CycleDiagram d = cycleDiagram(k, {}, {w}, {});
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  const double a = std::acos((45.0 * 45 - 16 * 16 - 54 * 54) / (108.0 * 16)) * 180 / M_PI;
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[0].intervals[0].fromDeg, a, 1e-9);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, 360 - a, 1e-9);
  // Its dead centres: top at 0, bottom at 180.
  ASSERT_EQ(d.rows[0].extremes.size(), 2u);
  EXPECT_NEAR(d.rows[0].extremes[1].crankDeg, 180, 1e-9);
  EXPECT_NEAR(d.rows[0].min, -192, 1e-9);
}

// A window whose level is the value at a dead centre at crank 0 (the central slider-crank
// drawn at its top: y = r + l exactly): y < r + l holds over the whole cycle but that instant,
// y > r + l nowhere.
TEST(Timing, WindowStartingAtADeadCentreOnItsLevel) {
  const test::SliderCrank s = test::sliderCrank(20, 60, 0, 90);
  Kinematics k;
  ASSERT_TRUE(k.load(s.m).ok());
  std::string why;
  const CycleDiagram d = cycleDiagram(k, {},
                                      {*parseWindow(s.m, "below=slider.B:y<80", &why),
                                       *parseWindow(s.m, "above=slider.B:y>80", &why)},
                                      {});
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_EQ(d.windows[0].intervals[0].fromDeg, 0);
  EXPECT_EQ(d.windows[0].intervals[0].toDeg, 360);
  EXPECT_TRUE(d.windows[1].intervals.empty());
}

}  // namespace
}  // namespace linkage
