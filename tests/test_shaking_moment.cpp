// The shaking moment as an output (issue 29): its exact derivative with respect to every
// dimension of an offset slider-crank with masses, inertias and gravity, against the moment
// written out in the dimensions' own terms and differentiated by complex step.
#include <gtest/gtest.h>

#include <complex>
#include <map>
#include <tuple>

#include "complex_step.h"
#include "examples.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "mechanisms.h"
#include "optimize_checks.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;

// A body's state per crank radian: a point's position and acceleration (its base point's b,
// b2 and its line's unit u, u2), its angular acceleration cross(u, u2).
struct BodyLine {
  CVec b, b2, u, u2;
  CVec at(double along, double across) const { return b + C(along) * u + C(across) * perp(u); }
  CVec acc(double along, double across) const { return b2 + C(along) * u2 + C(across) * perp(u2); }
  C alpha() const { return cross(u, u2); }
};

struct Masses {
  double m1 = 0.1, m2 = 0.15, m3 = 0.2, j1 = 20, j2 = 90;
  double a1 = 0, p1 = 0, a2 = 0, p2 = 0;  // the crank's and the rod's centres on their lines
  Vec2 off3 = Vec2::Zero();               // the block's centre from B, as drawn
};

// The shaking moment about the drawing's origin, N m: the bodies' weights and inertia forces
// at their centres and their inertia couples (linkage/dynamics.h shaking()).
C moment(const std::map<std::string, C>& v, const Masses& ms, double r, double l, double e,
         double phi, double rpm, const Vec2& g) {
  const CVec O{v.at("ground.O.x"), v.at("ground.O.y")};
  const C cr = r + v.at("crank.O-A"), rl = l + v.at("rod.A-B");
  // The guide turns; the block keeps its drawing (setDimension turns no body pinned to the slot).
  const C turn = v.at("ground.guide.angle") * (M_PI / 180);
  const CVec p0{e - v.at("ground.guide.offset"), C(0)}, dir{-std::sin(turn), std::cos(turn)};
  const CVec A = O + CVec{cr * std::cos(phi), cr * std::sin(phi)};
  const CVec w = A - p0, vA = perp(A - O), aA = O - A;
  const C c = cross(dir, w), cv = cross(dir, vA), ca = cross(dir, aA);
  const C root = std::sqrt(rl * rl - c * c);
  const CVec B = p0 + (dot(dir, w) + root) * dir;
  const C s2 = dot(dir, aA) - (cv * cv + c * ca) / root - c * c * cv * cv / (root * root * root);
  const CVec aB = s2 * dir;
  const BodyLine crank{O, CVec{0, 0}, (C(1) / cr) * (A - O), (C(1) / cr) * aA};
  const BodyLine rod{A, aA, (C(1) / rl) * (B - A), (C(1) / rl) * (aB - aA)};
  const double w2 = std::pow(rpm * 2 * M_PI / 60, 2) / 1000;  // rad^2/s^2, mm -> m
  const CVec G{C(g.x()), C(g.y())};
  auto about = [&](double m, const CVec& at, const CVec& acc) {  // N mm
    return cross(at, C(m) * G - C(m * w2) * acc);
  };
  const C sum =
      about(ms.m1, crank.at(ms.a1, ms.p1), crank.acc(ms.a1, ms.p1)) -
      C(ms.j1 * w2) * crank.alpha() + about(ms.m2, rod.at(ms.a2, ms.p2), rod.acc(ms.a2, ms.p2)) -
      C(ms.j2 * w2) * rod.alpha() + about(ms.m3, B + CVec{C(ms.off3.x()), C(ms.off3.y())}, aB);
  return sum / C(1000);
}

