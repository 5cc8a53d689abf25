// Limit positions and stroke (linkage/limits.h) against closed forms: a four-bar's rocker and an
// offset slider-crank's slider are at their extremes where the crank and the coupler (rod) are
// collinear; a coupler point's and the Wanzer needle's extremes against roots of the
// independent references' velocities, found by bisection in __float128.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/limits.h"
#include "mechanisms.h"
#include "reference/four_bar.h"
#include "reference/slider_crank.h"
#include "reference/wanzer.h"

namespace linkage {
namespace {

using Q = __float128;
using linkref::Vec2;

constexpr double kTolDeg = 1e-9;  // the crank angle of every extreme
constexpr double kTolMm = 1e-9;   // and the value there (mm, or degrees for a body)

using test::example;

// The crank angle (degrees in [0, 360)) of an absolute crank direction theta, for a crank drawn
// at theta0 turning in direction s.
double crankOf(Q theta, Q theta0, int s) {
  Q d = Q(s) * (theta - theta0) * 180 / linkref::pi<Q>();
  while (d < 0) d += 360;
  while (d >= 360) d -= 360;
  return static_cast<double>(d);
}

// The root of f in [a, b] (a sign change), by bisection in __float128.
template <class F>
Q bisect(F f, Q a, Q b) {
  const bool up = f(a) < 0;
  for (int i = 0; i < 200 && b - a > Q(1e-25); ++i) {
    const Q m = (a + b) / 2;
    ((f(m) < 0) == up ? a : b) = m;
  }
  return (a + b) / 2;
}

// Every sign change of f over [0, 360) degrees, sampled every 0.25 degree, bisected.
template <class F>
std::vector<Q> rootsDeg(F f) {
  std::vector<Q> out;
  for (int i = 0; i < 4 * 360; ++i) {
    const Q a = Q(i) / 4, b = Q(i + 1) / 4;
    if ((f(a) < 0) != (f(b) < 0)) out.push_back(bisect(f, a, b));
  }
  return out;
}

double periodicGap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360 - d);
}

struct FourBarCase {
  double d, r2, r3, r4, crankDeg;
  bool open;
  Direction dir;
};

linkref::FourBarParams<Q> reference(const FourBarCase& c) {
  linkref::FourBarParams<Q> p;
  p.O2 = {Q(0), Q(0)};
  p.O4 = {Q(c.d), Q(0)};
  p.r2 = c.r2;
  p.r3 = c.r3;
  p.r4 = c.r4;
  p.theta20 = Q(c.crankDeg) * linkref::pi<Q>() / 180;
  p.s = c.dir == Direction::Ccw ? 1 : -1;
  p.omega = linkref::rpm_to_rad_s(Q(60));
  p.branch = c.open ? linkref::FourBarBranch::kOpen : linkref::FourBarBranch::kCrossed;
  return p;
}

const FourBarCase kFourBars[] = {
    {60, 20, 70, 50, 60, true, Direction::Ccw},
    {80, 25, 90, 60, 200, false, Direction::Cw},
    {100, 30, 85, 70, 10, true, Direction::Cw},
};

TEST(Limits, FourBarRockerIsAtItsExtremesWhereCrankAndCouplerAreCollinear) {
  for (const FourBarCase& c : kFourBars) {
    const test::FourBar f = test::fourBar(c.d, c.r2, c.r3, c.r4, c.crankDeg, c.open, 0, 0, c.dir);
    Kinematics k;
    ASSERT_TRUE(k.load(f.m).ok());
    const Limits lim = findLimits(k, LimitMeasure::angleOf(f.rocker));
    ASSERT_TRUE(lim.status.ok()) << lim.status.message;
    ASSERT_EQ(lim.extremes.size(), 2u);
    const linkref::FourBarParams<Q> p = reference(c);
    const Q theta40 = linkref::four_bar(p, Q(0)).theta4;
    // B at |O2 B| = r3 + r2 (stretched: A between O2 and B) or r3 - r2 (folded), on the
    // circle of radius r4 about O4; of the two intersections, the one on the drawn branch.
    for (const int stretched : {1, -1}) {
      const Q rho = Q(c.r3) + stretched * Q(c.r2), d = c.d, r4 = c.r4;
      const Q x = (rho * rho - r4 * r4 + d * d) / (2 * d), h = linkref::sqrt(rho * rho - x * x);
      double best = 1e300, crank = 0;
      for (const Q y : {h, -h}) {
        const Q theta = linkref::atan2(stretched * y, stretched * x);
        const double deg = crankOf(theta, p.theta20, p.s);
        const auto st = linkref::four_bar(p, Q(deg) * linkref::pi<Q>() / 180);
        const double miss = static_cast<double>(linkref::norm(st.B - Vec2<Q>{x, y}));
        if (miss < best) best = miss, crank = deg;
      }
      ASSERT_LT(best, 1e-6);  // the drawn branch goes through one of them
      const LocalExtreme* e = nullptr;
      for (const LocalExtreme& x : lim.extremes)
        if (periodicGap(x.crankDeg, crank) < 1e-3) e = &x;
      ASSERT_NE(e, nullptr) << "no extreme near " << crank;
      EXPECT_LT(periodicGap(e->crankDeg, crank), kTolDeg) << e->crankDeg << " vs " << crank;
      const Q q = Q(crank) * linkref::pi<Q>() / 180;
      const Q value = (linkref::four_bar(p, q).theta4 - theta40) * 180 / linkref::pi<Q>();
      EXPECT_NEAR(e->value, static_cast<double>(value), kTolMm);
    }
    EXPECT_EQ(lim.extremes[0].max, !lim.extremes[1].max);
    EXPECT_NEAR(lim.stroke, lim.max - lim.min, 0);
    EXPECT_GT(lim.stroke, 0);
  }
}

