// Clearance (linkage/clearance.h) against closed forms: two points on two shafts coupled 2:1
// (a belt) or on one crank, whose distance's minima are the roots of d/dphi |d|^2 (bisected in
// long double here, from the formula, not the solver); a crank pin against a ground slot's
// line, which it crosses or passes at a known height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "examples.h"
#include "linkage/clearance.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using LD = long double;

struct Shafts {
  Mechanism m;
  PointId p1, p2;
  SlotId line;
};

// Shaft 1 about the origin (driven, ccw), shaft 2 about (dist, 0) turning `ratio` times as
// fast; a point on each at radius r and drawn angle alpha; a ground slot y = lineY.
Shafts shafts(double dist, double ratio, double r1, double a1, double r2, double a2, double lineY) {
  Shafts s;
  Mechanism& m = s.m;
  const BodyId g = m.addBody("ground", true), c1 = m.addBody("main"), c2 = m.addBody("hook");
  const Vec2 o2(dist, 0);
  const PointId g1 = m.addPoint(g, "O1", Vec2(0, 0)), g2 = m.addPoint(g, "O2", o2);
  const PointId m1 = m.addPoint(c1, "O", Vec2(0, 0)), h2 = m.addPoint(c2, "O", o2);
  s.p1 = m.addPoint(c1, "P", r1 * Vec2(std::cos(a1), std::sin(a1)));
  s.p2 = m.addPoint(c2, "P", o2 + r2 * Vec2(std::cos(a2), std::sin(a2)));
  s.line = m.addSlot(g, "plate", Vec2(-50, lineY), Vec2(50, lineY));
  const JointId drive = m.addPin(g1, m1);
  m.addPin(g2, h2);
  m.addGear(m1, h2, ratio);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  return s;
}

// Crank angles (degrees) in [0, 360) where g goes from negative to positive, by bisection.
template <class G>
std::vector<double> risingRoots(G g) {
  std::vector<double> out;
  const int n = 7200;
  for (int i = 0; i < n; ++i) {
    LD a = 360.0L * i / n, b = 360.0L * (i + 1) / n;
    if (!(g(a) < 0 && g(b) >= 0)) continue;
    for (int k = 0; k < 100; ++k) {
      const LD c = (a + b) / 2;
      (g(c) < 0 ? a : b) = c;
    }
    out.push_back(static_cast<double>((a + b) / 2));
  }
  return out;
}

TEST(Clearance, TwoPointsOnShaftsCoupledTwoToOne) {
  const double D = 30, k = 2, r1 = 12, a1 = 0.3, r2 = 9, a2 = 2.0;
  Shafts s = shafts(D, k, r1, a1, r2, a2, 100);
  Kinematics kin;
  ASSERT_TRUE(kin.load(s.m).ok());
  const Clearance c = findClearance(kin, ClearancePart::of(s.p1), ClearancePart::of(s.p2));
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_TRUE(c.periodic);
  const LD deg = M_PIl / 180;
  auto d = [&](LD phi) {  // P2 - P1 and its derivative in phi (radians)
    const LD t1 = a1 + phi * deg, t2 = a2 + k * phi * deg;
    const LD x = D + r2 * cosl(t2) - r1 * cosl(t1), y = r2 * sinl(t2) - r1 * sinl(t1);
    const LD dx = -k * r2 * sinl(t2) + r1 * sinl(t1), dy = k * r2 * cosl(t2) - r1 * cosl(t1);
    return std::pair{std::pair{x, y}, std::pair{dx, dy}};
  };
  const std::vector<double> expect = risingRoots([&](LD phi) {
    const auto [p, v] = d(phi);
    return p.first * v.first + p.second * v.second;
  });
  ASSERT_GE(expect.size(), 2u);  // the 2:1 coupling gives two approaches a turn
  ASSERT_EQ(c.minima.size(), expect.size());
  double closest = 1e300;
  for (size_t i = 0; i < expect.size(); ++i) {
    EXPECT_NEAR(c.minima[i].crankDeg, expect[i], 1e-9);
    const auto [p, v] = d(expect[i]);
    const double dist = static_cast<double>(sqrtl(p.first * p.first + p.second * p.second));
    EXPECT_NEAR(c.minima[i].distance, dist, 1e-9 * D);
    closest = std::min(closest, dist);
  }
  EXPECT_NEAR(c.closest.distance, closest, 1e-9 * D);
}

