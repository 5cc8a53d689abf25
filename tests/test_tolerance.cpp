// Tolerances carried through the motion (linkage/tolerance.h): the first-order band against a
// four-bar's closed form differentiated by complex step, the Monte Carlo against first order
// where first order holds (small tolerances; bounds of several standard errors at a fixed seed),
// a crank-rocker whose tolerances span its toggle (first order fails there, and the result says
// so), pin play, determinism across thread counts, and refusals.
#include <gtest/gtest.h>

#include <complex>
#include <map>

#include "examples.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"
#include "linkage/tolerance.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using C = std::complex<double>;
constexpr double kH = 1e-30;

// The four-bar's coupler point from its dimensions (the names of dimensions()), the crank at its
// drawn angle plus phi, open branch, P left of A->B: independent of the solver.
std::array<C, 2> coupler(const std::map<std::string, C>& v, double crankRad) {
  const C O2x = v.at("ground.O2.x"), O2y = v.at("ground.O2.y");
  const C O4x = v.at("ground.O4.x"), O4y = v.at("ground.O4.y");
  const C r2 = v.at("crank.O2-A"), r3 = v.at("coupler.A-B"), r4 = v.at("rocker.B-O4");
  const C ap = v.at("coupler.A-P"), bp = v.at("coupler.B-P");
  const C Ax = O2x + r2 * std::cos(crankRad), Ay = O2y + r2 * std::sin(crankRad);
  const C Dx = O4x - Ax, Dy = O4y - Ay, d2 = Dx * Dx + Dy * Dy, d = std::sqrt(d2);
  const C m = (r3 * r3 - r4 * r4 + d2) / (2.0 * d), h = std::sqrt(r3 * r3 - m * m);
  const C Bx = Ax + (m * Dx - h * Dy) / d, By = Ay + (m * Dy + h * Dx) / d;
  const C ux = (Bx - Ax) / r3, uy = (By - Ay) / r3;
  const C px = (r3 * r3 + ap * ap - bp * bp) / (2.0 * r3), py = std::sqrt(ap * ap - px * px);
  return {Ax + px * ux - py * uy, Ay + px * uy + py * ux};
}

ToleranceSpec specFor(PointId p, const std::vector<std::pair<std::string, double>>& tols) {
  ToleranceSpec s;
  s.point = p;
  for (const auto& [name, t] : tols) s.tolerances.push_back({name, t, false});
  return s;
}

const std::vector<std::pair<std::string, double>> kFourBarTols = {
    {"ground.O2.x", 0.02}, {"ground.O2.y", 0.03}, {"ground.O4.x", 0.05},
    {"ground.O4.y", 0.01}, {"crank.O2-A", 0.02},  {"coupler.A-B", 0.04},
    {"coupler.B-P", 0.03}, {"coupler.A-P", 0.02}, {"rocker.B-O4", 0.05}};

// Issue 29: the first-order band is the closed form's derivatives times the tolerances, 1e-10.
TEST(Tolerance, FirstOrderBandIsTheClosedFormsDerivativeTimesT) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  std::map<std::string, C> base;
  for (const Dimension& d : dimensions(f.m)) base[d.name] = d.value;
  ToleranceSpec spec = specFor(f.P, kFourBarTols);
  spec.steps = 72;
  const ToleranceResult r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.rows.size(), 72u);
  double worstErr = 0, peak = 0;
  for (const ToleranceRow& row : r.rows) {
    ASSERT_TRUE(row.firstOrder);
    const double t = (60 + row.crankDeg) * M_PI / 180;
    Vec2 worst = Vec2::Zero(), rss2 = Vec2::Zero();
    for (const auto& [name, T] : kFourBarTols) {
      std::map<std::string, C> v = base;
      v.at(name) += C(0, kH);
      const std::array<C, 2> p = coupler(v, t);
      const Vec2 g(p[0].imag() / kH, p[1].imag() / kH);
      worst += g.cwiseAbs() * T;
      rss2 += (g * T).cwiseProduct(g * T);
    }
    const std::array<C, 2> p = coupler(base, t);
    EXPECT_NEAR(row.nominal.x(), p[0].real(), 1e-9);
    peak = std::max(peak, worst.maxCoeff());
    worstErr = std::max({worstErr, (row.worst.head<2>() - worst).cwiseAbs().maxCoeff(),
                         (row.rss.head<2>() - rss2.cwiseSqrt()).cwiseAbs().maxCoeff()});
  }
  std::printf("first-order band against the closed form: %.2e of the band's peak %.3g mm\n",
              worstErr / peak, peak);
  EXPECT_LT(worstErr, 1e-10 * peak);
  EXPECT_TRUE(r.nonlinearDeg.empty());
}