TEST(ShakingMoment, SliderCrankMatchesClosedFormByComplexStep) {
  const double r = 20, l = 70, e = 8, crankDeg = 30, rpm = 600;
  const Vec2 g(0, -9.81);
  test::SliderCrank sc = test::sliderCrank(r, l, e, crankDeg, Direction::Ccw, rpm);
  const Vec2 A0 = sc.m.point(sc.A)->pos, B0 = sc.m.point(sc.B)->pos;
  Masses ms;
  const Vec2 c1(6, 9), c2 = A0 + 0.4 * (B0 - A0) + Vec2(4, -1);
  ms.off3 = Vec2(1, 2);
  sc.m.body(sc.crank)->mass = Mass{ms.m1, c1, ms.j1, ""};
  sc.m.body(sc.rod)->mass = Mass{ms.m2, c2, ms.j2, ""};
  sc.m.body(sc.slider)->mass = Mass{ms.m3, B0 + ms.off3, 0, ""};
  sc.m.gravity = g;
  auto parts = [](Vec2 from, Vec2 to, Vec2 c) {
    const Vec2 u = (to - from).normalized();
    return std::pair{(c - from).dot(u), (c - from).dot(perp(u))};
  };
  std::tie(ms.a1, ms.p1) = parts(Vec2(0, 0), A0, c1);
  std::tie(ms.a2, ms.p2) = parts(A0, B0, c2);
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(sc.m);
  std::map<std::string, C> base;
  for (const Dimension& d : dims) base[d.name] = 0;
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims).ok());
  std::vector<double> peak(dims.size(), 0), err(dims.size(), 0);
  for (int deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    ASSERT_TRUE(s.at(k).ok());
    const double phi = (crankDeg + deg) * M_PI / 180;
    Vec2 F;
    double M = 0;
    shaking(k, F, M);
    const C exact = moment(base, ms, r, l, e, phi, rpm, g);
    ASSERT_NEAR(M, exact.real(), 1e-12 * (1 + std::abs(M))) << deg;
    for (size_t d = 0; d < dims.size(); ++d) {
      std::map<std::string, C> v = base;
      v.at(dims[d].name) += C(0, kH);
      const double want = moment(v, ms, r, l, e, phi, rpm, g).imag() / kH;
      peak[d] = std::max(peak[d], std::abs(want));
      err[d] =
          std::max(err[d], std::abs(shakingMomentSensitivity(k, s, static_cast<int>(d)) - want));
    }
  }
  for (size_t d = 0; d < dims.size(); ++d) {
    std::printf("  d M / d %-20s peak %.6g N m per unit, worst error %.2e\n", dims[d].name.c_str(),
                peak[d], err[d]);
    EXPECT_GT(peak[d], 1e-4) << dims[d].name;  // every dimension moves the moment
    EXPECT_LT(err[d], 1e-10 * peak[d]) << dims[d].name;
  }
}

// The four-bar example with masses, inertias and gravity: its rocker turns to and fro about
// O4, away from the origin, so a counterweight there has every part of its moment.
Kinematics fourBarWithMasses() {
  Mechanism m = test::example("four-bar-crank-rocker");
  auto body = [&](const char* point) { return m.body(m.point(*m.findPoint(point))->body); };
  body("crank.A")->mass = Mass{0.1, Vec2(5, 8), 20, ""};
  body("coupler.A")->mass = Mass{0.3, Vec2(40, 40), 200, ""};
  body("rocker.B")->mass = Mass{0.2, Vec2(64, 24), 50, ""};
  m.gravity = Vec2(0, -9.81);
  m.driver->rpm = 300;
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  return k;
}

OptimizeSpec momentSpec(const std::vector<OptVariable>& vars, double limit) {
  OptimizeSpec spec;
  spec.variables = vars;
  OptTarget t;
  t.kind = OptTarget::Kind::Shaking;
  t.moment = true;
  t.limitN = limit;
  spec.targets = {t};
  spec.steps = 120;
  return spec;
}

TEST(OptimizeShakingMoment, GradientMatchesCentralDifferences) {
  const Kinematics k = fourBarWithMasses();
  test::expectGradientAt(k,
                         momentSpec({{"crank.O2-A", 5, 30},
                                     {"coupler.A-B", 50, 90},
                                     {"rocker.B-O4", 30, 70},
                                     {"ground.O4.x", 40, 80},
                                     {"ground.O2.y", -20, 20}},
                                    0),
                         {20, 70, 50, 60, 0});
  test::expectGradientAt(k,
                         momentSpec({{"crank.counterweight.x", -50, 50},
                                     {"crank.counterweight.y", -50, 50},
                                     {"rocker.counterweight.x", -50, 50},
                                     {"rocker.counterweight.y", -50, 50}},
                                    0),
                         {2, 5, 4, -3});
}