TEST(Clearance, TwoPointsOfOneCrankKeepTheirDistance) {
  Shafts s = shafts(30, 2, 12, 0.3, 9, 2.0, 100);
  const PointId q = s.m.addPoint(s.m.bodyNamed("main")->id, "Q", Vec2(0, 5));
  Kinematics kin;
  ASSERT_TRUE(kin.load(s.m).ok());
  const Clearance c = findClearance(kin, ClearancePart::of(s.p1), ClearancePart::of(q));
  ASSERT_TRUE(c.status.ok());
  EXPECT_TRUE(c.minima.empty());
  const Vec2 p1 = s.m.point(s.p1)->pos;
  EXPECT_NEAR(c.closest.distance, (p1 - Vec2(0, 5)).norm(), 1e-12 * 30);
}

// The crank pin at radius 12 against the line y = lineY: below 12 it crosses the line at
// asin(lineY / 12) and its supplement (distance 0); above, it passes it at the top.
TEST(Clearance, PointAgainstAGroundSlotLine) {
  const double r = 12, a1 = 0.3;
  for (double lineY : {6.0, 15.0}) {
    Shafts s = shafts(30, 2, r, a1, 9, 2.0, lineY);
    Kinematics kin;
    ASSERT_TRUE(kin.load(s.m).ok());
    const Clearance c = findClearance(kin, ClearancePart::of(s.line), ClearancePart::of(s.p1));
    ASSERT_TRUE(c.status.ok()) << c.status.message;
    auto crank = [&](double theta) {
      double d = (theta - a1) * 180 / M_PI;
      return d - 360 * std::floor(d / 360);
    };
    if (lineY < r) {
      std::vector<double> expect = {crank(std::asin(lineY / r)),
                                    crank(M_PI - std::asin(lineY / r))};
      std::sort(expect.begin(), expect.end());
      ASSERT_EQ(c.minima.size(), 2u);
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(c.minima[i].crankDeg, expect[i], 1e-9);
        EXPECT_EQ(c.minima[i].distance, 0);
      }
      EXPECT_EQ(c.closest.distance, 0);
    } else {
      ASSERT_EQ(c.minima.size(), 1u);
      EXPECT_NEAR(c.minima[0].crankDeg, crank(M_PI / 2), 1e-9);
      EXPECT_NEAR(c.minima[0].distance, lineY - r, 1e-9 * r);
      EXPECT_NEAR(c.closest.distance, lineY - r, 1e-9 * r);
    }
  }
}

