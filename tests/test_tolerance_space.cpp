// Tolerances on machines in space (linkage/tolerance.h): the first-order band of a point's world
// x, y and z is the sum of |d/dp| T from Sensitivity's own World rows; a depth alone moves a
// crank's ball along z by exactly its tolerance; a rod's length moves the RSSR's rocker as its
// closed form's derivative says; Monte Carlo with tiny tolerances agrees with first order within
// statistical error; a play whose point is on the ground is refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "linkage/tolerance.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

ToleranceSpec specOf(const Mechanism& m, const char* point,
                     const std::vector<std::pair<std::string, double>>& tols) {
  ToleranceSpec spec;
  spec.point = *m.findPoint(point);
  for (const auto& [name, t] : tols) spec.tolerances.push_back({name, t, false});
  spec.steps = 36;
  return spec;
}

// The band at a few angles against the Sensitivity's rows summed here.
TEST(ToleranceSpace, FirstOrderIsTheSumOfTheWorldRows) {
  const Mechanism m = test::example("overedge-machine");
  const std::vector<std::pair<std::string, double>> tols = {
      {"main.A1.depth", 0.05}, {"ball-rod:main.A1.length", 0.1}, {"planes.rocker.origin.z", 0.08},
      {"ground.H.z", 0.04},    {"ground.u.offset", 0.03},        {"ground.u.angle", 0.1},
      {"needlerock.H-B", 0.02}};
  ToleranceSpec spec = specOf(m, "needlearm.N", tols);
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.space);
  std::vector<Dimension> cols;
  for (const auto& [name, t] : tols)
    for (const Dimension& d : dimensions(m))
      if (d.name == name) cols.push_back(d);
  ASSERT_EQ(cols.size(), tols.size());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, cols, Sensitivity::Space::World).ok());
  for (int i : {0, 5, 13, 22, 31}) {
    const ToleranceRow& row = r.rows[i];
    ASSERT_TRUE(k.moveTo(row.crankDeg).ok() && s.at(k).ok());
    ASSERT_TRUE(row.firstOrder);
    Vec3 worst = Vec3::Zero(), rss2 = Vec3::Zero();
    for (size_t d = 0; d < cols.size(); ++d) {
      const Vec3 g = s.point3(k, spec.point, static_cast<int>(d)) * tols[d].second;
      worst += g.cwiseAbs();
      rss2 += g.cwiseProduct(g);
    }
    EXPECT_LT((row.nominal - k.motionInSpace(spec.point).position).norm(), 1e-12);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(row.worst[c], worst[c], 1e-12 * std::max(1.0, worst[c])) << i << " " << c;
      EXPECT_NEAR(row.rss[c], std::sqrt(rss2[c]), 1e-12) << i << " " << c;
    }
    EXPECT_GT(worst.z(), 1e-3) << i;  // z has a band of its own
  }
}

// The RSSR's crank ball A turns about z at its depth: with its depth alone varying its band of z
// is the tolerance exactly (first order and every sample), of x and y none.
TEST(ToleranceSpace, ADepthAloneMovesTheCranksBallAlongZByItsTolerance) {
  const Mechanism m = parseMechanism(test::rssrText()).mechanism.value();
  ToleranceSpec spec = specOf(m, "crank.A", {{"crank.A.depth", 0.25}});
  spec.samples = 40;
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.used, 40);
  for (const ToleranceRow& row : r.rows) {
    EXPECT_NEAR(row.nominal.z(), test::rssr::kDepth, 1e-12);
    EXPECT_NEAR(row.worst.z(), 0.25, 1e-12) << row.crankDeg;
    EXPECT_NEAR(row.rss.z(), 0.25, 1e-12) << row.crankDeg;
    EXPECT_NEAR(row.worst.x(), 0, 1e-12);
    EXPECT_NEAR(row.worst.y(), 0, 1e-12);
    EXPECT_LE(row.hi.z(), test::rssr::kDepth + 0.25 + 1e-12);
    EXPECT_GE(row.lo.z(), test::rssr::kDepth - 0.25 - 1e-12);
    EXPECT_LT(row.hi.x() - row.lo.x(), 1e-9);
  }
}

