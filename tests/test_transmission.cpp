// Transmission angles (linkage/transmission.h) against closed forms: the four-bar's by the law of
// cosines, extreme where the crank lies along the ground line; the offset slider-crank's from the
// rod's slope; the 876 needle mechanism's mu_1, mu_2, mu_3 by the paper's own formulas
// (tests/reference/needle876.h, __float128).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "examples.h"
#include "linkage/io/model_file.h"
#include "linkage/transmission.h"
#include "mechanisms.h"
#include "reference/needle876.h"

namespace linkage {
namespace {

using Q = __float128;

constexpr double kTol = 1e-9;  // degrees of angle and of crank

using test::example;

double wrap360(double d) {
  d = std::fmod(d, 360.0);
  return d < 0 ? d + 360 : d;
}

double periodicGap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360 - d);
}

double acosDeg(double c) {
  return std::acos(c) * 180 / M_PI;
}

TransmissionSweep sweep(const Mechanism& m, TransmissionOptions opt = {}) {
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  return sweepTransmission(k, opt);
}

// Four-bar, ground d along +x, crank r2 drawn at theta20: the angle at B between B->A and B->O4
// is acos((r3^2 + r4^2 - |A O4|^2) / (2 r3 r4)), |A O4|^2 = r2^2 + d^2 - 2 r2 d cos theta2,
// whichever branch; smallest at theta2 = 0, largest at theta2 = 180 degrees.
double fourBarMu(double d, double r2, double r3, double r4, double theta2) {
  const double ao2 = r2 * r2 + d * d - 2 * r2 * d * std::cos(theta2 * M_PI / 180);
  return acosDeg((r3 * r3 + r4 * r4 - ao2) / (2 * r3 * r4));
}

TEST(Transmission, FourBarMatchesTheLawOfCosinesWithExtremesOnTheGroundLine) {
  struct Case {
    double d, r2, r3, r4, drawn;
    bool open;
    Direction dir;
  };
  for (const Case& c : {Case{60, 20, 70, 50, 60, true, Direction::Ccw},
                        Case{80, 25, 90, 60, 200, false, Direction::Cw},
                        Case{20, 60, 70, 50, 30, true, Direction::Ccw}}) {  // a double-crank
    const test::FourBar f = test::fourBar(c.d, c.r2, c.r3, c.r4, c.drawn, c.open, 0, 0, c.dir);
    const TransmissionSweep s = sweep(f.m);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    ASSERT_EQ(s.joints.size(), 1u);
    EXPECT_EQ(s.joints[0].kind, TransmissionKind::Dyad);
    EXPECT_EQ(s.joints[0].joint, f.pinB);
    EXPECT_EQ(s.joints[0].label, "mu:coupler.B");
    const double sgn = c.dir == Direction::Ccw ? 1 : -1;
    ASSERT_EQ(s.crankDeg.size(), 361u);
    for (size_t i = 0; i < s.crankDeg.size(); ++i)
      ASSERT_NEAR(s.values[0][i], fourBarMu(c.d, c.r2, c.r3, c.r4, c.drawn + sgn * s.crankDeg[i]),
                  kTol)
          << i;
    const TransmissionSummary& r = s.summaries[0];
    EXPECT_NEAR(r.min, fourBarMu(c.d, c.r2, c.r3, c.r4, 0), kTol);
    EXPECT_NEAR(r.max, fourBarMu(c.d, c.r2, c.r3, c.r4, 180), kTol);
    EXPECT_LT(periodicGap(r.minDeg, wrap360(-sgn * c.drawn)), kTol) << r.minDeg;
    EXPECT_LT(periodicGap(r.maxDeg, wrap360(180 - sgn * c.drawn)), kTol) << r.maxDeg;
    ASSERT_EQ(r.extremes.size(), 2u);
  }
}