TEST(Limits, CouplerPointAlongADirectionMatchesTheReferenceVelocityRoots) {
  const FourBarCase c = kFourBars[0];
  const test::FourBar f = test::fourBar(c.d, c.r2, c.r3, c.r4, c.crankDeg, c.open, 35, 25, c.dir);
  linkref::FourBarParams<Q> p = reference(c);
  p.px = 35;
  p.py = 25;
  const Vec2<Q> dir{Q(3) / 5, Q(-4) / 5};
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const Limits lim = findLimits(k, LimitMeasure::along(f.P, linkage::Vec2(3, -4)));
  ASSERT_TRUE(lim.status.ok()) << lim.status.message;
  const std::vector<Q> roots = rootsDeg([&](Q deg) {
    return linkref::dot(linkref::four_bar(p, deg * linkref::pi<Q>() / 180).vP, dir);
  });
  ASSERT_EQ(lim.extremes.size(), roots.size());
  ASSERT_GE(roots.size(), 2u);
  for (size_t i = 0; i < roots.size(); ++i) {
    EXPECT_LT(periodicGap(lim.extremes[i].crankDeg, static_cast<double>(roots[i])), kTolDeg);
    const auto st = linkref::four_bar(p, roots[i] * linkref::pi<Q>() / 180);
    EXPECT_NEAR(lim.extremes[i].value, static_cast<double>(linkref::dot(st.P, dir)), kTolMm);
    // A maximum where the velocity along the direction turns from positive to negative.
    const auto before = linkref::four_bar(p, (roots[i] - Q(0.01)) * linkref::pi<Q>() / 180);
    EXPECT_EQ(lim.extremes[i].max, linkref::dot(before.vP, dir) > 0);
  }
}

TEST(Limits, OffsetSliderCrankStrokeIsWhereCrankAndRodAreCollinear) {
  for (const bool pinInSlot : {false, true})
    for (const Direction dir : {Direction::Ccw, Direction::Cw}) {
      const double r = 15, l = 50, e = 8, drawn = 20;
      const test::SliderCrank s = test::sliderCrank(r, l, e, drawn, dir, 60, pinInSlot);
      EXPECT_EQ(defaultDirection(s.m, s.B), linkage::Vec2(0, 1));
      Kinematics k;
      ASSERT_TRUE(k.load(s.m).ok());
      const Limits lim = findLimits(k, LimitMeasure::along(s.B, defaultDirection(s.m, s.B)));
      ASSERT_TRUE(lim.status.ok()) << lim.status.message;
      ASSERT_EQ(lim.extremes.size(), 2u);
      const int sgn = dir == Direction::Ccw ? 1 : -1;
      // Top: A on the ray O->B, |OB| = l + r; bottom: A opposite, |OB| = l - r.
      for (const int stretched : {1, -1}) {
        const Q ob = Q(l) + stretched * Q(r), y = linkref::sqrt(ob * ob - Q(e) * Q(e));
        const Q theta = linkref::atan2(stretched * y, stretched * Q(e));
        const double crank = crankOf(theta, Q(drawn) * linkref::pi<Q>() / 180, sgn);
        const LocalExtreme& x = lim.extremes[lim.extremes[0].max == (stretched > 0) ? 0 : 1];
        EXPECT_EQ(x.max, stretched > 0);
        EXPECT_LT(periodicGap(x.crankDeg, crank), kTolDeg) << x.crankDeg << " vs " << crank;
        EXPECT_NEAR(x.value, static_cast<double>(y), kTolMm);
      }
      const double top = std::sqrt((l + r) * (l + r) - e * e),
                   bottom = std::sqrt((l - r) * (l - r) - e * e);
      EXPECT_NEAR(lim.stroke, top - bottom, kTolMm);
      EXPECT_GT(lim.stroke, 2 * r);  // an offset lengthens the stroke
    }
}

