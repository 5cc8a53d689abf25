// Sampled motion curves: exact samples, jerk against the slider-crank's closed form, extremes
// against roots found in __float128, a crank that cannot turn the whole way.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "examples.h"
#include "linkage/extremes.h"
#include "linkage/motion_samples.h"
#include "mechanisms.h"
#include "reference/dual.h"

namespace linkage {
namespace {

using Q = __float128;

using test::example;

Kinematics loaded(const Mechanism& m) {
  Kinematics k;
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

// The example's slider-crank (r = 15, l, outer dead centre at crank angle 0, 1000 rpm ccw):
// the needle bar's motion and jerk at crank angle phi (rad).
template <class T>
linkref::SliderJerk<T> needleBar(T l, T phi) {
  return linkref::slider_crank_jerk(linkref::slider_crank_22a<T>(l), phi);
}

// The reference's jerk (a dual number through the closed form) against the third derivative
// by hand: y = r sin t + D, D = sqrt(l^2 - r^2 cos^2 t), t = pi/2 + phi, u = sin t cos t:
// y''' = -r cos t - 2 r^2 sin 2t / D - 3 r^4 u cos 2t / D^3 + 3 r^6 u^3 / D^5.
TEST(MotionSamples, ReferenceJerkIsTheThirdDerivative) {
  for (Q l : {Q(30), Q(50)})
    for (Q phi : {Q(0.1), Q(1), Q(2.5), Q(4)}) {
      const Q r = 15, t = linkref::pi<Q>() / 2 + phi, c = cosq(t), sn = sinq(t), u = sn * c;
      const Q D = sqrtq(l * l - r * r * c * c), w = linkref::rpm_to_rad_s(Q(1000));
      const Q y3 = -r * c - 2 * r * r * 2 * u / D -
                   3 * powq(r, 4) * u * (c * c - sn * sn) / powq(D, 3) +
                   3 * powq(r, 6) * u * u * u / powq(D, 5);
      EXPECT_LT(double(fabsq(needleBar<Q>(l, phi).jy - w * w * w * y3)),
                1e-20 * double(w * w * w * r));
    }
}

TEST(MotionSamples, SamplesAreTheSolversOwnAndTheGivenSolverDoesNotMove) {
  const Mechanism m = example("wanzer-inversion-2");
  Kinematics k = loaded(m);
  const PointId G = m.outputs.at(0);
  const BodyId tri = m.bodyNamed("triangle")->id;
  SampleSpec spec;
  spec.points = {G};
  spec.bodies = {tri};
  spec.steps = 90;
  spec.revs = 2;
  const MotionSamples s = sampleMotion(k, spec);
  ASSERT_TRUE(s.complete()) << s.status.message;
  EXPECT_TRUE(s.periodic);
  EXPECT_EQ(k.crankDeg(), 0);
  ASSERT_EQ(s.size(), 181);
  Kinematics fresh = loaded(m);
  for (long long i = 0; i < s.size(); ++i) {
    ASSERT_EQ(s.crankDeg[i], i * 4.0);
    ASSERT_TRUE(fresh.moveTo(s.crankDeg[i]).ok());
    const Kinematics::PointMotion mm = fresh.motion(G);
    EXPECT_EQ(s.points[0].p[i], mm.position) << i;
    EXPECT_EQ(s.points[0].v[i], mm.velocity) << i;
    EXPECT_EQ(s.points[0].a[i], mm.acceleration) << i;
    EXPECT_EQ(s.bodies[0].angle[i], fresh.bodyAngle(tri));
    EXPECT_EQ(s.bodies[0].omega[i], fresh.bodyOmega(tri));
    EXPECT_EQ(s.bodies[0].alpha[i], fresh.bodyAlpha(tri));
  }
  const Curve vy = curveOf(s, Quantity::ofPoint(G, Quantity::Component::Y), Order::Velocity);
  const Curve speed =
      curveOf(s, Quantity::ofPoint(G, Quantity::Component::Magnitude), Order::Velocity);
  const Curve along = curveOf(s, Quantity::ofPoint(G, Quantity::Component::Along, Vec2(0, -3)),
                              Order::Acceleration);
  for (long long i = 0; i < s.size(); ++i) {
    EXPECT_EQ(vy.values[i], s.points[0].v[i].y());
    EXPECT_EQ(speed.values[i], s.points[0].v[i].norm());
    EXPECT_NEAR(along.values[i], -s.points[0].a[i].y(), 1e-12 * std::abs(along.values[i]));
  }
}

TEST(MotionSamples, AccelerationsOnlyWhenAsked) {
  const Mechanism m = example("wanzer-inversion-1");
  Kinematics k = loaded(m);
  SampleSpec spec;
  spec.points = m.outputs;
  spec.bodies = {m.bodyNamed("triangle")->id};
  spec.accelerations = false;
  const MotionSamples s = sampleMotion(k, spec);
  ASSERT_TRUE(s.complete());
  EXPECT_TRUE(s.points[0].a.empty());
  EXPECT_TRUE(s.bodies[0].alpha.empty());
  EXPECT_FALSE(s.kinematics.accelerations());
  const Quantity q = Quantity::ofPoint(m.outputs[0], Quantity::Component::Y);
  EXPECT_FALSE(curveOf(s, q, Order::Acceleration).status.ok());
  EXPECT_FALSE(curveOf(s, q, Order::Jerk).status.ok());
  EXPECT_TRUE(curveOf(s, q, Order::Velocity).status.ok());
  EXPECT_TRUE(k.accelerations());  // the caller's solver keeps its setting
}

TEST(MotionSamples, BadRequestsAreRefusedWithAReason) {
  const Mechanism m = example("wanzer-inversion-1");
  Kinematics k = loaded(m);
  Mechanism other = example("wanzer-inversion-2");
  SampleSpec spec;
  spec.points = other.outputs;  // another mechanism's id
  EXPECT_EQ(sampleMotion(k, spec).status.code, StatusCode::BadModel);
  spec.points = m.outputs;
  spec.steps = 7;
  spec.revs = 0.5;
  EXPECT_EQ(sampleMotion(k, spec).status.code, StatusCode::BadModel);
  spec.steps = 360;
  spec.revs = 1;
  const MotionSamples s = sampleMotion(k, spec);
  const Curve c = curveOf(
      s, Quantity::ofPoint(m.outputs[0], Quantity::Component::Along, Vec2(0, 0)), Order::Position);
  EXPECT_EQ(c.status.code, StatusCode::BadModel);
  EXPECT_NE(c.status.message.find("direction"), std::string::npos);
}

// Seed 002's slider-crank: the solver's jerk is the spectral derivative of its exact
// accelerations; the closed form's is the derivative of the closed-form acceleration.
TEST(MotionSamples, JerkOfTheSliderCrankMatchesTheClosedForm) {
  for (const auto& [name, l] :
       {std::pair{"slider-crank-22a-lambda-0.3", 50.0}, {"slider-crank-22a-lambda-0.5", 30.0}}) {
    SCOPED_TRACE(name);
    const Mechanism m = example(name);
    Kinematics k = loaded(m);
    const PointId B = *m.findPoint("needlebar.B");
    for (long long steps : {360LL, 90LL, 24LL}) {
      SCOPED_TRACE(steps);
      SampleSpec spec;
      spec.points = {B};
      spec.steps = steps;
      spec.revs = 2;
      const MotionSamples s = sampleMotion(k, spec);
      ASSERT_TRUE(s.periodic);
      const Curve j = curveOf(s, Quantity::ofPoint(B, Quantity::Component::Y), Order::Jerk);
      ASSERT_TRUE(j.status.ok()) << j.status.message;
      ASSERT_EQ(j.values.size(), size_t(s.size()));
      double err = 0, peak = 0;
      for (long long i = 0; i < s.size(); ++i) {
        const auto ref = needleBar<Q>(Q(l), Q(s.crankDeg[i]) * linkref::pi<Q>() / 180);
        err = std::max(err, std::abs(j.values[i] - double(ref.jy)));
        peak = std::max(peak, std::abs(double(ref.jy)));
      }
      EXPECT_LE(err, j.errorEstimate);
      if (steps >= 90) {
        EXPECT_LT(err, 1e-9 * peak);
        EXPECT_LT(j.errorEstimate, 1e-8 * peak);
      }
      if (steps == 24 && l == 30.0) EXPECT_GT(err, 1e-9 * peak);  // too few: the estimate says so
      // Components and magnitudes of the jerk vector: x is 0 on the guide.
      const Curve jm =
          curveOf(s, Quantity::ofPoint(B, Quantity::Component::Magnitude), Order::Jerk);
      for (long long i = 0; i < s.size(); ++i)
        EXPECT_NEAR(jm.values[i], std::abs(j.values[i]), 1e-12 * peak);
    }
  }
}

// The angle in (-180, 180] from a to b, degrees.
double angleBetween(double a, double b) {
  return std::remainder(b - a, 360.0);
}

// Zero of f between a and b (signs differ), by bisection in __float128.
template <class F>
Q bisect(F f, Q a, Q b) {
  Q fa = f(a);
  for (int i = 0; i < 200; ++i) {
    const Q c = (a + b) / 2, fc = f(c);
    if ((fc > 0) == (fa > 0))
      a = c, fa = fc;
    else
      b = c;
  }
  return (a + b) / 2;
}

TEST(Extremes, SliderCrankStrokePeakVelocityAndAccelerationExactEvenFromCoarseSamples) {
  const double l = 30, r = 15;  // lambda = 0.5
  const Mechanism m = example("slider-crank-22a-lambda-0.5");
  Kinematics k = loaded(m);
  const PointId B = *m.findPoint("needlebar.B");
  const Quantity y = Quantity::ofPoint(B, Quantity::Component::Y);
  const Q deg = linkref::pi<Q>() / 180;
  // Peak velocity: where the closed-form acceleration vanishes (seed 002: near cos phi_B =
  // (1 +- sqrt(1 + 8 lambda^2)) / 4 lambda); peak acceleration: where the jerk vanishes, near
  // 180 +- 60 degrees of this crank angle. Found in __float128 from sign changes.
  auto acc = [&](Q phi) { return needleBar<Q>(Q(l), phi * deg).ay; };
  auto jerk = [&](Q phi) { return needleBar<Q>(Q(l), phi * deg).jy; };
  Q vMaxAt = 0, vMinAt = 0, aMaxAt = 0;
  for (int d = 0; d < 360; ++d) {
    const Q a0 = acc(d), a1 = acc(d + 1);
    const bool down = a0 > 0 && a1 <= 0, up = a0 < 0 && a1 >= 0;
    if (down) vMaxAt = bisect(acc, Q(d), Q(d + 1));  // v rises then falls: a maximum
    if (up) vMinAt = bisect(acc, Q(d), Q(d + 1));
    if (d > 90 && d < 180 && jerk(d) > 0 && jerk(d + 1) <= 0) aMaxAt = bisect(jerk, Q(d), Q(d + 1));
  }
  ASSERT_GT(double(aMaxAt), 0);
  for (long long steps : {360LL, 36LL}) {
    SCOPED_TRACE(steps);
    SampleSpec spec;
    spec.points = {B};
    spec.steps = steps;
    const MotionSamples s = sampleMotion(k, spec);
    ASSERT_TRUE(s.periodic);
    const Extremes p = extremesOf(s, y, Order::Position);
    EXPECT_NEAR(p.max.value, r + l, 1e-12);
    EXPECT_NEAR(p.min.value, l - r, 1e-12);
    EXPECT_NEAR(p.range(), 2 * r, 1e-12);  // the stroke
    EXPECT_NEAR(angleBetween(p.max.crankDeg, 0), 0, 1e-9);
    EXPECT_NEAR(p.min.crankDeg, 180, 1e-9);
    EXPECT_GE(p.max.crankDeg, 0);
    EXPECT_LT(p.max.crankDeg, 360);

    const Extremes v = extremesOf(s, y, Order::Velocity);
    EXPECT_EQ(v.max.method, Extreme::Method::Root);
    EXPECT_NEAR(v.max.crankDeg, double(vMaxAt), 1e-9);
    EXPECT_NEAR(v.min.crankDeg, double(vMinAt), 1e-9);
    const double vPeak = double(needleBar<Q>(Q(l), vMaxAt * deg).vy);
    EXPECT_NEAR(v.max.value, vPeak, 1e-12 * std::abs(vPeak));
    EXPECT_NEAR(v.min.value, double(needleBar<Q>(Q(l), vMinAt * deg).vy), 1e-12 * std::abs(vPeak));

    const Extremes a = extremesOf(s, y, Order::Acceleration);
    const double w = s.omega;
    // Outer dead centre: -r w^2 (1 + lambda), seed 002's largest acceleration.
    EXPECT_NEAR(a.min.value, -r * w * w * 1.5, 1e-12 * r * w * w);
    EXPECT_NEAR(angleBetween(a.min.crankDeg, 0), 0, 1e-5);
    EXPECT_EQ(a.max.method, Extreme::Method::Minimised);
    const double aMax = double(needleBar<Q>(Q(l), aMaxAt * deg).ay);
    EXPECT_NEAR(a.max.value, aMax, 1e-12 * std::abs(aMax));
    // Two maxima of equal height (symmetric about 180 degrees): either one.
    EXPECT_NEAR(std::min(std::abs(a.max.crankDeg - double(aMaxAt)),
                         std::abs(a.max.crankDeg - (360 - double(aMaxAt)))),
                0, 1e-5);
    EXPECT_EQ(a.peak().value, a.min.value);
  }
}

// A non-Grashof four-bar driven at a link that cannot turn fully: the sweep stops before the
// angle it cannot pass, says why, and keeps the part that exists on the branch it started on.
TEST(MotionSamples, CrankThatCannotTurnFullyGivesThePartThatExists) {
  auto f = test::fourBar(100, 60, 40, 70, 30);  // locks 52.819 degrees on
  Kinematics k = loaded(f.m);
  SampleSpec spec;
  spec.points = {f.P, f.B};
  spec.bodies = {f.rocker};
  const MotionSamples s = sampleMotion(k, spec);
  EXPECT_FALSE(s.complete());
  EXPECT_EQ(s.status.code, StatusCode::Unreachable) << s.status.message;
  ASSERT_TRUE(s.status.lastReachedDeg.has_value());
  EXPECT_NEAR(*s.status.lastReachedDeg, 52.8192, 1e-3);
  EXPECT_FALSE(s.status.message.empty());
  ASSERT_EQ(s.size(), 53);  // 0 ... 52 degrees
  EXPECT_FALSE(s.periodic);
  Kinematics fresh = loaded(f.m);
  for (long long i = 0; i < s.size(); ++i) {
    ASSERT_TRUE(fresh.moveTo(s.crankDeg[i]).ok());
    EXPECT_EQ(s.points[1].p[i], fresh.position(f.B));  // the same branch as a fresh track
    for (const Vec2& v : {s.points[1].p[i], s.points[1].v[i], s.points[1].a[i]})
      EXPECT_TRUE(std::isfinite(v.x()) && std::isfinite(v.y())) << i;
  }
  const Quantity q = Quantity::ofPoint(f.B, Quantity::Component::X);
  const Curve j = curveOf(s, q, Order::Jerk);
  EXPECT_FALSE(j.status.ok());
  EXPECT_NE(j.status.message.find("did not complete a revolution"), std::string::npos)
      << j.status.message;
  Status why;
  EXPECT_TRUE(harmonicsOf(s, q, Order::Position, 10, &why).terms.empty());
  EXPECT_FALSE(why.ok());
  // Extremes of what exists: a sample at an end of the sweep stays as it is (it has one
  // neighbour), one inside is placed between its neighbours.
  for (const Quantity& c : {q, Quantity::ofPoint(f.P, Quantity::Component::Y)}) {
    const Extremes e = extremesOf(s, c, Order::Position);
    ASSERT_TRUE(e.status.ok());
    const Curve x = curveOf(s, c, Order::Position);
    const auto hi = std::max_element(x.values.begin(), x.values.end());
    const auto lo = std::min_element(x.values.begin(), x.values.end());
    for (const auto& [it, ex, sign] : {std::tuple{hi, e.max, 1.0}, std::tuple{lo, e.min, -1.0}}) {
      const bool atEnd = it == x.values.begin() || it + 1 == x.values.end();
      EXPECT_EQ(ex.method, atEnd ? Extreme::Method::Sample : Extreme::Method::Root);
      EXPECT_GE(sign * ex.value, sign * *it);
      if (atEnd) EXPECT_EQ(ex.value, *it);
    }
  }
}

TEST(Harmonics, BodyAngleLessItsSteadyTurning) {
  const Mechanism m = example("slider-crank-22a-lambda-0.5");
  Kinematics k = loaded(m);
  const BodyId crank = m.bodyNamed("crank")->id;
  SampleSpec spec;
  spec.bodies = {crank};
  const MotionSamples s = sampleMotion(k, spec);
  // The crank turns steadily: one whole turn and nothing periodic left.
  Status why;
  const Spectrum sp = harmonicsOf(s, Quantity::ofBody(crank), Order::Position, 5, &why);
  ASSERT_TRUE(why.ok()) << why.message;
  for (const Harmonic& h : sp.terms) EXPECT_LT(h.amplitude, 1e-12);
  const Curve w = curveOf(s, Quantity::ofBody(crank), Order::Velocity);
  for (double x : w.values) EXPECT_NEAR(x, s.omega, 1e-12 * s.omega);  // ccw: positive
}

}  // namespace
}  // namespace linkage