// The counterweights the search varies, written into the design as masses of their bodies
// (linkage/balance.h addCounterweights) and the design solved again: its shaking moment at the
// peak's angle is the peak the search measured.
TEST(OptimizeShakingMoment, CounterweightsWrittenInBearTheMeasuredPeak) {
  const Kinematics k = fourBarWithMasses();
  const OptimizeSpec spec = momentSpec({{"crank.counterweight.x", -50, 50},
                                        {"crank.counterweight.y", -50, 50},
                                        {"rocker.counterweight.x", -50, 50},
                                        {"rocker.counterweight.y", -50, 50}},
                                       0);
  const std::vector<double> x{2, 5, 4, -3};
  const Evaluation e = evaluate(k, spec, x, false);
  ASSERT_TRUE(e.feasible) << e.why;
  Mechanism m = k.mechanism();
  std::vector<Counterweight> cws(2);
  for (int c = 0; c < 2; ++c) {
    const PointId on = *m.findPoint(c == 0 ? "crank.A" : "rocker.B");
    ASSERT_TRUE(counterweightOn(m, m.point(on)->body, cws[c]).ok());
    cws[c].staticMoment = Vec2(x[2 * c], x[2 * c + 1]);
    cws[c].kg = cws[c].staticMoment.norm() / cws[c].maxRadiusMm;
  }
  addCounterweights(m, cws);
  Kinematics written;
  ASSERT_TRUE(written.load(m).ok());
  written.setAccelerations(true);
  double largest = 0;
  for (int i = 0; i < 3600; ++i) {  // the peak is no lower than any sample of the written design
    ASSERT_TRUE(written.moveTo(i * 0.1).ok());
    Vec2 F;
    double M = 0;
    shaking(written, F, M);
    largest = std::max(largest, std::abs(M));
  }
  ASSERT_TRUE(written.moveTo(e.measures[0][1]).ok());
  Vec2 F;
  double M = 0;
  shaking(written, F, M);
  std::printf("  peak %.12g N m at %.6f degrees; written design there %.12g, sampled %.12g\n",
              e.measures[0][0], e.measures[0][1], std::abs(M), largest);
  EXPECT_NEAR(std::abs(M), e.measures[0][0], 1e-12 * e.measures[0][0]);
  EXPECT_GE(e.measures[0][0], largest - 1e-12 * largest);
  EXPECT_LT(e.measures[0][0], largest + 1e-6 * largest);
}

// The peak of the moment lowered by dimensions below a limit, and the written design measured
// again: its moment nowhere above the limit over a fine sweep.
TEST(OptimizeShakingMoment, DimensionsBringThePeakUnderALimit) {
  const Kinematics k = fourBarWithMasses();
  OptimizeSpec spec = momentSpec({{"rocker.B-O4", 40, 60}, {"ground.O4.x", 50, 70}}, 0);
  const Evaluation before = evaluate(k, spec, {50, 60}, false);
  ASSERT_TRUE(before.feasible) << before.why;
  spec.targets[0].limitN = 0.8 * before.measures[0][0];
  spec.starts = 4;
  const OptimizeResult r = optimize(k, spec);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  std::printf(
      "  peak %.6g -> %.6g N m (limit %.6g), rocker %.6g mm, O4.x %.6g mm, %d of %d starts\n",
      before.measures[0][0], r.atAfter.measures[0][0], spec.targets[0].limitN, r.after[0],
      r.after[1], r.foundBest, r.starts);
  EXPECT_LE(r.atAfter.measures[0][0], spec.targets[0].limitN * (1 + 1e-9));
  Kinematics written;
  ASSERT_TRUE(written.load(r.design).ok());
  written.setAccelerations(true);
  double largest = 0;
  for (int i = 0; i < 3600; ++i) {
    ASSERT_TRUE(written.moveTo(i * 0.1).ok());
    Vec2 F;
    double M = 0;
    shaking(written, F, M);
    largest = std::max(largest, std::abs(M));
  }
  EXPECT_LE(largest, spec.targets[0].limitN * (1 + 1e-9));
  EXPECT_GT(largest, 0.99 * spec.targets[0].limitN);  // the limit binds: the search stops there
}

}  // namespace
}  // namespace linkage