TEST(Limits, WanzerDwellHasFourExtremesMatchingTheReference) {
  const Mechanism m = example("wanzer-inversion-2");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  linkref::Wanzer<Q> w(linkref::wanzer_homework_params<Q>(linkref::WanzerInversion::k2));
  const std::vector<Q> roots = rootsDeg([&](Q deg) { return w.at_deg(deg).vG.y; });
  ASSERT_EQ(roots.size(), 4u);  // min, max, min, max: the needle dwells between the middle two
  // 5 sampling intervals put the middle pair (153 and 205 degrees) in one interval of 72.
  for (const int steps : {360, 36, 5}) {
    LimitOptions opt;
    opt.steps = steps;
    const Limits lim = findLimits(k, LimitMeasure::along(*m.findPoint("needlebar.G"), {0, 1}), opt);
    ASSERT_TRUE(lim.status.ok()) << lim.status.message;
    ASSERT_EQ(lim.extremes.size(), 4u) << steps;
    for (size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(lim.extremes[i].max, i % 2 == 1);
      EXPECT_NEAR(lim.extremes[i].crankDeg, static_cast<double>(roots[i]), kTolDeg) << steps;
      EXPECT_NEAR(lim.extremes[i].value, static_cast<double>(w.at_deg(roots[i]).G.y), kTolMm);
    }
    EXPECT_NEAR(lim.stroke, static_cast<double>(w.at_deg(roots[3]).G.y - w.at_deg(roots[0]).G.y),
                kTolMm);
  }
  EXPECT_EQ(k.crankDeg(), 0);  // the caller's kinematics did not move
}

TEST(Limits, StillPointsTurningBodiesAndFailures) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Limits lim = findLimits(k, LimitMeasure::along(f.O4, {0, 1}));
  ASSERT_TRUE(lim.status.ok());
  EXPECT_FALSE(lim.moves);
  EXPECT_TRUE(lim.extremes.empty());
  EXPECT_EQ(lim.stroke, 0);
  lim = findLimits(k, LimitMeasure::angleOf(f.crank));  // turns fully: no extreme, 360
  ASSERT_TRUE(lim.status.ok());
  EXPECT_TRUE(lim.extremes.empty());
  EXPECT_NEAR(lim.stroke, 360, 1e-9);
  // Unknown ids, a zero direction, too few steps.
  Mechanism other = f.m;
  const BodyId stranger = other.addBody("stranger");
  EXPECT_EQ(findLimits(k, LimitMeasure::angleOf(stranger)).status.code, StatusCode::BadModel);
  EXPECT_EQ(findLimits(k, LimitMeasure::along(f.P, {0, 0})).status.code, StatusCode::BadModel);
  LimitOptions few;
  few.steps = 3;
  EXPECT_EQ(findLimits(k, LimitMeasure::along(f.P, {0, 1}), few).status.code, StatusCode::BadModel);
  // A non-Grashof four-bar: the crank stops; the status says where.
  const test::FourBar locked = test::fourBar(60, 40, 50, 45, 70);
  ASSERT_TRUE(k.load(locked.m).ok());
  lim = findLimits(k, LimitMeasure::along(locked.B, {0, 1}));
  EXPECT_EQ(lim.status.code, StatusCode::Unreachable) << lim.status.message;
  ASSERT_TRUE(lim.status.lastReachedDeg.has_value());
  EXPECT_GT(*lim.status.lastReachedDeg, 0);
  EXPECT_LT(*lim.status.lastReachedDeg, 360);
}

TEST(Limits, DefaultDirectionIsTheGroundSlotsPointingUpOrRight) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), block = m.addBody("block");
  const SlotId down = m.addSlot(g, "down", {0, 10}, {3, -30});
  const SlotId left = m.addSlot(g, "left", {10, 0}, {-30, 1});
  const PointId a = m.addPoint(block, "A", {0, 0}), b = m.addPoint(block, "B", {5, 5});
  const BodyId pin = m.addBody("pin");
  const PointId c = m.addPoint(pin, "C", {1, 0});
  m.addSlider(a, down);
  m.addPinInSlot(c, left);
  const linkage::Vec2 up = linkage::Vec2(-3, 40).normalized();
  EXPECT_EQ(defaultDirection(m, a), up);
  EXPECT_EQ(defaultDirection(m, b), up);  // every point of a block moves along its slot
  EXPECT_EQ(defaultDirection(m, c), linkage::Vec2(40, -1).normalized());
  EXPECT_EQ(defaultDirection(m, m.addPoint(pin, "D", {0, 0})), linkage::Vec2(0, 1));
}

}  // namespace
}  // namespace linkage
