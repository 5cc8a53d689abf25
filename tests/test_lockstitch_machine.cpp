// The lockstitch-machine example (resources/examples/machines.py): the needle below the throat
// plate and the feed dog above it, windows whose ends are compared with an independent
// derivation of the feed (circle intersections and one arcsine, bisected in long double), and
// the hook point's clearance to the needle; the two windows do not overlap, as a machine that
// sews needs. The windows the lockstitch files ship (issue 26): their thresholds are the
// drawing's own (the plate's line, the needle's line, the top of the hook's circle) and their
// ends those of the closed forms, in the library and as `linkage-cli timing` prints them.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "examples.h"
#ifdef LINKAGE_CLI
#include "cli_harness.h"
#include "linkage/io/numbers.h"
#endif
#include "linkage/clearance.h"
#include "linkage/slot_travel.h"
#include "linkage/timing.h"

namespace linkage {
namespace {

using LD = long double;

struct P2 {
  LD x, y;
};

// The feed dog's tooth T at crank angle phi (degrees): the feed shaft S = (-60, -225) turns with
// the arm shaft (1:1), its eccentrics E1 (2) and E2 (2.5) drawn straight up; R on the rocker of
// 20 about G = (-110, -245) at 50 from E2, on the drawing's side; the feed bar pinned at R with
// its fork (the line along x through E1, as drawn) through E1.
P2 tooth(LD phi) {
  const LD t = phi * M_PIl / 180, sx = -60, sy = -225;
  const P2 e1{sx - 2 * sinl(t), sy + 2 * cosl(t)}, e2{sx - 2.5L * sinl(t), sy + 2.5L * cosl(t)};
  const P2 g{-110, -245};
  // circle(E2, 50) and circle(G, 20): the intersection right of E2 -> G (machines.py, left=False)
  const LD ex = g.x - e2.x, ey = g.y - e2.y, d = sqrtl(ex * ex + ey * ey);
  const LD m = (50 * 50 - 20 * 20 + d * d) / (2 * d), h = -sqrtl(50 * 50 - m * m);
  const P2 u{ex / d, ey / d};
  const P2 r{e2.x + m * u.x - h * u.y, e2.y + m * u.y + h * u.x};
  // Drawn: R0, E1_0 = (-60, -223), T0 = (-5, -182); the fork's offset from R across it is
  // w0.y = E1_0.y - R0.y, kept: (E1 - R) x (cos th, sin th) = -w0.y.
  static const P2 r0 = [] {
    const P2 e20{-60, -222.5L};
    const LD fx = -110 - e20.x, fy = -245 - e20.y, fd = sqrtl(fx * fx + fy * fy);
    const LD fm = (50 * 50 - 20 * 20 + fd * fd) / (2 * fd), fh = -sqrtl(50 * 50 - fm * fm);
    return P2{e20.x + fm * fx / fd - fh * fy / fd, e20.y + fm * fy / fd + fh * fx / fd};
  }();
  const LD w0y = -223 - r0.y;
  const LD vx = e1.x - r.x, vy = e1.y - r.y, rho = sqrtl(vx * vx + vy * vy);
  const LD th = atan2l(vy, vx) - asinl(w0y / rho);
  const LD tx = -5 - r0.x, ty = -182 - r0.y;
  return {r.x + cosl(th) * tx - sinl(th) * ty, r.y + sinl(th) * tx + cosl(th) * ty};
}

std::vector<double> crossings(LD level) {
  std::vector<double> out;
  auto g = [&](LD phi) { return tooth(phi).y - level; };
  for (int i = 0; i < 3600; ++i) {
    LD a = i / 10.0L, b = (i + 1) / 10.0L;
    if ((g(a) < 0) == (g(b) < 0)) continue;
    const bool up = g(a) < 0;
    for (int k = 0; k < 100; ++k) ((g((a + b) / 2) < 0) == up ? a : b) = (a + b) / 2;
    out.push_back(static_cast<double>((a + b) / 2));
  }
  return out;
}

TEST(LockstitchMachine, NeedleBelowAndFeedDogAboveTheThroatPlate) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-machine")).ok());
  const Mechanism& m = k.mechanism();
  // The derivation is the drawing at crank 0.
  const P2 t0 = tooth(0);
  EXPECT_NEAR(static_cast<double>(t0.x), -5, 1e-12);
  EXPECT_NEAR(static_cast<double>(t0.y), -182, 1e-12);
  std::string why;
  const CycleDiagram d = cycleDiagram(k, {},
                                      {*parseWindow(m, "needle=needlebar.N:y<-185", &why),
                                       *parseWindow(m, "feed=feedbar.T:y>-185", &why)},
                                      {{"needle", "feed"}});
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  // The needle: a central slider-crank 16, 45, its point 131 below B (tests/test_timing.cpp).
  const double a = std::acos((45.0 * 45 - 16 * 16 - 54 * 54) / (108.0 * 16)) * 180 / M_PI;
  ASSERT_EQ(d.windows[0].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[0].intervals[0].fromDeg, a, 1e-9);
  EXPECT_NEAR(d.windows[0].intervals[0].toDeg, 360 - a, 1e-9);
  // The feed dog is above the plate around crank 0: one window wrapping through it.
  const std::vector<double> x = crossings(-185);
  ASSERT_EQ(x.size(), 2u);
  ASSERT_EQ(d.windows[1].intervals.size(), 1u);
  EXPECT_NEAR(d.windows[1].intervals[0].fromDeg, x[1], 1e-9);
  EXPECT_NEAR(d.windows[1].intervals[0].toDeg, 360 + x[0], 1e-9);
  EXPECT_FALSE(d.anyConflict());
  // Its feed bar's fork keeps the lift eccentric inside it.
  const SlotTravels s = slotTravel(k);
  ASSERT_TRUE(s.status.ok());
  EXPECT_TRUE(s.allInside());
}

// The hook point passes closest to the needle's point after the needle's bottom dead centre, as
// on the arm shaft alone (whose clearance tests/test_clearance.cpp checks against the closed
// form): the feed, on a shaft of its own, changes neither the angle nor the distance.
TEST(LockstitchMachine, HookPointClearanceToTheNeedle) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-machine")).ok());
  Kinematics arm;
  ASSERT_TRUE(arm.load(test::example("lockstitch-arm-shaft")).ok());
  const Mechanism& m = k.mechanism();
  const Clearance c = findClearance(k, ClearancePart::of(*m.findPoint("hook.K")),
                                    ClearancePart::of(*m.findPoint("needlebar.N")));
  ASSERT_TRUE(c.status.ok());
  ASSERT_EQ(c.minima.size(), 2u);
  EXPECT_GT(c.closest.crankDeg, 180);
  const Mechanism& n = arm.mechanism();
  const Clearance alone = findClearance(arm, ClearancePart::of(*n.findPoint("hook.K")),
                                        ClearancePart::of(*n.findPoint("needlebar.N")));
  EXPECT_NEAR(c.closest.crankDeg, alone.closest.crankDeg, 1e-9);
  EXPECT_NEAR(c.closest.distance, alone.closest.distance, 1e-9 * 200);
  EXPECT_LT(c.closest.distance, 5);
}