// The crank pin (radius 12, drawn at a1) against slots of the ground that its circle does not
// reach as drawn: a short slot beside its path (x = 20, y from -5 to 5: the closest is 8 mm
// from its line at theta = 0), and one whose line the pin crosses beyond the slot's drawn ends
// (x = 5, y from 50 to 60: the closest is its end E, |E| - 12 at theta = atan2(E)); where the
// two are at the closest, and the distance at a pose.
TEST(Clearance, PointAgainstASlotAsDrawn) {
  const double r = 12, a1 = 0.3;
  Shafts s = shafts(30, 2, r, a1, 9, 2.0, 100);
  const BodyId g = s.m.ground()->id;
  const SlotId beside = s.m.addSlot(g, "beside", Vec2(20, -5), Vec2(20, 5));
  const SlotId beyond = s.m.addSlot(g, "beyond", Vec2(5, 60), Vec2(5, 50));
  Kinematics kin;
  ASSERT_TRUE(kin.load(s.m).ok());
  auto crank = [&](double theta) {
    double d = (theta - a1) * 180 / M_PI;
    return d - 360 * std::floor(d / 360);
  };
  struct Case {
    SlotId slot;
    double thetaDeg, distance;
    Vec2 other;
  };
  const Vec2 e(5, 50);
  for (const Case& c : {Case{beside, 0, 8, Vec2(20, 0)},
                        Case{beyond, std::atan2(50.0, 5.0) * 180 / M_PI, e.norm() - r, e}}) {
    const Clearance k = findClearance(kin, ClearancePart::of(s.p1), ClearancePart::of(c.slot));
    ASSERT_TRUE(k.status.ok()) << k.status.message;
    ASSERT_EQ(k.minima.size(), 1u);
    EXPECT_NEAR(k.minima[0].crankDeg, crank(c.thetaDeg * M_PI / 180), 1e-9);
    EXPECT_NEAR(k.minima[0].distance, c.distance, 1e-12 * 60);
    EXPECT_EQ(k.closest.crankDeg, k.minima[0].crankDeg);
    const double t = c.thetaDeg * M_PI / 180;
    EXPECT_NEAR((k.closestPoint - r * Vec2(std::cos(t), std::sin(t))).norm(), 0, 1e-9);
    EXPECT_NEAR((k.closestOther - c.other).norm(), 0, 1e-9);
    EXPECT_NEAR((k.closestPoint - k.closestOther).norm(), k.closest.distance, 1e-9);
    // The ground's slot, where it is drawn, for a figure.
    ASSERT_EQ(k.closestPart.size(), 2u);
    EXPECT_EQ(k.closestPart[0], s.m.slot(c.slot)->p0);
    EXPECT_EQ(k.closestPart[1], s.m.slot(c.slot)->p1);
    // The curve's samples are the distances at those angles.
    ASSERT_EQ(k.crankDeg.size(), k.distance.size());
    EXPECT_EQ(k.crankDeg.front(), 0);
    EXPECT_EQ(k.crankDeg.back(), 360);
    const Vec2 p0 = r * Vec2(std::cos(a1), std::sin(a1));
    const Slot& slot = *s.m.slot(c.slot);
    const Vec2 d = slot.p1 - slot.p0;
    const double u = std::clamp((p0 - slot.p0).dot(d) / d.squaredNorm(), 0.0, 1.0);
    EXPECT_NEAR(k.distance.front(), (p0 - (slot.p0 + u * d)).norm(), 1e-12 * 60);
    EXPECT_NEAR(clearanceAt(kin, ClearancePart::of(c.slot), ClearancePart::of(s.p1)),
                k.distance.front(), 1e-12 * 60);
  }
}

TEST(Clearance, Refusals) {
  Shafts s = shafts(30, 2, 12, 0.3, 9, 2.0, 20);
  Kinematics kin;
  ASSERT_TRUE(kin.load(s.m).ok());
  EXPECT_EQ(findClearance(kin, ClearancePart::of(s.line), ClearancePart::of(s.line)).status.code,
            StatusCode::BadModel);
  const PointId onGround = s.m.ground()->id == s.m.point(s.m.findPoint("ground.O1").value())->body
                               ? s.m.findPoint("ground.O1").value()
                               : PointId{};
  EXPECT_EQ(findClearance(kin, ClearancePart::of(onGround), ClearancePart::of(s.line)).status.code,
            StatusCode::BadModel);
  EXPECT_EQ(findClearance(kin, ClearancePart::of(PointId{}), ClearancePart::of(s.p1)).status.code,
            StatusCode::BadModel);
  EXPECT_EQ(
      findClearance(Kinematics(), ClearancePart::of(s.p1), ClearancePart::of(s.p2)).status.code,
      StatusCode::BadModel);
  EXPECT_EQ(findClearance(kin, ClearancePart::of(s.p1), ClearancePart::of(s.p1)).status.code,
            StatusCode::BadModel);
  EXPECT_TRUE(std::isnan(clearanceAt(kin, ClearancePart::of(s.p1), ClearancePart::of(s.p1))));
}

