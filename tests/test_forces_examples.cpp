// The examples with masses (resources/examples/masses.py: slider-crank-22a-masses,
// wanzer-inversion-2-masses, drop-feed) against closed forms and derivations written here from
// their dimensions, not from the program's output: the 22-A needle bar's inertia force from its
// exact acceleration (seed 002), the needle load's share of the driver's torque by virtual work,
// the drop feed's positions by intersecting circles and its shaking force from their
// derivatives. Each file loads, solves in closed form, is drawn exactly closed and is as the
// program saves it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "examples.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;
const char* const kExamples[] = {"slider-crank-22a-masses", "wanzer-inversion-2-masses",
                                 "drop-feed"};

Kinematics loaded(const Mechanism& m) {
  Kinematics k;
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

PointId pointOf(const Mechanism& m, const std::string& dotted) {
  const std::optional<PointId> p = m.findPoint(dotted);
  EXPECT_TRUE(p.has_value()) << dotted;
  return p.value_or(PointId{});
}

TEST(ForcesExamples, LoadSolveInClosedFormAndAreAsTheProgramSavesThem) {
  for (const char* name : kExamples) {
    const Mechanism m = test::example(name);
    Kinematics k = loaded(m);
    EXPECT_TRUE(k.closedForm()) << name;
    EXPECT_FALSE(k.assembly().moved) << name;
    EXPECT_EQ(k.structure().mobility, 1) << name;
    ForceSolver f;
    EXPECT_TRUE(f.prepare(k).ok()) << name;
    EXPECT_TRUE(f.result().undetermined.empty()) << name;
    for (const Body& b : m.bodies)
      if (!b.ground && b.name != "armshaft") EXPECT_TRUE(b.mass.has_value()) << name << b.name;
    const std::string path = std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json";
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(serializeMechanism(m), text) << path;
  }
}

// Seed 002's needle bar: a central slider-crank, r = 15, l = 30, drawn with the crank straight up
// along the guide, turning ccw at 3000 rpm. Crank pin A = r (-sin phi, cos phi), the needle bar's
// pin B = (0, y), y = r cos phi + D, D = sqrt(l^2 - r^2 sin^2 phi); its exact acceleration
// differentiated twice. The crank's centre of mass is on its axis, the rod's a third of the way
// from A to B; no gravity: the shaking force is -(m_rod a_rod + m_bar a_B), and the rod pushes
// the needle bar with m_bar a_B (the seed's inertia force, reversed).
TEST(ForcesExamples, TheNeedleBarOf22AShakesTheFrameWithItsExactInertiaForce) {
  const Mechanism m = test::example("slider-crank-22a-masses");
  ASSERT_EQ(m.driver->rpm, 3000);
  ASSERT_FALSE(m.gravity.has_value());
  const double r = 15, l = 30, w = 3000 * 2 * M_PI / 60;
  const double mRod = m.bodyNamed("rod")->mass->kg, mBar = m.bodyNamed("needlebar")->mass->kg;
  ASSERT_EQ(m.bodyNamed("rod")->mass->com, Vec2(0, 25));  // A + (B - A) / 3 in the drawing
  ASSERT_EQ(m.bodyNamed("crank")->mass->com, Vec2(0, 0));
  Kinematics k = loaded(m);
  ForceSolver f;
  ASSERT_TRUE(f.prepare(k).ok());
  const size_t rodPin = 2;  // pin rod.B - needlebar.B: the force on the rod from the needle bar
  ASSERT_EQ(m.pointLabel(m.joints[rodPin].a), "rod.B");
  const double peak = mBar * r * w * w * 1.5 / 1000;  // m r w^2 (1 + lambda), N
  for (double deg = 0; deg < 360; deg += 7.5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Forces& out = f.compute(k);
    ASSERT_TRUE(out.status.ok());
    const double phi = deg * kDeg, c = std::cos(phi), s = std::sin(phi);
    const double D = std::sqrt(l * l - r * r * s * s);
    const double aB =
        -r * w * w * (c + r * (c * c - s * s) / D + r * r * r * s * s * c * c / (D * D * D));
    const Vec2 aA = -w * w * Vec2(-r * s, r * c);
    const Vec2 aRod = (2 * aA + Vec2(0, aB)) / 3;
    const Vec2 shaking = -(mRod * aRod + mBar * Vec2(0, aB)) / 1000;
    EXPECT_NEAR(out.shakingForceN.x(), shaking.x(), 1e-12 * peak) << deg;
    EXPECT_NEAR(out.shakingForceN.y(), shaking.y(), 1e-12 * peak) << deg;
    EXPECT_NEAR(out.joints[rodPin].force.y(), -mBar * aB / 1000, 1e-12 * peak) << deg;
  }
}

// The needle's penetration load: what it adds to the driver's torque is, by virtual work,
// -F . v_N / omega_driver (the load's power taken from the driver), inside its window and
// nothing outside; the windows bracket the bottom dead centre at 81.5 degrees, and both ends
// are 10 mm above it (to half a degree), where the point enters and leaves the material.
TEST(ForcesExamples, TheWanzerNeedleLoadCostsTheDriverItsPower) {
  const Mechanism m = test::example("wanzer-inversion-2-masses");
  Mechanism unloaded = m;
  unloaded.loads.clear();
  ASSERT_EQ(m.loads.size(), 2u);
  Kinematics k = loaded(m), k0 = loaded(unloaded);
  ForceSolver f, f0;
  ASSERT_TRUE(f.prepare(k).ok() && f0.prepare(k0).ok());
  const PointId N = pointOf(m, "needlebar.N");
  ASSERT_EQ(m.loads[0].point, N);
  const double w = k.bodyOmega(m.bodyNamed("disk")->id);  // the driver's, clockwise: < 0
  ASSERT_LT(w, 0);
  double lowest = 1e9, lowestDeg = 0;
  for (double deg = 0; deg < 360; deg += 0.5) {
    ASSERT_TRUE(k.moveTo(deg).ok() && k0.moveTo(deg).ok());
    const Forces &a = f.compute(k), &b = f0.compute(k0);
    ASSERT_TRUE(a.status.ok() && b.status.ok());
    Vec2 F = Vec2::Zero();
    for (const Load& load : m.loads)
      if (load.activeAt(deg)) F += load.forceN;
    const double power = 1e-3 * F.dot(k.velocity(N));  // W
    ASSERT_NEAR(k.bodyOmega(m.bodyNamed("disk")->id), w, 1e-12 * std::abs(w));
    EXPECT_NEAR(a.driverTorqueNm - b.driverTorqueNm, -power / w, 1e-12 * (1 + std::abs(power)))
        << deg;
    if (k.position(N).y() < lowest) lowest = k.position(N).y(), lowestDeg = deg;
  }
  EXPECT_EQ(lowestDeg, 81.5);
  for (double deg : {47.0, 233.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    EXPECT_NEAR(k.position(N).y(), lowest + 10, 0.25) << deg;  // to half a degree
  }
  EXPECT_TRUE(m.loads[0].activeAt(60) && !m.loads[0].activeAt(100));
  EXPECT_TRUE(m.loads[1].activeAt(100) && !m.loads[1].activeAt(240));
}

// The drop feed by hand: the lower shaft turns with the arm shaft (a 1:1 belt); the advance
// four-bar L-Ea-P-R by intersecting circles (P on the circle of 24 about R, at |Ea P| from Ea);
// F is R - 40/24 (P - R); the feed bar's C where the circle about the lift eccentric El (the
// strap El-C) meets the circle about F (|FC|); every body's pose from two of its points.
struct FeedPose {
  Vec2 Ea, El, P, F, C;
};

Vec2 meet(const Vec2& c0, double r0, const Vec2& c1, double r1, const Vec2& near) {
  const Vec2 e = c1 - c0;
  const double d = e.norm(), a = (r0 * r0 - r1 * r1 + d * d) / (2 * d);
  const double h = std::sqrt(r0 * r0 - a * a);
  const Vec2 u = e / d, n(-u.y(), u.x());
  const Vec2 p = c0 + a * u + h * n, q = c0 + a * u - h * n;
  return (p - near).norm() < (q - near).norm() ? p : q;
}

FeedPose feedAt(double phi) {
  const Vec2 R(-70, 24), P0(-70, 0), F0(-70, 64), C0(0, 50);
  FeedPose p;
  p.Ea = 4.5 * Vec2(-std::sin(phi), std::cos(phi));
  p.El = p.Ea / 3;
  p.P = meet(p.Ea, (P0 - Vec2(0, 4.5)).norm(), R, 24, P0);
  p.F = R - (40.0 / 24) * (p.P - R);
  p.C = meet(p.El, 48.5, p.F, (C0 - F0).norm(), C0);
  return p;
}

// A point fixed in a body drawn with points a0, b0 at the pose where they are a, b.
Vec2 carried(const Vec2& x0, const Vec2& a0, const Vec2& b0, const Vec2& a, const Vec2& b) {
  const double t = std::atan2((b - a).y(), (b - a).x()) - std::atan2((b0 - a0).y(), (b0 - a0).x());
  const Vec2 d = x0 - a0;
  return a +
         Vec2(std::cos(t) * d.x() - std::sin(t) * d.y(), std::sin(t) * d.x() + std::cos(t) * d.y());
}

// Sum of m x_com over the moving bodies (kg mm) at crank angle phi.
Vec2 firstMoment(const Mechanism& m, double phi) {
  const FeedPose p = feedAt(phi), p0 = feedAt(0);
  Vec2 sum = Vec2::Zero();
  for (const Body& b : m.bodies) {
    if (!b.mass) continue;
    const Vec2 c = b.mass->com;
    Vec2 x = c;
    if (b.name == "lowershaft") x = carried(c, Vec2::Zero(), p0.Ea, Vec2::Zero(), p.Ea);
    if (b.name == "advancerod") x = carried(c, p0.Ea, p0.P, p.Ea, p.P);
    if (b.name == "feedrock") x = carried(c, Vec2(-70, 24), p0.P, Vec2(-70, 24), p.P);
    if (b.name == "liftstrap") x = carried(c, p0.El, p0.C, p.El, p.C);
    if (b.name == "feedbar") x = carried(c, p0.F, p0.C, p.F, p.C);
    sum += b.mass->kg * x;
  }
  return sum;
}

TEST(ForcesExamples, TheDropFeedMovesAndShakesAsItsCirclesSay) {
  const Mechanism m = test::example("drop-feed");
  ASSERT_FALSE(m.gravity.has_value());
  Kinematics k = loaded(m);
  const PointId F = pointOf(m, "feedbar.F"), C = pointOf(m, "feedbar.C"),
                D = pointOf(m, "feedbar.D");
  const double w = k.omega(), h = 1e-3;
  double xMin = 1e9, xMax = -1e9;
  for (double deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const double phi = deg * kDeg;
    const FeedPose p = feedAt(phi), p0 = feedAt(0);
    EXPECT_LT((k.position(F) - p.F).norm(), 1e-11) << deg;
    EXPECT_LT((k.position(C) - p.C).norm(), 1e-11) << deg;
    const Vec2 dog = carried(Vec2(20, 70), p0.F, p0.C, p.F, p.C);
    EXPECT_LT((k.position(D) - dog).norm(), 1e-11) << deg;
    xMin = std::min(xMin, p.F.x()), xMax = std::max(xMax, p.F.x());
    // -d2/dt2 of the first moment by the six-point central difference (error ~h^6): N.
    auto M = [&](double t) { return firstMoment(m, t); };
    const Vec2 dd =
        (2 * (M(phi + 3 * h) + M(phi - 3 * h)) - 27 * (M(phi + 2 * h) + M(phi - 2 * h)) +
         270 * (M(phi + h) + M(phi - h)) - 490 * M(phi)) /
        (180 * h * h);
    Vec2 S;
    double moment;
    shaking(k, S, moment);
    EXPECT_LT((S + w * w * dd / 1000).norm(), 1e-6 * 20) << deg;
  }
  EXPECT_NEAR(xMax - xMin, 15, 0.1);  // seed 003's stitch length, as README.md says
}

// A bound that binds: the exchange ends once the counterweights are within the programme's own
// tolerance of it (it used to add the same tangent row until its 200 rounds ran out, CLP keeping
// rows only to 1e-11), with both on the bound and the gap certified.
TEST(ForcesExamples, TheDropFeedsBoundedBalanceEnds) {
  const Mechanism m = test::example("drop-feed");
  Kinematics k = loaded(m);
  BalanceOptions opt;
  opt.bodies = {m.bodyNamed("lowershaft")->id, m.bodyNamed("feedrock")->id};
  opt.measure = BalanceMeasure::Fx;
  opt.maxKgMm = 0.5;
  const BalanceResult r = balanceShaking(k, opt);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LT(r.exchanges, 50);
  for (const Counterweight& c : r.counterweights) EXPECT_NEAR(c.kgMm(), 0.5, 1e-12);
  EXPECT_GE(r.gap(), 0);
  EXPECT_LT(r.gap(), 1e-8 * r.peakBefore);
  EXPECT_LT(r.peakAfter, 0.6 * r.peakBefore);
}

TEST(ForcesExamples, ASolverOutlivesTheKinematicsItWasPreparedOn) {
  // The editor prepares a solver on a copy of its kinematics and computes with later copies of
  // the same revision: what the solver reads at each pose (the loads) must be its own, not read
  // through the first copy, which is gone (a read after free: AddressSanitizer, which
  // scripts/run-tests.sh runs every test under, catches it; a Release build may not).
  const Mechanism m = test::example("wanzer-inversion-2-masses");
  ASSERT_FALSE(m.loads.empty());
  const Kinematics k = loaded(m);
  ForceSolver solver;
  {
    const Kinematics first = k;
    ASSERT_TRUE(solver.prepare(first).ok());
  }
  for (double deg : {60.0, 123.0}) {  // the needle's load acts at 60 degrees, not at 123
    Kinematics later = k;
    ASSERT_TRUE(later.moveTo(deg).ok());
    const Forces& f = solver.compute(later);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const Forces fresh = computeForces(later);
    EXPECT_EQ(f.driverTorqueNm, fresh.driverTorqueNm) << deg;
    EXPECT_EQ(f.shakingForceN, fresh.shakingForceN) << deg;
  }
}

}  // namespace
}  // namespace linkage