TEST(Transmission, BandStretchesAreExactAndWrapPastCrankZero) {
  // Crank-rocker drawn with the crank along the ground line: mu is smallest (34.05 degrees) at
  // crank 0, so a band from 40 is left from -delta to +delta, through crank 0.
  const double d = 60, r2 = 20, r3 = 70, r4 = 50;
  const test::FourBar f = test::fourBar(d, r2, r3, r4, 0);
  TransmissionOptions opt;
  opt.band = {40, 80};
  const TransmissionSweep s = sweep(f.m, opt);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_FALSE(s.inBand());
  // Where mu = 40 and mu = 80: |A O4|^2 from the law of cosines, then theta2.
  auto crankAt = [&](double mu) {
    const double ao2 = r3 * r3 + r4 * r4 - 2 * r3 * r4 * std::cos(mu * M_PI / 180);
    return acosDeg((r2 * r2 + d * d - ao2) / (2 * r2 * d));
  };
  const double below = crankAt(40), above = crankAt(80);
  const std::vector<TransmissionStretch>& out = s.summaries[0].outside;
  ASSERT_EQ(out.size(), 2u);
  EXPECT_FALSE(out[0].below);  // above 80 around crank 180
  EXPECT_NEAR(out[0].fromDeg, above, kTol);
  EXPECT_NEAR(out[0].toDeg, 360 - above, kTol);
  EXPECT_TRUE(out[1].below);  // below 40 from 360 - delta on, through 0
  EXPECT_NEAR(out[1].fromDeg, 360 - below, kTol);
  EXPECT_NEAR(out[1].toDeg, 360 + below, kTol);
  // Every sample outside a stretch is in the band, every one inside is out of it.
  for (size_t i = 0; i < s.crankDeg.size(); ++i) {
    const double c = s.crankDeg[i], mu = s.values[0][i];
    bool in = false;
    for (const TransmissionStretch& x : out)
      in = in || (c > x.fromDeg && c < x.toDeg) || (c + 360 > x.fromDeg && c + 360 < x.toDeg);
    EXPECT_EQ(in, mu < 40 || mu > 80) << c;
  }
  // A band the angle never leaves, and one it never enters.
  opt.band = {30, 150};
  EXPECT_TRUE(sweep(f.m, opt).inBand());
  opt.band = {85, 150};
  const TransmissionSweep never = sweep(f.m, opt);
  ASSERT_EQ(never.summaries[0].outside.size(), 1u);
  EXPECT_EQ(never.summaries[0].outside[0].fromDeg, 0);
  EXPECT_EQ(never.summaries[0].outside[0].toDeg, 360);
}

TEST(Transmission, OffsetSliderCrankRodAgainstItsSlot) {
  // mu = 90 - asin(|e - r cos theta| / l): 90 where the rod stands along the slot
  // (cos theta = e / r), local minimum at theta = 0, global minimum at theta = 180.
  const double r = 15, l = 50, e = 8;
  for (const bool pinInSlot : {false, true}) {
    const test::SliderCrank sc = test::sliderCrank(r, l, e, 0, Direction::Ccw, 60, pinInSlot);
    const TransmissionSweep s = sweep(sc.m);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    ASSERT_EQ(s.joints.size(), 1u);
    EXPECT_EQ(s.joints[0].kind,
              pinInSlot ? TransmissionKind::RodInSlot : TransmissionKind::RodSlider);
    for (size_t i = 0; i < s.crankDeg.size(); ++i) {
      const double dx = e - r * std::cos(s.crankDeg[i] * M_PI / 180);
      ASSERT_NEAR(s.values[0][i], 90 - std::asin(std::abs(dx) / l) * 180 / M_PI, kTol);
    }
    const double along = acosDeg(e / r);
    const std::vector<TransmissionExtreme>& x = s.summaries[0].extremes;
    ASSERT_EQ(x.size(), 4u);
    const double at[4] = {0, along, 180, 360 - along};
    const double value[4] = {90 - std::asin((r - e) / l) * 180 / M_PI, 90,
                             90 - std::asin((r + e) / l) * 180 / M_PI, 90};
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(periodicGap(x[k].crankDeg, at[k]), kTol) << k << ": " << x[k].crankDeg;
      EXPECT_NEAR(x[k].deg, value[k], kTol) << k;
      EXPECT_EQ(x[k].max, k % 2 == 1);
    }
    EXPECT_NEAR(s.summaries[0].min, value[2], kTol);
    EXPECT_NEAR(s.summaries[0].minDeg, 180, kTol);
    EXPECT_NEAR(s.summaries[0].max, 90, kTol);
  }
}

