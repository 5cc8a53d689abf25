// Harmonics of motion curves: the transform on trigonometric polynomials, and the central
// slider-crank's spectrum against its closed-form Fourier series (seed 002: Karabegovic, Bolic
// and Ujevic write the needle's motion as a series in cos 2k phi), computed here in __float128
// from the binomial series of sqrt(1 - lambda^2 sin^2 phi).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "examples.h"
#include "linkage/motion_samples.h"
#include "linkage/spectrum.h"
#include "reference/scalar.h"

namespace linkage {
namespace {

using Q = __float128;

// f(phi) = c0 + sum a_k cos k phi + b_k sin k phi with random coefficients, k <= K.
struct TrigPolynomial {
  double c0 = 0;
  std::vector<double> a, b;  // index k - 1
  explicit TrigPolynomial(int K, unsigned seed) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    c0 = u(gen);
    for (int k = 0; k < K; ++k) a.push_back(u(gen)), b.push_back(u(gen));
  }
  double operator()(double phi) const {
    double s = c0;
    for (size_t k = 0; k < a.size(); ++k)
      s += a[k] * std::cos((k + 1) * phi) + b[k] * std::sin((k + 1) * phi);
    return s;
  }
  double derivative(double phi) const {
    double s = 0;
    for (size_t k = 0; k < a.size(); ++k)
      s += (k + 1) * (-a[k] * std::sin((k + 1) * phi) + b[k] * std::cos((k + 1) * phi));
    return s;
  }
  std::vector<double> samples(int n) const {
    std::vector<double> v;
    for (int j = 0; j < n; ++j) v.push_back((*this)(2 * M_PI * j / n));
    return v;
  }
};

TEST(Spectrum, TrigonometricPolynomialsAreRecoveredExactly) {
  for (int n : {17, 36, 90, 360, 361}) {  // odd, even, a prime: every transform length
    const TrigPolynomial f(7, n);
    const Spectrum s = harmonics(f.samples(n), 10);
    ASSERT_EQ(s.terms.size(), size_t(std::min(10, n / 2))) << n;
    EXPECT_NEAR(s.mean, f.c0, 1e-14) << n;
    for (const Harmonic& h : s.terms) {
      const double a = h.k <= 7 ? f.a[h.k - 1] : 0, b = h.k <= 7 ? f.b[h.k - 1] : 0;
      EXPECT_NEAR(h.a, a, 1e-14) << n << " k=" << h.k;
      EXPECT_NEAR(h.b, b, 1e-14) << n << " k=" << h.k;
      EXPECT_NEAR(h.amplitude * std::cos(h.phase), a, 1e-14);
      EXPECT_NEAR(-h.amplitude * std::sin(h.phase), b, 1e-14);
    }
  }
}

TEST(Spectrum, NyquistTermAndTooFewSamples) {
  // cos(2 phi) on 4 samples is +1, -1, +1, -1: k = N / 2, whose sine part no grid sees.
  const Spectrum s = harmonics({1, -1, 1, -1}, 5);
  ASSERT_EQ(s.terms.size(), 2u);
  EXPECT_NEAR(s.terms[1].a, 1, 1e-15);
  EXPECT_EQ(s.terms[1].b, 0);
  EXPECT_TRUE(harmonics({1}, 3).terms.empty());
}

TEST(Spectrum, DerivativeAndInterpolantOfATrigonometricPolynomial) {
  const TrigPolynomial f(9, 5);
  const int n = 64;
  const Derivative d = periodicDerivative(f.samples(n));
  ASSERT_EQ(d.values.size(), size_t(n));
  for (int j = 0; j < n; ++j) EXPECT_NEAR(d.values[j], f.derivative(2 * M_PI * j / n), 1e-12);
  EXPECT_LT(d.errorEstimate, 1e-11);  // nothing above N / 4 = 16 but rounding
  const PeriodicInterpolant p(f.samples(n));
  for (double phi : {0.0, 0.1, 1.234, 3.0, 6.2, -2.5, 20.0}) EXPECT_NEAR(p(phi), f(phi), 1e-13);
}

TEST(Spectrum, DerivativeErrorEstimateBoundsTheErrorOfUnderResolvedCurves) {
  // g(phi) = 1 / (1.3 - cos phi): harmonics 2 rho^k / sqrt(1.3^2 - 1), rho = 1.3 - sqrt(0.69),
  // decaying by 0.47 a harmonic: 24 samples do not resolve its derivative to rounding.
  auto g = [](double x) { return 1 / (1.3 - std::cos(x)); };
  auto dg = [](double x) { return -std::sin(x) / ((1.3 - std::cos(x)) * (1.3 - std::cos(x))); };
  for (int n : {12, 24, 48, 96}) {
    std::vector<double> v;
    for (int j = 0; j < n; ++j) v.push_back(g(2 * M_PI * j / n));
    const Derivative d = periodicDerivative(v);
    double err = 0;
    for (int j = 0; j < n; ++j) err = std::max(err, std::abs(d.values[j] - dg(2 * M_PI * j / n)));
    EXPECT_LE(err, d.errorEstimate) << n;
    if (n <= 24) EXPECT_GT(err, 1e-6) << n;  // the case is a real one
  }
}

// --- the central slider-crank ---------------------------------------------------------------

// sqrt(1 - lambda^2 sin^2 phi) = sum_m C_m cos(2 m phi): the binomial series of sqrt(1 - x),
// with sin^2n phi = 4^-n [binom(2n, n) + 2 sum_m (-1)^m binom(2n, n - m) cos 2m phi].
Q sqrtSeriesCoefficient(Q lambda, int m) {
  Q sum = 0, half = 1, x = 1;  // half = binom(1/2, n), x = (-lambda^2 / 4)^n
  Q choose = 1;                // binom(2n, n - m), from n = m on
  for (int n = 0; n < 400; ++n) {
    if (n > 0) {
      half = half * (Q(0.5) - Q(n - 1)) / Q(n);
      x = x * (-lambda * lambda / Q(4));
    }
    if (n < m) continue;
    if (n > m) choose = choose * Q(2 * n) * Q(2 * n - 1) / (Q(n - m) * Q(n + m));
    sum += half * x * choose * Q(m == 0 ? 1 : 2 * (m % 2 ? -1 : 1));
  }
  return sum;
}

using test::example;

// Example files: r = 15, l = r / lambda, drawn at the outer dead centre, ccw, 1000 rpm; the
// needle bar's y at crank angle phi is r cos phi + l sqrt(1 - lambda^2 sin^2 phi) (seed 002's
// eq. 2 with its phi_B = phi + pi): mean l C_0, a_1 = r, a_2m = l C_m, no odd harmonics above
// the first and no sines. Velocity and acceleration: each term's time derivatives.
void checkSliderCrankHarmonics(const std::string& name, double lambda) {
  SCOPED_TRACE(name);
  const Mechanism m = example(name);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId B = *m.findPoint("needlebar.B");
  SampleSpec spec;
  spec.points = {B};
  MotionSamples s = sampleMotion(k, spec);
  ASSERT_TRUE(s.complete()) << s.status.message;
  ASSERT_TRUE(s.periodic);
  const double r = 15, l = r / lambda, w = s.omega;
  const int K = 24;
  std::vector<double> a(K + 1, 0.0);  // exact cosine coefficients of y; a[0] is the mean
  a[1] = r;
  for (int mm = 0; 2 * mm <= K; ++mm) a[2 * mm] += double(Q(l) * sqrtSeriesCoefficient(lambda, mm));
  // Seed 002's own truncation (its eq. 3): the cos 2 phi coefficient to lambda^7.
  const double paper =
      r * (lambda / 4 + 4 * std::pow(lambda, 3) / 64 + 15 * std::pow(lambda, 5) / (16 * 32) +
           5 * 56 * std::pow(lambda, 7) / (128 * 128));
  EXPECT_NEAR(a[2], paper, r * std::pow(lambda, 9));

  const Quantity y = Quantity::ofPoint(B, Quantity::Component::Y);
  for (Order o : {Order::Position, Order::Velocity, Order::Acceleration}) {
    SCOPED_TRACE(static_cast<int>(o));
    Status why;
    const Spectrum sp = harmonicsOf(s, y, o, K, &why);
    ASSERT_TRUE(why.ok()) << why.message;
    ASSERT_EQ(sp.terms.size(), size_t(K));
    // d/dt a cos(k phi) = -k w a sin(k phi); d2/dt2 = -(k w)^2 a cos(k phi).
    EXPECT_NEAR(sp.mean, o == Order::Position ? a[0] : 0, 1e-9 * a[0] + 1e-12);
    for (const Harmonic& h : sp.terms) {
      const double kw = h.k * w;
      const double ea = o == Order::Position       ? a[h.k]
                        : o == Order::Acceleration ? -kw * kw * a[h.k]
                                                   : 0;
      const double eb = o == Order::Velocity ? -kw * a[h.k] : 0;
      // 1e-9 relative; below 1e-12 r (w k)^o, the samples' rounding.
      const double floor = 1e-12 * r * std::pow(kw, static_cast<int>(o));
      EXPECT_NEAR(h.a, ea, 1e-9 * std::abs(ea) + floor) << "k=" << h.k;
      EXPECT_NEAR(h.b, eb, 1e-9 * std::abs(eb) + floor) << "k=" << h.k;
      EXPECT_NEAR(h.amplitude, std::abs(ea) + std::abs(eb),
                  1e-9 * (std::abs(ea) + std::abs(eb)) + floor)
          << "k=" << h.k;
    }
  }
}

TEST(Harmonics, CentralSliderCrankEqualsItsClosedFormFourierSeries) {
  checkSliderCrankHarmonics("slider-crank-22a-lambda-0.3", 0.3);
  checkSliderCrankHarmonics("slider-crank-22a-lambda-0.5", 0.5);
}

TEST(Harmonics, SeriesCoefficientsSumToTheClosedForm) {
  // The reference itself: the series at a few angles against sqrt(1 - lambda^2 sin^2 phi).
  for (Q lambda : {Q(0.3), Q(0.5), Q(0.8)}) {
    for (Q phi : {Q(0.1), Q(0.7), Q(2.0)}) {
      Q sum = 0;
      for (int m = 0; m < 80; ++m) sum += sqrtSeriesCoefficient(lambda, m) * cosq(2 * m * phi);
      const Q exact = sqrtq(1 - lambda * lambda * sinq(phi) * sinq(phi));
      EXPECT_LT(double(fabsq(sum - exact)), 1e-25);
    }
  }
}

}  // namespace
}  // namespace linkage
