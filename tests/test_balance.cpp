// Exact balancing (linkage/balance.h) against closed forms: the counterweights that make a
// four-bar satisfy the Berkof-Lowen conditions (zero shaking force), the central slider-crank's
// crank counterweight (the peak of the vertical shaking force), and against an independent
// search for the peak of |F| (nothing does better than the programme's optimum).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

Kinematics loaded(const Mechanism& m) {
  Kinematics k;
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

TEST(Balance, FindsTheBerkofLowenCounterweightsOfAFourBar) {
  // Berkof-Lowen: the coupler's centre of mass at k3 along A->B; the crank's at
  // m3 (k3 - 1) / m2 along O2->A, the rocker's at -m3 k3 / m4 along O4->B: the whole
  // mechanism's centre of mass stays put. Drawn with the crank's centre of mass at A and the
  // rocker's at B instead, the counterweights must put them back.
  using C = std::complex<double>;
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30, true, 0, 0, Direction::Ccw, 600);
  Mechanism m = f.m;
  const Vec2 O2 = m.point(f.O2)->pos, A = m.point(f.A)->pos, B = m.point(f.B)->pos,
             O4 = m.point(f.O4)->pos;
  auto z = [](const Vec2& v) { return C(v.x(), v.y()); };
  auto v2 = [](C c) { return Vec2(c.real(), c.imag()); };
  const double m2 = 0.3, m3 = 0.2, m4 = 0.25;
  const C k3(0.4, 0.1), k2 = m3 * (k3 - 1.0) / m2, k4 = -m3 * k3 / m4;
  const Vec2 c2 = v2(z(O2) + k2 * z(A - O2)), c4 = v2(z(O4) + k4 * z(B - O4));
  m.body(f.crank)->mass = Mass{m2, A, 40, ""};
  m.body(f.coupler)->mass = Mass{m3, v2(z(A) + k3 * z(B - A)), 90, ""};
  m.body(f.rocker)->mass = Mass{m4, B, 60, ""};
  Kinematics k = loaded(m);
  BalanceOptions opt;
  opt.bodies = {f.crank, f.rocker};
  opt.measure = BalanceMeasure::Force;
  const BalanceResult r = balanceShaking(k, opt);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.counterweights.size(), 2u);
  const Vec2 want2 = m2 * (c2 - A), want4 = m4 * (c4 - B);
  EXPECT_LT((r.counterweights[0].staticMoment - want2).norm(), 1e-9 * want2.norm());
  EXPECT_LT((r.counterweights[1].staticMoment - want4).norm(), 1e-9 * want4.norm());
  EXPECT_GT(r.peakBefore, 1);
  EXPECT_LT(r.peakAfter, 1e-9 * r.peakBefore);
  EXPECT_GE(r.gap(), -1e-12 * r.peakBefore);
  // An editor's kinematics with accelerations off (no view shows them) balances the same.
  Kinematics off = k;
  off.setAccelerations(false);
  const BalanceResult r2 = balanceShaking(off, opt);
  ASSERT_TRUE(r2.status.ok()) << r2.status.message;
  EXPECT_EQ(r2.counterweights[0].staticMoment, r.counterweights[0].staticMoment);
  // The balanced design, as --out writes it, shakes no more than that.
  addCounterweights(m, r.counterweights);
  Kinematics b = loaded(m);
  for (double deg = 0; deg < 360; deg += 7) {
    ASSERT_TRUE(b.moveTo(deg).ok());
    Vec2 F;
    double M;
    shaking(b, F, M);
    EXPECT_LT(F.norm(), 1e-8 * r.peakBefore) << deg;
  }
}

TEST(Balance, CentralSliderCrankVerticalPeakIsItsClosedForm) {
  // Only the block (mass m) moves with mass. Its vertical shaking force is m a_B: m r w^2 (1 +
  // lambda) at the top dead centre, m r w^2 (1 - lambda) at the bottom, and m r w^2 lambda /
  // sqrt(1 - lambda^2) where the crank is across the guide (cos = 0), which no crank
  // counterweight changes. The best counterweight (m r opposite the pin) leaves the peak at that.
  for (const double lambda : {0.3, 0.5}) {
    const double r = 15, l = r / lambda, mb = 0.12;
    test::SliderCrank s = test::sliderCrank(r, l, 0, 90, Direction::Ccw, 1200);
    s.m.body(s.slider)->mass = Mass{mb, s.m.point(s.B)->pos, 0, ""};
    Kinematics k = loaded(s.m);
    const double w = k.omega();
    BalanceOptions opt;
    opt.bodies = {s.crank};
    opt.measure = BalanceMeasure::Fy;
    const BalanceResult res = balanceShaking(k, opt);
    ASSERT_TRUE(res.status.ok()) << res.status.message;
    const double unit = mb * r * w * w / 1000;  // N
    EXPECT_NEAR(res.peakBefore, unit * (1 + lambda), 1e-9 * unit);
    EXPECT_NEAR(res.peakAfter, unit * lambda / std::sqrt(1 - lambda * lambda), 1e-9 * unit)
        << lambda;
    EXPECT_NEAR(res.lowerBound, res.peakAfter, 1e-9 * unit);
  }
}