TEST(Transmission, NeedleMechanismsAnglesAreThePapersFormulas) {
  for (int alpha : {0, 35}) {
    const Mechanism m = example("needle-876-alpha-" + std::to_string(alpha));
    const TransmissionSweep s = sweep(m);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    ASSERT_EQ(s.joints.size(), 3u);
    EXPECT_EQ(s.joints[0].label, "mu:coupler.B");
    EXPECT_EQ(s.joints[1].label, "mu:link.E");
    EXPECT_EQ(s.joints[2].label, "mu:rod.G");
    EXPECT_EQ(s.joints[2].kind, TransmissionKind::RodSlider);
    const linkref::Needle876<Q> ref(alpha);
    for (size_t i = 0; i < s.crankDeg.size(); ++i) {
      const auto st = ref.at(Q(s.crankDeg[i]));
      ASSERT_NEAR(s.values[0][i], static_cast<double>(st.mu1), kTol) << i;
      ASSERT_NEAR(s.values[1][i], static_cast<double>(st.mu2), kTol) << i;
      ASSERT_NEAR(s.values[2][i], static_cast<double>(st.mu3), kTol) << i;
    }
    // Every extreme is where the reference's angle is stationary: golden-section search in
    // __float128 about it finds the same crank angle and value.
    for (size_t j = 0; j < 3; ++j)
      for (const TransmissionExtreme& x : s.summaries[j].extremes) {
        auto mu = [&](Q deg) {
          const auto st = ref.at(deg);
          const Q v = j == 0 ? st.mu1 : j == 1 ? st.mu2 : st.mu3;
          return x.max ? -v : v;
        };
        Q a = Q(x.crankDeg) - Q(0.5), b = Q(x.crankDeg) + Q(0.5);
        const Q g = (linkref::sqrt(Q(5)) - 1) / 2;
        for (int it = 0; it < 160; ++it) {
          const Q c = b - g * (b - a), d = a + g * (b - a);
          (mu(c) < mu(d) ? b : a) = mu(c) < mu(d) ? d : c;
        }
        const Q best = (a + b) / 2;
        // The value is the reference's, and no better one is near.
        EXPECT_NEAR(x.deg, static_cast<double>(x.max ? -mu(Q(x.crankDeg)) : mu(Q(x.crankDeg))),
                    kTol);
        EXPECT_LT(static_cast<double>(mu(Q(x.crankDeg)) - mu(best)), 1e-12);
        // The crank angle to 1e-9 wherever the extreme is curved enough to fix it (mu changes
        // by 1e-12 degree within 1e-3 degree of crank). Not so: mu_3 at crank 0 for alpha = 0,
        // flat to the fourth order (E is at rest and moves vertically there, and mu_3 depends
        // on x_E only): flat to 1e-19 degree within 1e-3 degree of crank, so no computation
        // fixes its angle, and the value is what counts.
        if (mu(best + Q(1e-3)) - mu(best) > Q(1e-12) && mu(best - Q(1e-3)) - mu(best) > Q(1e-12))
          EXPECT_NEAR(x.crankDeg, static_cast<double>(best), kTol) << j << " " << x.crankDeg;
        else
          EXPECT_TRUE(alpha == 0 && j == 2 && x.crankDeg == 0) << j << " " << x.crankDeg;
      }
    // The paper's band holds, mu_2 is lowest at the lowest position and falls by alpha.
    EXPECT_TRUE(s.inBand());
    EXPECT_NEAR(s.summaries[1].minDeg, 0, kTol);
    EXPECT_NEAR(s.summaries[1].min, 67.677483779484959 - alpha, 1e-9);
  }
}

TEST(Transmission, JointsFromTheStructureOfAnyMechanism) {
  // Watt II: two dyads; the second one's links are the link and the output.
  const test::WattSixBar w = test::wattSixBar();
  const std::vector<TransmissionJoint> js = transmissionJoints(w.m);
  ASSERT_EQ(js.size(), 2u);
  EXPECT_EQ(js[0].label, "mu:coupler.B");
  EXPECT_EQ(js[1].label, "mu:link.F");
  EXPECT_EQ(js[1].other, w.output);
  // Wanzer: its class-III group has none.
  EXPECT_TRUE(transmissionJoints(example("wanzer-inversion-2")).empty());
  // The angle at one pose agrees with the sweep's first row, and its rate with a central
  // difference of the sweep (a check on the sign conventions of the rates).
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const TransmissionJoint t = transmissionJoints(f.m)[0];
  const TransmissionReading r0 = transmissionAngle(k, t);
  EXPECT_NEAR(r0.deg, fourBarMu(60, 20, 70, 50, 60), kTol);
  ASSERT_TRUE(k.moveTo(1e-4).ok());
  const double up = transmissionAngle(k, t).deg;
  ASSERT_TRUE(k.moveTo(-1e-4).ok());
  const double down = transmissionAngle(k, t).deg;
  EXPECT_NEAR(r0.perDeg, (up - down) / 2e-4, 1e-7);
  // Bad options and a crank that stops.
  TransmissionOptions bad;
  bad.band = {150, 30};
  EXPECT_EQ(sweep(f.m, bad).status.code, StatusCode::BadModel);
  const TransmissionSweep locked = sweep(test::fourBar(60, 40, 50, 45, 70).m);
  EXPECT_EQ(locked.status.code, StatusCode::Unreachable);
  EXPECT_GT(locked.crankDeg.size(), 1u);  // the samples reached
  EXPECT_LT(locked.crankDeg.size(), 361u);
  EXPECT_EQ(locked.values[0].size(), locked.crankDeg.size());
  EXPECT_TRUE(locked.summaries.empty());
}

}  // namespace
}  // namespace linkage