// The rocker point C with the rod's length alone varying: d C/d l = C'(psi) d psi/d l, with
// d psi/d l = 2 l / F_psi from F = |A - C|^2 - l^2 (test::rockerAt's derivation): the band of
// each world component is |d C/d l| T.
TEST(ToleranceSpace, ARodsLengthMovesTheRockerAsItsClosedFormSays) {
  using namespace test::rssr;
  const Mechanism m = parseMechanism(test::rssrText()).mechanism.value();
  const double T = 0.2, l = test::rssrRod();
  const ToleranceSpec spec = specOf(m, "rocker.C", {{"ball-rod:crank.A.length", T}});
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  double near = kPsi0;
  for (const ToleranceRow& row : r.rows) {
    const double phi = row.crankDeg * M_PI / 180;
    const test::Rocker rk = test::rockerNear(phi, near, l);
    near = rk.psi;
    const Vec3 C = kH + kW * (std::cos(rk.psi) * kX + std::sin(rk.psi) * kY);
    const Vec3 C1 = kW * (-std::sin(rk.psi) * kX + std::cos(rk.psi) * kY);
    const double Fpsi = -2 * (test::rssrBall(phi, kR) - C).dot(C1);
    const Vec3 dC = C1 * (2 * l / Fpsi);
    EXPECT_LT((row.nominal - C).norm(), 1e-10) << row.crankDeg;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(row.worst[c], std::abs(dC[c]) * T, 1e-9) << row.crankDeg << " " << c;
  }
}

// Tiny tolerances on the overedge machine's needle: the samples' spread is first order's
// (uniform changes: sigma^2 = sum (g T)^2 / 3) within statistical error, their mean the nominal,
// every sample inside the worst case; nothing fails.
TEST(ToleranceSpace, MonteCarloAgreesWithFirstOrder) {
  const Mechanism m = test::example("overedge-machine");
  ToleranceSpec spec = specOf(m, "needlearm.N",
                              {{"main.A1.depth", 1e-3},
                               {"ball-rod:main.A1.length", 2e-3},
                               {"planes.rocker.origin.x", 1e-3},
                               {"ground.u.offset", 1e-3},
                               {"needlearm.G-N", 1e-3}});
  spec.steps = 12;
  spec.samples = 400;
  spec.seed = 11;
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.failed, 0) << r.firstFailure;
  EXPECT_TRUE(r.nonlinearDeg.empty());
  const double n = r.used;
  for (const ToleranceRow& row : r.rows)
    for (int c = 0; c < 3; ++c) {
      const double sigma = row.sigma[c], eps = 1e-9;
      EXPECT_NEAR(row.sd[c], sigma, 0.2 * sigma + eps) << row.crankDeg << " " << c;
      EXPECT_NEAR(row.mean[c], row.nominal[c], 5 * sigma / std::sqrt(n) + eps) << row.crankDeg;
      EXPECT_LE(row.hi[c] - row.nominal[c], 1.01 * row.worst[c] + eps) << row.crankDeg;
      EXPECT_LE(row.nominal[c] - row.lo[c], 1.01 * row.worst[c] + eps) << row.crankDeg;
    }
  EXPECT_NEAR(r.stroke.sd, r.stroke.sigma, 0.2 * r.stroke.sigma + 1e-9);
}

// A play opens its pin in the pin's plane: of a pin whose free point is on a moving body it is
// carried; of one whose free point is on the ground (x, y the world's) it is refused by name.
TEST(ToleranceSpace, APlayOnAGroundPointIsRefusedByName) {
  const Mechanism m = test::example("overedge-machine");
  ToleranceSpec spec = specOf(m, "lower.P", {});
  spec.tolerances.push_back({"needlerock.C-needlelink.C", 0.01, true});
  ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  spec.tolerances = {{"lower.K-ground.K", 0.01, true}};
  r = tolerances(m, spec);
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.message.find("pin lower.K-ground.K"), std::string::npos) << r.status.message;
}

}  // namespace
}  // namespace linkage