TEST(Balance, NoCounterweightsWithinTheBoundDoBetterThanTheOptimum) {
  // A slider-crank with masses on the crank, the rod and the block, a counterweight on the crank
  // within 2 kg mm, |F|: a search over the disk of static moments (independent of the linear
  // programme) finds no smaller peak.
  test::SliderCrank s = test::sliderCrank(15, 45, 4, 60, Direction::Cw, 900);
  s.m.body(s.crank)->mass = Mass{0.08, Vec2(6, 9), 20, ""};
  s.m.body(s.rod)->mass = Mass{0.05, (s.m.point(s.A)->pos + s.m.point(s.B)->pos) / 2, 30, ""};
  s.m.body(s.slider)->mass = Mass{0.12, s.m.point(s.B)->pos, 0, ""};
  Kinematics k = loaded(s.m);
  BalanceOptions opt;
  opt.bodies = {s.crank};
  opt.measure = BalanceMeasure::Force;
  opt.maxKgMm = 2;
  const BalanceResult r = balanceShaking(k, opt);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.counterweights[0].kgMm(), 2 * (1 + 1e-12));
  EXPECT_LT(r.gap(), 1e-9 * r.peakBefore);
  // The peak for static moments on a polar grid of the disk, at 720 crank angles.
  Kinematics w = k;
  std::vector<Vec2> F0;
  std::vector<Eigen::Matrix2d> A;
  for (int i = 0; i < 720; ++i) {
    ASSERT_TRUE(w.moveTo(i * 0.5).ok());
    Vec2 F;
    double M;
    shaking(w, F, M);
    F0.push_back(F);
    const double om = w.bodyOmega(s.crank), al = w.bodyAlpha(s.crank);
    const Rot R = Rot::of(w.bodyAngle(s.crank));
    Eigen::Matrix2d Mm, Rm;
    Mm << om * om, al, -al, om * om;
    Rm << R.c, -R.s, R.s, R.c;
    A.push_back(1e-3 * Mm * Rm);
  }
  double best = INFINITY;
  for (double rad = 0; rad <= 2; rad += 0.05)
    for (double ang = 0; ang < 2 * M_PI; ang += M_PI / 90) {
      const Vec2 sm = rad * Vec2(std::cos(ang), std::sin(ang));
      double peak = 0;
      for (size_t i = 0; i < F0.size(); ++i) peak = std::max(peak, (F0[i] + A[i] * sm).norm());
      best = std::min(best, peak);
    }
  EXPECT_LE(r.peakAfter, best * (1 + 1e-9));
  EXPECT_LT(r.peakAfter, 0.9 * r.peakBefore);
}

TEST(Balance, ACounterweightNeedsABodyPinnedToTheGround) {
  test::SliderCrank s = test::sliderCrank(15, 45, 0, 60);
  Kinematics k = loaded(s.m);
  BalanceOptions opt;
  opt.bodies = {s.rod};
  const BalanceResult r = balanceShaking(k, opt);
  EXPECT_EQ(r.status.code, StatusCode::BadModel);
  EXPECT_EQ(r.status.message,
            "body 'rod' is not pinned to the ground: a counterweight's static moment is measured "
            "from that pivot");
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

// A crank alone, 2 kg at r = 100 mm (its farthest point A: R = 100), under gravity (0, -9.81)
// m/s^2, turning at w: its shaking force is the rotating 1e-3 w^2 S (S = 200 kg mm plus the
// counterweight's static moment s, opposite) and the constant weight -(2 + m_c) g, with the
// counterweight's mass m_c >= |s| / R. The peak of |F| (and of |fy|) is
//   1e-3 w^2 |200 - |s|| + 9.81 (2 + |s| / 100):
// each kg mm of counterweight takes 1e-3 w^2 N off the rotating part and puts 0.0981 N of weight
// on. Above w = 9.9 rad/s the whole 200 kg mm is cancelled (peak 4 g = 39.24 N: the weight of
// 2 + 2 kg); below it no counterweight lowers the peak, and none is placed (a balance that left
// the weight out placed the 200 kg mm all the same: its peak "after" was 2 g, applied 4 g, above
// the peak before).
Mechanism gravityCrank(double rpm) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), c = m.addBody("crank");
  const JointId drive = m.addPin(m.addPoint(g, "O", Vec2(0, 0)), m.addPoint(c, "O", Vec2(0, 0)));
  m.addPoint(c, "A", Vec2(100, 0));
  m.body(c)->mass = Mass{2, Vec2(100, 0), 0, ""};
  m.gravity = Vec2(0, -9.81);
  m.driver = Driver{drive, rpm, Direction::Ccw, 0, ""};
  return m;
}

TEST(Balance, UnderGravityTheCounterweightsWeightIsPartOfThePeak) {
  for (const BalanceMeasure measure : {BalanceMeasure::Force, BalanceMeasure::Fy}) {
    const Mechanism fast = gravityCrank(600);
    Kinematics k = loaded(fast);
    BalanceOptions opt;
    opt.bodies = {fast.bodyNamed("crank")->id};
    opt.measure = measure;
    const BalanceResult r = balanceShaking(k, opt);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const double w = 600 * 2 * M_PI / 60, before = 1e-3 * w * w * 200 + 2 * 9.81;
    EXPECT_NEAR(r.peakBefore, before, 1e-9 * before);
    EXPECT_LT((r.counterweights[0].staticMoment - Vec2(-200, 0)).norm(), 1e-8 * 200);
    EXPECT_NEAR(r.counterweights[0].kg, 2, 1e-8);
    EXPECT_NEAR(r.counterweights[0].radiusMm(), 100, 1e-8);
    EXPECT_NEAR(r.peakAfter, 4 * 9.81, 1e-9 * before);
    // Slow, the weight costs more than the rotation: the peak is left as it is.
    const Mechanism slow = gravityCrank(60);
    Kinematics ks = loaded(slow);
    opt.bodies = {slow.bodyNamed("crank")->id};
    const BalanceResult rs = balanceShaking(ks, opt);
    ASSERT_TRUE(rs.status.ok()) << rs.status.message;
    const double ws = 2 * M_PI, beforeSlow = 1e-3 * ws * ws * 200 + 2 * 9.81;
    EXPECT_NEAR(rs.peakBefore, beforeSlow, 1e-9 * beforeSlow);
    EXPECT_LT(rs.counterweights[0].kgMm(), 1e-8 * 200);
    EXPECT_LT(rs.counterweights[0].kg, 1e-8);
    EXPECT_NEAR(rs.peakAfter, beforeSlow, 1e-9 * beforeSlow);
  }
}

// The same crank with a constant 50 N upward load at its pivot: the frame feels 50 - 9.81 (2 +
// m_c) N up plus the rotating part. Both vanish with m_c = 50 / 9.81 - 2 kg and s = -200 kg mm:
// a counterweight heavier than 200 kg mm needs at R, so nearer the pivot (200 / m_c mm). The
// peak after is 0.
TEST(Balance, AHeavierCounterweightNearerThePivotWhenItsWeightHelps) {
  Mechanism m = gravityCrank(600);
  Load up;
  up.point = m.pointNamed(m.bodyNamed("crank")->id, "O")->id;
  up.forceN = Vec2(0, 50);
  m.addLoad(up);
  Kinematics k = loaded(m);
  BalanceOptions opt;
  opt.bodies = {m.bodyNamed("crank")->id};
  const BalanceResult r = balanceShaking(k, opt);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double mc = 50 / 9.81 - 2;
  EXPECT_LT((r.counterweights[0].staticMoment - Vec2(-200, 0)).norm(), 1e-7 * 200);
  EXPECT_NEAR(r.counterweights[0].kg, mc, 1e-7 * mc);
  EXPECT_NEAR(r.counterweights[0].radiusMm(), 200 / mc, 1e-6);
  EXPECT_LT(r.peakAfter, 1e-7 * r.peakBefore);
  // Applied as a mass, the design shakes its frame with what the balance said.
  addCounterweights(m, r.counterweights);
  Kinematics b = loaded(m);
  for (double deg = 0; deg < 360; deg += 13) {
    ASSERT_TRUE(b.moveTo(deg).ok());
    Vec2 F;
    double M;
    shaking(b, F, M);
    EXPECT_LT(F.norm(), 1e-7 * r.peakBefore) << deg;
  }
}

}  // namespace
}  // namespace linkage
