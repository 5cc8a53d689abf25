// A cam's motion laws and programme (linkage/cam.h) against closed forms: each law's ends and
// its peak coefficients (Norton's table, as issue 28 quotes it), the continuity of the piecewise
// laws where their pieces meet, and their derivatives against each other by Simpson's rule on a
// fine grid (an independent check of the exact formulas); a programme's s, s', s'' against the
// laws scaled by hand, its period, and its checks.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "linkage/cam.h"

namespace linkage::cam {
namespace {

constexpr double kPi = M_PI;

// Simpson's rule over [0, x] in n (even) intervals.
double simpson(const std::function<double(double)>& f, double x, int n) {
  const double h = x / n;
  double sum = f(0) + f(x);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(i * h);
  return sum * h / 3;
}

TEST(CamLaws, EveryLawRisesFromRestToOne) {
  for (Law law : allLaws()) {
    const Normalised a = evaluate(law, 0), b = evaluate(law, 1);
    EXPECT_NEAR(a.s, 0, 1e-15) << lawName(law);
    EXPECT_NEAR(b.s, 1, 1e-15) << lawName(law);
    EXPECT_NEAR(a.v, 0, 1e-15) << lawName(law);
    EXPECT_NEAR(b.v, 0, 1e-14) << lawName(law);
    // Half way every symmetric rise is at one half.
    EXPECT_NEAR(evaluate(law, 0.5).s, 0.5, 1e-15) << lawName(law);
    if (law == Law::Harmonic) {
      // Its acceleration jumps from a dwell's 0 to pi^2 / 2 at both ends.
      EXPECT_NEAR(a.a, kPi * kPi / 2, 1e-14);
      EXPECT_NEAR(b.a, -kPi * kPi / 2, 1e-14);
    } else {
      EXPECT_NEAR(a.a, 0, 1e-14) << lawName(law);
      EXPECT_NEAR(b.a, 0, 1e-13) << lawName(law);
    }
  }
}

// The peak velocity and acceleration coefficients, at the places the closed forms put them, and
// no larger anywhere on a fine grid.
TEST(CamLaws, PeakCoefficientsAreNortons) {
  struct Peak {
    Law law;
    double cv, xa, ca, tolerance;  // Ca at x = xa; the tolerance of the quoted figures
  };
  const Peak peaks[] = {
      {Law::Cycloidal, 2, 0.25, 2 * kPi, 1e-14},
      {Law::Harmonic, kPi / 2, 0, kPi * kPi / 2, 1e-14},
      {Law::Polynomial345, 1.875, (3 - std::sqrt(3.0)) / 6, 10 / std::sqrt(3.0), 1e-13},
      {Law::Polynomial4567, 35.0 / 16, (5 - std::sqrt(5.0)) / 10, 7.5132, 5e-5},
      {Law::ModifiedTrapezoid, 2, 0.25, 4.8881, 5e-5},
      {Law::ModifiedSine, 1.7596, 0.125, 5.5280, 5e-5},
  };
  for (const Peak& p : peaks) {
    EXPECT_NEAR(evaluate(p.law, 0.5).v, p.cv, std::max(p.tolerance, 1e-14)) << lawName(p.law);
    EXPECT_NEAR(evaluate(p.law, p.xa).a, p.ca, p.tolerance) << lawName(p.law);
    double vMax = 0, aMax = 0;
    for (int i = 0; i <= 100000; ++i) {
      const Normalised n = evaluate(p.law, i / 100000.0);
      vMax = std::max(vMax, std::abs(n.v));
      aMax = std::max(aMax, std::abs(n.a));
    }
    // (The grid passes within 5e-6 of the peak, where the value is within 1e-8 of it.)
    EXPECT_LE(vMax, evaluate(p.law, 0.5).v + 1e-13) << lawName(p.law);
    EXPECT_GE(vMax, evaluate(p.law, 0.5).v - 1e-8) << lawName(p.law);
    EXPECT_LE(aMax, std::abs(evaluate(p.law, p.xa).a) + 1e-13) << lawName(p.law);
    EXPECT_GE(aMax, std::abs(evaluate(p.law, p.xa).a) - 1e-8) << lawName(p.law);
  }
  // The exact figures the quoted ones round: modified trapezoid Ca = 1 / (1/8 + 1/(4 pi)) and
  // Cv exactly 2; modified sine Ca = 1 / (1/(4 pi) + 1/pi^2), Cv = Ca / pi.
  EXPECT_NEAR(evaluate(Law::ModifiedTrapezoid, 0.3).a, 1 / (0.125 + 1 / (4 * kPi)), 1e-14);
  EXPECT_NEAR(evaluate(Law::ModifiedTrapezoid, 0.5).v, 2, 1e-14);
  const double sineCa = 1 / (1 / (4 * kPi) + 1 / (kPi * kPi));
  EXPECT_NEAR(evaluate(Law::ModifiedSine, 0.125).a, sineCa, 1e-14);
  EXPECT_NEAR(evaluate(Law::ModifiedSine, 0.5).v, sineCa / kPi, 1e-14);
  // Symmetric: the fall half mirrors the rise half.
  for (Law law : allLaws())
    for (double x : {0.1, 0.2, 0.3, 0.45}) {
      const Normalised a = evaluate(law, x), b = evaluate(law, 1 - x);
      EXPECT_NEAR(a.s + b.s, 1, 1e-14) << lawName(law) << " " << x;
      EXPECT_NEAR(a.v, b.v, 1e-13) << lawName(law) << " " << x;
      EXPECT_NEAR(a.a, -b.a, 1e-12) << lawName(law) << " " << x;
      EXPECT_NEAR(a.j, b.j, 1e-10) << lawName(law) << " " << x;
    }
}

// Where the pieces of the piecewise laws meet, S, V and A are continuous: the doubles on either
// side of a joint, each from its own piece, agree to rounding.
TEST(CamLaws, PiecewiseLawsAreContinuousWhereTheirPiecesMeet) {
  for (Law law : {Law::ModifiedTrapezoid, Law::ModifiedSine}) {
    const std::vector<double> joints = law == Law::ModifiedTrapezoid
                                           ? std::vector<double>{0.125, 0.375, 0.5, 0.625, 0.875}
                                           : std::vector<double>{0.125, 0.5, 0.875};
    for (double x : joints) {
      const Normalised a = evaluate(law, std::nextafter(x, 0.0)),
                       b = evaluate(law, std::nextafter(x, 1.0));
      EXPECT_NEAR(a.s, b.s, 1e-15) << lawName(law) << " at " << x;
      EXPECT_NEAR(a.v, b.v, 1e-14) << lawName(law) << " at " << x;
      EXPECT_NEAR(a.a, b.a, 1e-13) << lawName(law) << " at " << x;
    }
  }
  // At 1/8 the trapezoid's jerk is 0 on both sides (its quarter wave ends as the plateau
  // starts).
  EXPECT_NEAR(evaluate(Law::ModifiedTrapezoid, std::nextafter(0.125, 0.0)).j, 0, 1e-13);
  EXPECT_NEAR(evaluate(Law::ModifiedTrapezoid, std::nextafter(0.125, 1.0)).j, 0, 1e-13);
}

// Each derivative integrates to the one before it: Simpson on 8000 intervals (the pieces' joints
// are grid points, so no panel straddles one) against the closed forms.
TEST(CamLaws, DerivativesIntegrateToEachOther) {
  for (Law law : allLaws())
    for (double x : {0.125, 0.3, 0.5, 0.77, 1.0}) {
      const int n = static_cast<int>(std::lround(8000 * x));
      const Normalised at = evaluate(law, x), zero = evaluate(law, 0);
      auto part = [law](double Normalised::*f) {
        return [law, f](double t) { return evaluate(law, t).*f; };
      };
      EXPECT_NEAR(simpson(part(&Normalised::v), x, n), at.s, 1e-12) << lawName(law) << " " << x;
      EXPECT_NEAR(simpson(part(&Normalised::a), x, n), at.v - zero.v, 1e-11)
          << lawName(law) << " " << x;
      EXPECT_NEAR(simpson(part(&Normalised::j), x, n), at.a - zero.a, 1e-9)
          << lawName(law) << " " << x;
    }
}

TEST(CamLaws, NamesAreTheFilesAndUnknownOnesAreNone) {
  for (Law law : allLaws()) EXPECT_EQ(lawNamed(lawName(law)), law);
  EXPECT_EQ(lawNamed("parabolic"), std::nullopt);
  EXPECT_EQ(lawNamed("Cycloidal"), std::nullopt);
  EXPECT_EQ(lawNames(),
            "\"cycloidal\", \"harmonic\", \"polynomial-345\", \"polynomial-4567\", "
            "\"modified-trapezoid\" or \"modified-sine\"");
}

// The spec's example: rise 10 mm cycloidal over 90 degrees, dwell to 150, fall 10 mm by the
// 3-4-5 polynomial to 270, dwell to 360.
std::vector<Segment> specExample() {
  return {{90, 10, Law::Cycloidal}, {150, 0, {}}, {270, -10, Law::Polynomial345}, {360, 0, {}}};
}

TEST(CamProgram, DisplacementAndDerivativesAreTheLawsScaled) {
  int at = 0;
  const char* key = nullptr;
  ASSERT_EQ(checkProgram(specExample(), at, key), "");
  const Program p(specExample());
  const double rise = kPi / 2, fall = 2 * kPi / 3;  // the segments' spans, radians
  // Half way up: s = 10 S(1/2), s' = 10 Cv / beta; a quarter way up: s'' = 10 Ca / beta^2.
  Displacement d = p.at(kPi / 4);
  EXPECT_NEAR(d.s, 5, 1e-14);
  EXPECT_NEAR(d.v, 10 * 2 / rise, 1e-13);
  EXPECT_NEAR(p.at(kPi / 8).a, 10 * 2 * kPi / (rise * rise), 1e-12);
  EXPECT_NEAR(d.j, 10 * -4 * kPi * kPi / (rise * rise * rise), 1e-11);
  // The dwells.
  for (double deg : {90.0, 120.0, 149.999}) {
    d = p.at(deg * kPi / 180);
    EXPECT_NEAR(d.s, 10, 1e-14) << deg;
    EXPECT_EQ(d.v, 0);
    EXPECT_EQ(d.a, 0);
  }
  for (double deg : {270.0, 300.0, 359.999, 0.0}) EXPECT_NEAR(p.at(deg * kPi / 180).s, 0, 1e-14);
  // Half way down the fall.
  d = p.at(210 * kPi / 180);
  EXPECT_NEAR(d.s, 5, 1e-13);
  EXPECT_NEAR(d.v, -10 * 1.875 / fall, 1e-13);
  const double xa = (3 - std::sqrt(3.0)) / 6;
  EXPECT_NEAR(p.at((150 + 120 * xa) * kPi / 180).a, -10 * 10 / std::sqrt(3.0) / (fall * fall),
              1e-11);
  // One turn is the period, either way round.
  for (double deg : {10.0, 100.0, 200.0, 290.0}) {
    const Displacement a = p.at(deg * kPi / 180), b = p.at(deg * kPi / 180 + 2 * kPi),
                       c = p.at(deg * kPi / 180 - 4 * kPi);
    EXPECT_NEAR(a.s, b.s, 1e-13) << deg;
    EXPECT_NEAR(a.v, c.v, 1e-12) << deg;
    EXPECT_NEAR(a.a, c.a, 1e-11) << deg;
  }
  EXPECT_EQ(p.segmentAt(-0.1), 3);
  EXPECT_EQ(p.segmentAt(kPi / 2), 1);
}

// s' integrates to s and s'' to s' over the turn (Simpson, segment by segment).
TEST(CamProgram, DerivativesIntegrateToTheDisplacement) {
  std::vector<Segment> segs = {{60, 4, Law::ModifiedSine},       {100, 0, {}},
                               {170, 6, Law::ModifiedTrapezoid}, {220, -3, Law::Harmonic},
                               {300, -7, Law::Polynomial4567},   {360, 0, {}}};
  int at = 0;
  const char* key = nullptr;
  ASSERT_EQ(checkProgram(segs, at, key), "");
  const Program p(segs);
  double from = 0;
  for (const Segment& s : segs) {
    const double a = from * kPi / 180, b = s.toDeg * kPi / 180;
    const double eps = 1e-13;  // inside the segment
    auto shifted = [&](auto f) { return [&, f](double t) { return f(p.at(a + eps + t)); }; };
    const double span = b - a - 2 * eps;
    EXPECT_NEAR(simpson(shifted([](const Displacement& d) { return d.v; }), span, 8000),
                p.at(b - eps).s - p.at(a + eps).s, 1e-10)
        << s.toDeg;
    EXPECT_NEAR(simpson(shifted([](const Displacement& d) { return d.a; }), span, 8000),
                p.at(b - eps).v - p.at(a + eps).v, 1e-9)
        << s.toDeg;
    from = s.toDeg;
  }
}

TEST(CamProgram, AnOscillatingFollowersDegreesAreRadiansInS) {
  const Program p({{180, 20, Law::Cycloidal}, {360, -20, Law::Cycloidal}}, kPi / 180);
  EXPECT_NEAR(p.at(kPi / 2).s, 10 * kPi / 180, 1e-15);
  EXPECT_NEAR(p.at(kPi / 2).v, 20 * kPi / 180 * 2 / kPi, 1e-15);
  EXPECT_NEAR(p.at(kPi).s, 20 * kPi / 180, 1e-15);
}

TEST(CamProgram, BadProgrammesAreRefusedNamingTheSegment) {
  int at = 0;
  const char* key = nullptr;
  auto check = [&](std::vector<Segment> s) { return checkProgram(s, at, key); };
  EXPECT_EQ(check({}), "no segments: a programme's segments end at 360 degrees");
  EXPECT_EQ(at, -1);
  EXPECT_EQ(check({{90, 10, Law::Cycloidal}, {80, 0, {}}, {360, -10, Law::Cycloidal}}),
            "expected an end above the previous segment's (90 degrees), got 80");
  EXPECT_EQ(at, 1);
  EXPECT_STREQ(key, "to_deg");
  EXPECT_EQ(check({{0, 0, {}}, {360, 0, {}}}), "expected an end above 0 degrees, got 0");
  EXPECT_EQ(at, 0);
  EXPECT_EQ(check({{90, 10, Law::Cycloidal}, {400, -10, Law::Cycloidal}}),
            "beyond 360 degrees (400): a programme is one turn");
  EXPECT_EQ(at, 1);
  EXPECT_EQ(check({{90, 10, Law::Cycloidal}, {350, -10, Law::Cycloidal}}),
            "the last segment ends at 350 degrees, not at 360");
  EXPECT_EQ(at, 1);
  EXPECT_EQ(check({{90, 10, {}}, {360, -10, Law::Cycloidal}}),
            "a rise needs a law: \"cycloidal\", \"harmonic\", \"polynomial-345\", "
            "\"polynomial-4567\", \"modified-trapezoid\" or \"modified-sine\"");
  EXPECT_EQ(at, 0);
  EXPECT_STREQ(key, "law");
  EXPECT_EQ(check({{90, -10, Law::Cycloidal}, {360, 10, Law::Cycloidal}}),
            "the follower would go 10 below its drawn position, which is its lowest (the rises' "
            "partial sums stay at or above 0)");
  EXPECT_EQ(at, 0);
  EXPECT_STREQ(key, "rise");
  EXPECT_EQ(check({{90, 10, Law::Cycloidal}, {360, -9.5, Law::Cycloidal}}),
            "the rises sum to 0.5, not 0: the follower would not come back where the turn started");
  EXPECT_EQ(at, -1);
  // Closure and the lowest position to 1e-9: rounding in the rises is no fault.
  EXPECT_EQ(
      check({{90, 0.1, Law::Cycloidal}, {180, 0.2, Law::Cycloidal}, {360, -0.3, Law::Cycloidal}}),
      "");
}

}  // namespace
}  // namespace linkage::cam