// Small tolerances: the samples (solved exactly) spread as first order says. With n samples,
// the mean is within 6 sigma / sqrt(n) of the nominal (second order is 1e-4 of that here), the
// standard deviation within 6 standard errors (sigma / sqrt(2 n) bounds it for sums of uniform
// changes, whose kurtosis is below 3) of first order's, and no sample leaves the worst case.
TEST(Tolerance, MonteCarloConvergesToFirstOrderForSmallTolerances) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  std::vector<std::pair<std::string, double>> small = kFourBarTols;
  for (auto& t : small) t.second *= 0.05;
  ToleranceSpec spec = specFor(f.P, small);
  spec.steps = 36;
  spec.samples = 2000;
  spec.seed = 29;
  const ToleranceResult r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.used, 2000);
  EXPECT_EQ(r.failed, 0);
  const double n = r.used;
  for (const ToleranceRow& row : r.rows)
    for (int c = 0; c < 2; ++c) {
      EXPECT_LT(std::abs(row.mean[c] - row.nominal[c]), 6 * row.sigma[c] / std::sqrt(n));
      EXPECT_LT(std::abs(row.sd[c] - row.sigma[c]), 6 * row.sigma[c] / std::sqrt(2 * n))
          << row.crankDeg;
      EXPECT_LE(row.hi[c] - row.nominal[c], row.worst[c] * (1 + 1e-3));
      EXPECT_LE(row.nominal[c] - row.lo[c], row.worst[c] * (1 + 1e-3));
      EXPECT_GT(row.hi[c] - row.nominal[c], 2 * row.sigma[c]);  // the tails are reached
      EXPECT_FALSE(row.nonlinear) << row.crankDeg;
    }
  const StrokeSpread& s = r.stroke;
  EXPECT_TRUE(s.firstOrder);
  EXPECT_LT(std::abs(s.mean - s.nominal), 6 * s.sigma / std::sqrt(n));
  EXPECT_LT(std::abs(s.sd - s.sigma), 6 * s.sigma / std::sqrt(2 * n));
  EXPECT_LE(s.hi - s.nominal, s.worst * (1 + 1e-3));
  EXPECT_FALSE(s.nonlinear);
  EXPECT_TRUE(r.nonlinearDeg.empty());
}

// A crank-rocker 0.5 mm from its Grashof limit (s + l = 90 against p + q = 90.5): at crank angle
// 0 (the rows' 300 degrees; drawn at 60) its coupler and rocker fold to 0.5 mm of a line, a
// toggle. Tolerances that take that margin down to 0.01 mm: every sample turns, but near the
// toggle the motion is far from linear in them (B moves as the root of the margin) and the
// samples leave first order: the result names those crank angles. Away from it (120 +- 30
// degrees, the rocker at its best transmission) first order holds. Wider tolerances, some of
// whose samples cannot pass the toggle: those are counted with where they stop, never a NaN.
TEST(Tolerance, MonteCarloAcrossAToggleSaysFirstOrderFails) {
  const test::FourBar f = test::fourBar(60, 20, 70, 30.5, 60, true, 35, 25);
  ToleranceSpec spec = specFor(f.B, {{"rocker.B-O4", 0.45}, {"coupler.A-B", 0.04}});
  spec.steps = 72;
  spec.samples = 1000;
  spec.seed = 7;
  ToleranceResult r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.used, 1000) << r.firstFailure;
  std::printf("first order fails at:");
  for (double d : r.nonlinearDeg) std::printf(" %g", d);
  std::printf("\n");
  ASSERT_FALSE(r.nonlinearDeg.empty());
  bool atToggle = false;
  for (double d : r.nonlinearDeg) atToggle |= std::abs(d - 300) <= 5;
  EXPECT_TRUE(atToggle);
  for (const ToleranceRow& row : r.rows) {
    if (std::getenv("TOL_DEBUG"))
      std::printf("%g worst %g sigma %g lo %g hi %g mean %g sd %g\n", row.crankDeg, row.worst.y(),
                  row.sigma.y(), row.lo.y() - row.nominal.y(), row.hi.y() - row.nominal.y(),
                  row.mean.y() - row.nominal.y(), row.sd.y());
    if (std::abs(row.crankDeg - 120) <= 30) EXPECT_FALSE(row.nonlinear) << row.crankDeg;
  }
  spec.tolerances[0].plusMinus = 0.8;
  r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_GT(r.failed, 0);
  EXPECT_EQ(r.used + r.failed, 1000);
  EXPECT_NE(r.firstFailure.find("locks"), std::string::npos) << r.firstFailure;
  std::printf("%d of 1000 failed, stopping between %g and %g deg; the first: %s\n", r.failed,
              r.stopLoDeg, r.stopHiDeg, r.firstFailure.c_str());
  EXPECT_GT(r.stopLoDeg, 270);
  EXPECT_LT(r.stopHiDeg, 300);  // before the toggle, turning forward
  for (const ToleranceRow& row : r.rows)
    EXPECT_TRUE(row.lo.allFinite() && row.hi.allFinite() && row.mean.allFinite() &&
                row.sd.allFinite() && row.worst.allFinite())
        << row.crankDeg;
}