// The needle point (a central slider-crank 16, 45 hanging from the arm shaft, the point 131 below
// the rod's pin) is below y = -185 from crank a to 360 - a: there |OB| = 185 - 131 = 54, and the
// triangle O, A, B with OA 16, AB 45 gives cos a = (45^2 - 16^2 - 54^2) / (2 16 54) (degrees).
double needleBelowPlateFrom() {
  return std::acos((45.0 * 45 - 16 * 16 - 54 * 54) / (108.0 * 16)) * 180 / M_PI;
}

// The hook point K turns twice as fast as the arm shaft, the same way (counter-clockwise), from
// atan2(9, 12) at crank 0: it is left of the needle's line x = 0 while its angle is between 90
// and 270 degrees (mod 360): crank (90 - a0) / 2 to (270 - a0) / 2, and 180 later.
std::vector<AngleInterval> hookPastTheNeedle() {
  const double a0 = std::atan2(9.0, 12.0) * 180 / M_PI;
  return {{(90 - a0) / 2, (270 - a0) / 2}, {(90 - a0) / 2 + 180, (270 - a0) / 2 + 180}};
}

// The named slot's two ends, as drawn.
std::pair<Vec2, Vec2> slotEnds(const Mechanism& m, const char* name) {
  for (const Slot& s : m.slots)
    if (s.name == name) return {s.p0, s.p1};
  ADD_FAILURE() << "no slot " << name;
  return {};
}

const TimingWindow* windowNamed(const Mechanism& m, const std::string& name) {
  for (const TimingWindow& w : m.timing.windows)
    if (w.name == name) return &w;
  ADD_FAILURE() << "no window " << name;
  return nullptr;
}

void expectIntervals(const WindowIntervals& got, const std::vector<AngleInterval>& want) {
  ASSERT_EQ(got.intervals.size(), want.size()) << got.name;
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got.intervals[i].fromDeg, want[i].fromDeg, 1e-9) << got.name << " " << i;
    EXPECT_NEAR(got.intervals[i].toDeg, want[i].toDeg, 1e-9) << got.name << " " << i;
  }
}

TEST(LockstitchMachine, ShipsItsWindowsWithTheDrawingsThresholds) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-machine")).ok());
  const Mechanism& m = k.mechanism();
  // The throat plate is the ground slot along y = -185; the needle runs in the slot x = 0.
  const auto [p0, p1] = slotEnds(m, "plate");
  ASSERT_EQ(p0.y(), p1.y());
  const auto [n0, n1] = slotEnds(m, "needle");
  ASSERT_EQ(n0.x(), n1.x());
  ASSERT_EQ(m.timing.windows.size(), 3u);
  const TimingWindow *needle = windowNamed(m, "needle"), *hook = windowNamed(m, "hook"),
                     *feed = windowNamed(m, "feed");
  ASSERT_TRUE(needle && hook && feed);
  EXPECT_EQ(needle->output, LimitMeasure::along(*m.findPoint("needlebar.N"), Vec2(0, 1)));
  EXPECT_TRUE(needle->below);
  EXPECT_EQ(needle->level, p0.y());
  EXPECT_EQ(hook->output, LimitMeasure::along(*m.findPoint("hook.K"), Vec2(1, 0)));
  EXPECT_TRUE(hook->below);  // it turns counter-clockwise: over the needle it moves to -x
  EXPECT_EQ(hook->level, n0.x());
  EXPECT_EQ(feed->output, LimitMeasure::along(*m.findPoint("feedbar.T"), Vec2(0, 1)));
  EXPECT_FALSE(feed->below);
  EXPECT_EQ(feed->level, p0.y());
  ASSERT_EQ(m.timing.conflicts.size(), 1u);
  EXPECT_EQ(m.timing.conflicts[0], (TimingConflict{"needle", "feed"}));

  const CycleDiagram d = cycleDiagram(k, m.timing);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_EQ(d.windows.size(), 3u);
  const double a = needleBelowPlateFrom();
  expectIntervals(d.windows[0], {{a, 360 - a}});
  expectIntervals(d.windows[1], hookPastTheNeedle());
  const std::vector<double> x = crossings(p0.y());  // the feed, derived on its own
  ASSERT_EQ(x.size(), 2u);
  expectIntervals(d.windows[2], {{x[1], 360 + x[0]}});
  // The hook point reaches the needle's line after the needle's bottom dead centre (180), while
  // the needle is below the plate: the loop is taken below it.
  EXPECT_GT(d.windows[1].intervals[1].fromDeg, 180);
  EXPECT_LT(d.windows[1].intervals[1].fromDeg, 360 - a);
  ASSERT_EQ(d.conflicts.size(), 1u);
  EXPECT_TRUE(d.conflicts[0].overlaps.empty());  // the feed moves the fabric only while free
}

// The arm shaft alone has no plate: its needle window's level is where the plate of the
// machine lies, the top of the hook point's circle, L.y + |LK|.
TEST(LockstitchArmShaft, ShipsTheNeedleAndHookWindows) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-arm-shaft")).ok());
  const Mechanism& m = k.mechanism();
  const Point *l = nullptr, *kp = nullptr;
  for (const Point& p : m.points) {
    if (m.pointLabel(p.id) == "hook.L") l = &p;
    if (m.pointLabel(p.id) == "hook.K") kp = &p;
  }
  ASSERT_TRUE(l && kp);
  const TimingWindow *needle = windowNamed(m, "needle"), *hook = windowNamed(m, "hook");
  ASSERT_TRUE(needle && hook);
  EXPECT_EQ(needle->level, l->pos.y() + (kp->pos - l->pos).norm());
  EXPECT_EQ(hook->level, slotEnds(m, "needle").first.x());
  EXPECT_TRUE(m.timing.conflicts.empty());
  const CycleDiagram d = cycleDiagram(k, m.timing);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_EQ(d.windows.size(), 2u);
  const double a = needleBelowPlateFrom();
  expectIntervals(d.windows[0], {{a, 360 - a}});
  expectIntervals(d.windows[1], hookPastTheNeedle());
}

// Both lockstitch files watch the hook point's clearance to the needle as the segment from its
// point N up to the bar's pin B: the hook point meets it where it passes over the needle's line
// after the needle's bottom dead centre, at the top of its circle (0, -185), N_y(t) below it
// (the needle's closed form); on its idle turn it passes below the needle's point.
TEST(LockstitchMachine, ShipsTheHookPointsClearanceToTheNeedleSegment) {
  for (const char* name : {"lockstitch-machine", "lockstitch-arm-shaft"}) {
    Kinematics k;
    ASSERT_TRUE(k.load(test::example(name)).ok()) << name;
    const Mechanism& m = k.mechanism();
    ASSERT_EQ(m.timing.clearances.size(), 1u) << name;
    const ClearanceWatch& w = m.timing.clearances[0];
    EXPECT_EQ(w.point, *m.findPoint("hook.K")) << name;
    EXPECT_EQ(w.other,
              ClearancePart::segment(*m.findPoint("needlebar.N"), *m.findPoint("needlebar.B")))
        << name;
    EXPECT_FALSE(w.minMm) << name;  // they are meant to meet: no least distance
    const Clearance c = findClearance(k, ClearancePart::of(w.point), w.other);
    ASSERT_TRUE(c.status.ok()) << name << ": " << c.status.message;
    const double meet = hookPastTheNeedle()[1].fromDeg, t = meet * M_PI / 180;
    const double needleY =
        16 * std::cos(t) - std::sqrt(45 * 45 - 256 * std::sin(t) * std::sin(t)) - 131;
    EXPECT_EQ(c.closest.distance, 0) << name;
    EXPECT_NEAR(c.closest.crankDeg, meet, 1e-9) << name;
    int on = 0;
    for (const ClearanceCrossing& x : c.crossings)
      if (x.onPart) {
        ++on;
        EXPECT_NEAR(x.crankDeg, meet, 1e-9) << name;
        EXPECT_NEAR(x.alongMm, -185 - needleY, 1e-9) << name;
      }
    EXPECT_EQ(on, 1) << name;
  }
}

#ifdef LINKAGE_CLI
using LockstitchCli = test::CliTest;

// `linkage-cli timing lockstitch-machine`, no option: the file's windows, their ends the closed
// forms' and the feed's own derivation, exit 0 (the needle and the feed do not overlap).
TEST_F(LockstitchCli, TimingPrintsTheShippedWindowsWithNoOption) {
  const test::CliResult r = run("timing lockstitch-machine");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 5u) << r.out;
  EXPECT_EQ(lines[0], "window,from_deg,to_deg");
  const double a = needleBelowPlateFrom();
  const std::vector<AngleInterval> hook = hookPastTheNeedle();
  const std::vector<double> x = crossings(-185);
  ASSERT_EQ(x.size(), 2u);
  const struct {
    const char* name;
    AngleInterval at;
  } want[] = {
      {"needle", {a, 360 - a}}, {"hook", hook[0]}, {"hook", hook[1]}, {"feed", {x[1], 360 + x[0]}}};
  for (size_t i = 0; i < 4; ++i) {
    const std::string& line = lines[i + 1];
    const size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
    ASSERT_NE(c2, std::string::npos) << line;
    EXPECT_EQ(line.substr(0, c1), want[i].name);
    const std::optional<double> from = parseNumber(line.substr(c1 + 1, c2 - c1 - 1)),
                                to = parseNumber(line.substr(c2 + 1));
    ASSERT_TRUE(from && to) << line;
    EXPECT_NEAR(*from, want[i].at.fromDeg, 1e-9) << line;
    EXPECT_NEAR(*to, want[i].at.toDeg, 1e-9) << line;
  }
}
#endif

}  // namespace
}  // namespace linkage