// The lockstitch example's hook point K (15 mm from the hook shaft L = (0, -200), drawn at
// (12, 9) from it, turning twice per turn of the arm shaft) and its needle point N (x = 0,
// y = 16 cos t - sqrt(45^2 - (16 sin t)^2) - 131): the minima of |K - N| are the rising roots of
// d/dt |K - N|^2 / 2 = (K - N) . (K' - N').
TEST(Clearance, LockstitchHookPointToNeedle) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-arm-shaft")).ok());
  const Mechanism& m = k.mechanism();
  const Clearance c = findClearance(k, ClearancePart::of(*m.findPoint("hook.K")),
                                    ClearancePart::of(*m.findPoint("needlebar.N")));
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const LD h0 = atan2l(9, 12), deg = M_PIl / 180;
  auto gap = [&](LD phi, LD* slope) {
    const LD t = phi * deg, s = sqrtl(45 * 45 - 256 * sinl(t) * sinl(t));
    const LD ny = 16 * cosl(t) - s - 131, dny = -16 * sinl(t) + 256 * sinl(t) * cosl(t) / s;
    const LD kx = 15 * cosl(h0 + 2 * t), ky = -200 + 15 * sinl(h0 + 2 * t);
    const LD dkx = -30 * sinl(h0 + 2 * t), dky = 30 * cosl(h0 + 2 * t);
    if (slope) *slope = kx * dkx + (ky - ny) * (dky - dny);
    return sqrtl(kx * kx + (ky - ny) * (ky - ny));
  };
  const std::vector<double> expect = risingRoots([&](LD phi) {
    LD s = 0;
    gap(phi, &s);
    return s;
  });
  ASSERT_EQ(c.minima.size(), expect.size());
  ASSERT_EQ(expect.size(), 2u);
  for (size_t i = 0; i < expect.size(); ++i) {
    EXPECT_NEAR(c.minima[i].crankDeg, expect[i], 1e-9);
    EXPECT_NEAR(c.minima[i].distance, static_cast<double>(gap(expect[i], nullptr)), 1e-9 * 200);
  }
  EXPECT_EQ(c.closest.crankDeg, c.minima[1].crankDeg);  // past the needle's bottom (180)
  EXPECT_GT(c.closest.crankDeg, 180);
}

// The hook point K to the needle as a segment from its point N to the needle bar's pin B (131
// mm above N): K crosses the needle's line x = 0 where 15 cos(h0 + 2t) = 0, four times a turn;
// the crossing is on the needle where K's height is between N's and B's, at K_y - N_y from N
// (issue 26: to the point N alone the closest approach is 4.41 mm, while K crosses the needle
// 4.74 mm above its point). Beyond N's end the distance is to N: the other minimum is the
// point-to-point one.
TEST(Clearance, LockstitchHookPointToTheNeedleAsASegment) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-arm-shaft")).ok());
  const Mechanism& m = k.mechanism();
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N"),
                B = *m.findPoint("needlebar.B");
  const Clearance c =
      findClearance(k, ClearancePart::segment(N, B), ClearancePart::of(K));  // either way round
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const LD h0 = atan2l(9, 12), deg = M_PIl / 180;
  auto needleY = [&](LD t) {
    return 16 * cosl(t) - sqrtl(45 * 45 - 256 * sinl(t) * sinl(t)) - 131;
  };
  EXPECT_NEAR(c.partLengthMm, 131, 1e-12);
  ASSERT_EQ(c.crossings.size(), 4u);
  int on = 0;
  for (int i = 0; i < 4; ++i) {
    const LD t = (90 * deg - h0) / 2 + i * 90 * deg;
    const LD ky = -200 + 15 * sinl(h0 + 2 * t), along = ky - needleY(t);
    EXPECT_NEAR(c.crossings[i].crankDeg, static_cast<double>(t / deg), 1e-9) << i;
    EXPECT_NEAR(c.crossings[i].alongMm, static_cast<double>(along), 1e-9) << i;
    EXPECT_EQ(c.crossings[i].onPart, along >= 0 && along <= 131) << i;
    if (c.crossings[i].onPart) {
      ++on;
      EXPECT_NEAR(c.closest.crankDeg, c.crossings[i].crankDeg, 1e-9);
      EXPECT_EQ(c.closest.distance, 0);
      EXPECT_GT(along, 4.7);  // above the needle's point
    }
  }
  EXPECT_EQ(on, 1);
  // Where they meet, the needle as it is then: N and B on x = 0 at the needle's height.
  const LD t = c.closest.crankDeg * deg, ny = needleY(t);
  EXPECT_NEAR((c.closestPoint - Vec2(0, -185)).norm(), 0, 1e-9);
  EXPECT_NEAR((c.closestOther - c.closestPoint).norm(), 0, 1e-9);
  ASSERT_EQ(c.closestPart.size(), 2u);
  EXPECT_NEAR((c.closestPart[0] - Vec2(0, static_cast<double>(ny))).norm(), 0, 1e-9);
  EXPECT_NEAR((c.closestPart[1] - Vec2(0, static_cast<double>(ny + 131))).norm(), 0, 1e-9);
  const Clearance toN = findClearance(k, ClearancePart::of(K), ClearancePart::of(N));
  EXPECT_TRUE(toN.closestPart.empty());  // a point: no part to draw
  ASSERT_EQ(c.minima.size(), 2u);
  EXPECT_NEAR(c.minima[0].crankDeg, toN.minima[0].crankDeg, 1e-9);
  EXPECT_NEAR(c.minima[0].distance, toN.minima[0].distance, 1e-9);
  EXPECT_EQ(c.minima[1].crankDeg, c.closest.crankDeg);
  // At the drawing (crank 0) K = (12, -191) is below the needle's point N = (0, -160).
  EXPECT_NEAR(clearanceAt(k, ClearancePart::of(K), ClearancePart::segment(N, B)),
              std::hypot(12.0, 31.0), 1e-12);
  // A point to its own body's segment does not change: refused.
  EXPECT_EQ(findClearance(k, ClearancePart::of(N), ClearancePart::segment(B, N)).status.code,
            StatusCode::BadModel);
}