// Results for a seed do not depend on the number of threads: every sample draws from its own
// seed and the sums are added in sample order.
TEST(Tolerance, SameSeedSameResultOnOneAndTwoThreads) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  ToleranceSpec spec = specFor(f.P, kFourBarTols);
  spec.steps = 24;
  spec.samples = 700;
  spec.seed = 12345;
  spec.threads = 1;
  const ToleranceResult one = tolerances(f.m, spec);
  spec.threads = 2;
  const ToleranceResult two = tolerances(f.m, spec);
  ASSERT_EQ(one.rows.size(), two.rows.size());
  for (size_t i = 0; i < one.rows.size(); ++i) {
    EXPECT_EQ(one.rows[i].lo, two.rows[i].lo);
    EXPECT_EQ(one.rows[i].hi, two.rows[i].hi);
    EXPECT_EQ(one.rows[i].mean, two.rows[i].mean);
    EXPECT_EQ(one.rows[i].sd, two.rows[i].sd);
  }
  EXPECT_EQ(one.stroke.mean, two.stroke.mean);
  EXPECT_EQ(one.stroke.sd, two.stroke.sd);
  EXPECT_EQ(one.stroke.lo, two.stroke.lo);
  spec.seed = 12346;  // and another seed gives other samples
  EXPECT_NE(tolerances(f.m, spec).rows[3].mean, one.rows[3].mean);
}

// A pin's radial play c alone: first order is c |d point / d offset|, the largest over the
// direction; the samples, solved exactly with the pin's point anywhere in its disc, reach it
// (the largest of 4000 draws over a disc is within a few per cent of its edge) and never pass it
// by more than second order.
TEST(Tolerance, PinPlayIsTheLargestOverTheDirection) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  ToleranceSpec spec;
  spec.point = f.P;
  spec.tolerances.push_back({"coupler.B-rocker.B", 0.01, true});
  spec.steps = 12;
  spec.samples = 4000;
  spec.stroke = false;
  const ToleranceResult r = tolerances(f.m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.used, 4000);
  for (const ToleranceRow& row : r.rows)
    for (int c = 0; c < 2; ++c) {
      EXPECT_GT(row.worst[c], 1e-5) << row.crankDeg;
      EXPECT_LE(row.hi[c] - row.nominal[c], row.worst[c] * (1 + 1e-3)) << row.crankDeg;
      EXPECT_GE(row.hi[c] - row.nominal[c], row.worst[c] * 0.95) << row.crankDeg;
      EXPECT_GE(row.nominal[c] - row.lo[c], row.worst[c] * 0.95) << row.crankDeg;
    }
  // Named the other way round it is the same pin.
  spec.tolerances[0].dimension = "rocker.B-coupler.B";
  spec.samples = 0;
  EXPECT_TRUE(tolerances(f.m, spec).status.ok());
}

// Each sample's stroke is exact: the Wanzer needle's samples, each solved again independently
// by findLimits (every extreme found by root finding over a sampled turn), give the Monte Carlo
// extremes of the stroke to 1e-9 mm.
TEST(Tolerance, EachSamplesStrokeIsItsLimitPositions) {
  const Mechanism m = test::example("wanzer-inversion-2");
  const PointId g = *m.findPoint("needlebar.G");
  ToleranceSpec spec = specFor(g, {{"triangle.E-G", 0.1},
                                   {"triangle.F-G", 0.1},
                                   {"triangle.E-F", 0.05},
                                   {"disk.B.offset", 0.05},
                                   {"disk.C.angle", 0.2}});
  spec.tolerances.push_back({"triangle.E-slider4.E", 0.02, true});
  spec.samples = 6;
  spec.band = false;
  spec.seed = 3;
  const ToleranceResult r = tolerances(m, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.used, 6) << r.firstFailure;
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < 6; ++i) {
    Mechanism s;
    ASSERT_TRUE(toleranceSample(m, spec, i, s).ok());
    Kinematics k;
    ASSERT_TRUE(k.load(s).ok());
    const Limits l = findLimits(k, LimitMeasure::along(g, Vec2(0, 1)));
    ASSERT_TRUE(l.status.ok());
    lo = std::min(lo, l.stroke);
    hi = std::max(hi, l.stroke);
  }
  EXPECT_GT(hi - lo, 1e-3);  // the samples differ
  EXPECT_NEAR(r.stroke.lo, lo, 1e-9);
  EXPECT_NEAR(r.stroke.hi, hi, 1e-9);
}

TEST(Tolerance, UnknownNamesAreRefusedByName) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  ToleranceResult r = tolerances(f.m, specFor(f.P, {{"coupler.A-Q", 0.1}}));
  EXPECT_EQ(r.status.code, StatusCode::BadModel);
  EXPECT_NE(r.status.message.find("coupler.A-Q"), std::string::npos);
  ToleranceSpec s = specFor(f.P, {});
  s.tolerances.push_back({"coupler.A-rocker.B", 0.1, true});
  r = tolerances(f.m, s);
  EXPECT_EQ(r.status.code, StatusCode::BadModel);
  EXPECT_NE(r.status.message.find("coupler.A-rocker.B"), std::string::npos);
  r = tolerances(f.m, specFor(f.P, {{"crank.O2-A", -1}}));
  EXPECT_EQ(r.status.code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage
