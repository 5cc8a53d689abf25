// The lockstitch-machine example (resources/examples/machines.py): the needle below the throat
// plate and the feed dog above it, windows whose ends are compared with an independent
// derivation of the feed (circle intersections and one arcsine, bisected in long double), and
// the hook point's clearance to the needle; the two windows do not overlap, as a machine that
// sews needs.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "examples.h"
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

}  // namespace
}  // namespace linkage