// The needle point N runs along the line of the ground's needle slot (x = 0, y from -20 to
// -170): its distance from the slot is 0 while N_y = 16 cos t - sqrt(45^2 - (16 sin t)^2) - 131
// is at or above -170, which it leaves and comes back to where that equals -170 (bisected
// here). The minima are not the rounding inside that stretch but its start, and the closest is
// one of the minima (it named crank 0, an angle no minimum had: "min,282,0" then
// "closest,0,0").
TEST(Clearance, ANeedlePointRunsAlongItsGuide) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::example("lockstitch-arm-shaft")).ok());
  const Mechanism& m = k.mechanism();
  const Clearance c = findClearance(k, ClearancePart::of(*m.findPoint("needlebar.N")),
                                    ClearancePart::of(m.slotNamed(m.ground()->id, "needle")->id));
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const LD deg = M_PIl / 180;
  auto belowEnd = [&](LD phi) {
    const LD t = phi * deg;
    return -(16 * cosl(t) - sqrtl(45 * 45 - 256 * sinl(t) * sinl(t)) - 131 + 170);
  };
  const std::vector<double> leaves = risingRoots(belowEnd);
  const std::vector<double> enters = risingRoots([&](LD phi) { return -belowEnd(phi); });
  ASSERT_EQ(leaves.size(), 1u);
  ASSERT_EQ(enters.size(), 1u);
  EXPECT_TRUE(c.runsAlong);
  EXPECT_TRUE(c.crossings.empty());
  ASSERT_EQ(c.onPart.size(), 1u);
  EXPECT_NEAR(c.onPart[0].fromDeg, enters[0], 1e-9);
  EXPECT_NEAR(c.onPart[0].toDeg, leaves[0] + 360, 1e-9);
  ASSERT_EQ(c.minima.size(), 1u);
  EXPECT_NEAR(c.minima[0].crankDeg, enters[0], 1e-9);
  EXPECT_EQ(c.minima[0].distance, 0);
  EXPECT_EQ(c.closest.crankDeg, c.minima[0].crankDeg);
}

}  // namespace
}  // namespace linkage
