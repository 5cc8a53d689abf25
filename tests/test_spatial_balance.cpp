// Balancing a machine in space (linkage/balance.h) against optima found by hand: each
// counterweight turns in its body's plane, so it reaches only the shaking force's components in
// that plane; what lies along the normal of every counterweight's plane is beyond them, and the
// result says so with its peak.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

Mechanism read(const std::string& text) {
  const LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

BalanceResult balance(const Mechanism& m, std::vector<std::string> bodies, BalanceMeasure what) {
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  BalanceOptions opt;
  for (const std::string& b : bodies) opt.bodies.push_back(m.bodyNamed(b)->id);
  opt.measure = what;
  BalanceResult r = balanceShaking(k, opt);
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r;
}

// The peak of |shaking force| (or of its part along `along`) of m over `steps` angles a turn.
double sampledPeak(const Mechanism& m, int steps, const Vec3* along = nullptr) {
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  double peak = 0;
  for (int i = 0; i < steps; ++i) {
    EXPECT_TRUE(k.moveTo(360.0 * i / steps).ok());
    Vec3 F, M;
    shaking(k, F, M);
    peak = std::max(peak, along ? std::abs(F.dot(*along)) : F.norm());
  }
  return peak;
}

// A lone crank in a plane inclined 35 degrees, no gravity: its shaking force m w^2 c turns in
// that plane, and a counterweight of static moment -m c (kg mm, in the crank's plane) cancels it
// over the whole turn. Nothing is along the plane's normal.
TEST(SpatialBalance, ALoneCrankInAnInclinedPlaneIsCancelledExactly) {
  namespace ic = test::inclined_crank;
  const Mechanism m = read(ic::text(""));
  const double w = ic::kRpm * M_PI / 30, before = ic::kKg * ic::kCom.norm() * w * w / 1000;
  for (BalanceMeasure what : {BalanceMeasure::Force, BalanceMeasure::Fy, BalanceMeasure::Fz}) {
    const BalanceResult r = balance(m, {"crank"}, what);
    ASSERT_EQ(r.counterweights.size(), 1u);
    const Vec2 s = r.counterweights[0].staticMoment, want = -ic::kKg * ic::kCom;
    // Along y and z (the plane's y is (0, cos 35, sin 35)) the peak before is that part of it.
    const double part = what == BalanceMeasure::Force ? 1
                        : what == BalanceMeasure::Fy  ? std::cos(ic::kRho)
                                                      : std::sin(ic::kRho);
    EXPECT_NEAR(r.peakBefore, before * part, 1e-12 * before) << int(what);
    EXPECT_LT((s - want).norm(), 1e-9 * want.norm()) << int(what) << " " << s.transpose();
    EXPECT_LT(r.peakAfter, 1e-9 * before) << int(what);
    EXPECT_LE(r.gap(), 1e-9 * before);
    ASSERT_TRUE(r.unreached);
    EXPECT_LT((*r.unreached - ic::kN).norm(), 1e-15);
    EXPECT_LT(r.unreachedPeak, 1e-12 * before);
    EXPECT_LT(r.unreachedPeakBefore, 1e-12 * before);
  }
  // As the --out file writes it, the design does not shake.
  Mechanism balanced = m;
  addCounterweights(balanced, balance(m, {"crank"}, BalanceMeasure::Force).counterweights);
  EXPECT_LT(sampledPeak(balanced, 72), 1e-9 * before);
}

// The same crank under gravity [0, 0, -9.81]: the frame bears the weight of the crank and of the
// counterweight, (m + m_c) g in 3D, and the rotating m w^2 (c + s / m) in the plane. The peak of
// |F| is largest where the rotating part points along the weight's part in the plane:
// peak^2 = W^2 + rho^2 + 2 rho W sin(35). A kg mm more of |s| lowers rho by w^2 / 1000 N (so the
// peak by sin(35) w^2 / 1000 = 0.566 N) and adds g / R = 9.81 / 30 = 0.327 N of weight (at the
// farthest radius, R = 30 mm): the optimum cancels the rotation exactly with the lightest
// counterweight, s = -m c, m_c = m |c| / R, peak (m + m_c) g. Along the plane's normal the weight's
// part (m + m_c) g cos(35) is beyond the counterweight (it adds to it): the note's number.
TEST(SpatialBalance, UnderGravityTheWeightAlongTheNormalIsLeftAndSaid) {
  namespace ic = test::inclined_crank;
  const Mechanism m = read(ic::text("[0, 0, -9.81]"));
  const double w = ic::kRpm * M_PI / 30;
  ASSERT_GT(std::sin(ic::kRho) * w * w / 1000, 9.81 / 30);  // cancelling pays
  const BalanceResult r = balance(m, {"crank"}, BalanceMeasure::Force);
  const Counterweight& c = r.counterweights[0];
  const double mc = ic::kKg * ic::kCom.norm() / 30;
  EXPECT_NEAR(c.maxRadiusMm, 30, 1e-12);
  EXPECT_LT((c.staticMoment + ic::kKg * ic::kCom).norm(), 1e-6 * ic::kKg * ic::kCom.norm());
  EXPECT_NEAR(c.kg, mc, 1e-6 * mc);
  const double peak = (ic::kKg + mc) * 9.81;
  EXPECT_NEAR(r.peakAfter, peak, 1e-9 * peak);
  EXPECT_LE(r.gap(), 1e-9 * r.peakBefore);
  const double before = std::sqrt(
      std::pow(ic::kKg * 9.81, 2) + std::pow(ic::kKg * ic::kCom.norm() * w * w / 1000, 2) +
      2 * ic::kKg * 9.81 * ic::kKg * ic::kCom.norm() * w * w / 1000 * std::sin(ic::kRho));
  EXPECT_NEAR(r.peakBefore, before, 1e-9 * before);
  ASSERT_TRUE(r.unreached);
  EXPECT_NEAR(r.unreachedPeak, peak * std::cos(ic::kRho), 1e-9 * peak);
  EXPECT_NEAR(r.unreachedPeakBefore, ic::kKg * 9.81 * std::cos(ic::kRho), 1e-12 * peak);
  std::printf("[ inclined crank, g ] peak %.9g N (hand %.9g), along the normal %.9g N\n",
              r.peakAfter, peak, r.unreachedPeak);
}

// Crank one in the drawing plane drives crank two on a crossed shaft (its plane's normal x)
// through a bevel pair 1:1. A counterweight on one alone: F = C (cos, sin, 0)(theta + a) + K (0,
// cos, sin)(theta + b), K = m2 r2 w^2, C what one's own and its counterweight leave; |F|^2 = C^2
// + K^2 + C K (sin(2 theta + a + b) + sin(a - b)) peaks at C^2 + K^2 + C K (1 + sin(a - b)) >=
// C^2 + K^2: the optimum is C = 0 (s = -m1 c1), its peak K; two's force along z, K sin(theta +
// b), is beyond one's counterweight: its peak K. With a counterweight on each (planes that span
// space) the force is cancelled, and nothing is out of reach.
TEST(SpatialBalance, ACrankOnACrossedShaftLeavesItsPartAlongTheNormal) {
  namespace cc = test::crossed_cranks;
  const Mechanism m = read(cc::text());
  const double w = cc::kRpm * M_PI / 30, K = cc::kKg2 * cc::kR2 * w * w / 1000;
  BalanceResult r = balance(m, {"one"}, BalanceMeasure::Force);
  const Vec2 want = -cc::kKg1 * cc::kCom1;
  EXPECT_NEAR(r.peakAfter, K, 1e-9 * r.peakBefore);
  EXPECT_LE(r.gap(), 1e-9 * r.peakBefore);
  EXPECT_GE(r.peakAfter, K * (1 - 1e-12));
  EXPECT_LT((r.counterweights[0].staticMoment - want).norm(), 1e-3 * want.norm())
      << r.counterweights[0].staticMoment.transpose();
  ASSERT_TRUE(r.unreached);
  EXPECT_EQ(*r.unreached, Vec3::UnitZ());
  EXPECT_NEAR(r.unreachedPeak, K, 1e-12 * K);
  EXPECT_NEAR(r.unreachedPeakBefore, K, 1e-12 * K);
  const Vec3 z = Vec3::UnitZ();
  EXPECT_NEAR(sampledPeak(m, 3600, &z), K, 1e-6 * K);  // what the samples of the design show
  std::printf("[ crossed cranks ] peak %.12g N, K %.12g N, along z %.12g N, s (%.6g, %.6g)\n",
              r.peakAfter, K, r.unreachedPeak, r.counterweights[0].staticMoment.x(),
              r.counterweights[0].staticMoment.y());
  // fx: two's force has none; one's counterweight cancels it.
  r = balance(m, {"one"}, BalanceMeasure::Fx);
  EXPECT_LT(r.peakAfter, 1e-9 * r.peakBefore);
  // fz: beyond one's counterweight, which is then none.
  r = balance(m, {"one"}, BalanceMeasure::Fz);
  EXPECT_NEAR(r.peakAfter, K, 1e-12 * K);
  EXPECT_TRUE(r.counterweights[0].none()) << r.counterweights[0].staticMoment.transpose();
  // A counterweight on each: -m c on each cancels all.
  r = balance(m, {"one", "two"}, BalanceMeasure::Force);
  EXPECT_LT(r.peakAfter, 1e-9 * r.peakBefore);
  EXPECT_FALSE(r.unreached);
  EXPECT_LT((r.counterweights[1].staticMoment - Vec2(-cc::kKg2 * cc::kR2, 0)).norm(),
            1e-9 * cc::kKg2 * cc::kR2);
  Mechanism balanced = m;
  addCounterweights(balanced, r.counterweights);
  EXPECT_LT(sampledPeak(balanced, 72), 1e-9 * r.peakBefore);
}

// A planar machine has no fz to balance: refused naming it.
TEST(SpatialBalance, APlanarMachinesFzIsRefused) {
  const Mechanism m = test::example("slider-crank-22a-masses");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  BalanceOptions opt;
  opt.bodies = {m.bodyNamed("crank")->id};
  opt.measure = BalanceMeasure::Fz;
  const Status s = balanceShaking(k, opt).status;
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("fz is the shaking force along the drawing's normal"), std::string::npos)
      << s.message;
}

}  // namespace
}  // namespace linkage
