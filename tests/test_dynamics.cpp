// Forces at the driver's constant speed (linkage/dynamics.h) against what must hold whatever the
// mechanism: the power balance, each body's balance, the frame's (the shaking force and moment
// are what the joints put on the ground); and against closed forms: the central slider-crank's
// shaking force from its exact acceleration, a four-bar balanced by the Berkof-Lowen conditions.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <string>

#include "examples.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/force_samples.h"
#include "linkage/gear.h"
#include "linkage/io/model_file.h"
#include "mechanisms.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

// Masses on every moving body, drawn from its points' extent; gravity; a load in a window.
Mechanism withMasses(Mechanism m, unsigned seed, bool loads = true) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 1.0), off(-5, 5);
  for (Body& b : m.bodies) {
    if (b.ground) continue;
    Vec2 c = Vec2::Zero();
    int n = 0;
    for (const Point& p : m.points)
      if (p.body == b.id) c += p.pos, ++n;
    b.mass = Mass{u(rng), c / std::max(n, 1) + Vec2(off(rng), off(rng)), 100 * u(rng), ""};
  }
  m.gravity = Vec2(0, -9.81);
  if (loads)
    for (const Point& p : m.points)
      if (!m.body(p.body)->ground) {
        m.addLoad(Load{p.id, {}, Vec2(3, -7), 0, 40.0, 200.0, ""});
        m.addLoad(Load{{}, p.body, Vec2::Zero(), 0.05, std::nullopt, std::nullopt, ""});
        break;
      }
  return m;
}

Kinematics loaded(const Mechanism& m, bool closedForm) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  return k;
}

// d(kinetic + potential)/dt and the loads' power at k's pose, W.
struct Powers {
  double energyRate = 0, loads = 0;
};
Powers powers(const Kinematics& k) {
  const Mechanism& m = k.mechanism();
  const Vec2 g = m.gravity.value_or(Vec2::Zero());
  Powers p;
  for (const Body& b : m.bodies) {
    if (b.ground || !b.mass) continue;
    const Kinematics::PointMotion c = k.motionOf(b.id, b.mass->com);
    const double w = k.bodyOmega(b.id), al = k.bodyAlpha(b.id);
    // kg mm/s * mm/s^2 = 1e-6 W; kg m/s^2 * mm/s = 1e-3 W.
    p.energyRate += 1e-6 * (b.mass->kg * c.velocity.dot(c.acceleration) + b.mass->jKgMm2 * w * al);
    p.energyRate -= 1e-3 * b.mass->kg * g.dot(c.velocity);
  }
  for (const Load& l : m.loads) {
    if (!l.activeAt(k.crankDeg())) continue;
    if (l.point)
      p.loads += 1e-3 * l.forceN.dot(k.velocity(l.point));
    else
      p.loads += l.torqueNm * k.bodyOmega(l.body);
  }
  return p;
}

// The driver's relative angular velocity (rad/s): the body of its b point against a's.
double driverSpeed(const Kinematics& k) {
  const Mechanism& m = k.mechanism();
  const Joint& d = *m.joint(m.driver->joint);
  return k.bodyOmega(m.point(d.b)->body) - k.bodyOmega(m.point(d.a)->body);
}

struct Case {
  const char* example;
  bool closedForm;
};

TEST(Dynamics, PowerBalanceHoldsAtEveryStep) {
  for (const Case c :
       {Case{"wanzer-inversion-2", true}, Case{"wanzer-inversion-2", false},
        Case{"lockstitch-arm-shaft", true}, Case{"lockstitch-arm-shaft", false},
        Case{"planet-epicycloid", true}, Case{"curved-guide", true}, Case{"curved-guide", false},
        Case{"gear-four-bar", true}, Case{"needle-876-alpha-35", true}}) {
    const Mechanism m = withMasses(test::example(c.example), 7);
    Kinematics k = loaded(m, c.closedForm);
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok()) << c.example;
    std::vector<double> input, balance;
    for (double deg = 0; deg < 360; deg += 3) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << c.example << " " << deg;
      const Forces& r = f.compute(k);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      const Powers p = powers(k);
      input.push_back(r.driverTorqueNm * driverSpeed(k));
      balance.push_back(p.energyRate - p.loads);
    }
    double peak = 0;
    for (double x : input) peak = std::max(peak, std::abs(x));
    ASSERT_GT(peak, 0) << c.example;
    for (size_t i = 0; i < input.size(); ++i)
      EXPECT_NEAR(input[i], balance[i], 1e-12 * peak) << c.example << " at " << 3 * i << " deg";
  }
}

// The wrench each joint puts on a body (its force, and its moment about the sketch origin, N mm),
// as the reactions report it: on the body of point a, and the opposite on the other side; a
// coupling's force on a's body, the opposite on b's with the couple the ratio gives it.
struct Wrench {
  Vec2 f = Vec2::Zero();
  double m = 0;
};
std::vector<Wrench> jointWrenches(const Kinematics& k, const Forces& r) {
  const Mechanism& m = k.mechanism();
  std::vector<Wrench> on(m.bodies.size());
  auto index = [&](BodyId b) {
    return static_cast<size_t>(
        std::find_if(m.bodies.begin(), m.bodies.end(), [&](const Body& x) { return x.id == b; }) -
        m.bodies.begin());
  };
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    const JointReaction& x = r.joints[i];
    const BodyId a = m.point(j.a)->body;
    const BodyId o = kindOf(j).reads(FieldType::Slot) ? m.slot(j.slot)->body : m.point(j.b)->body;
    const double moment = cross(x.at, x.force) + 1000 * x.coupleNm;
    on[index(a)].f += x.force;
    on[index(a)].m += moment;
    on[index(o)].f -= x.force;
    if (j.type != JointType::Gear) {
      on[index(o)].m -= moment;
    } else {
      // b's body: -F with the couple c_b / c_a of a's about its centre B.
      const Vec2 A = k.position(j.a), B = k.position(j.b);
      const double Ma = cross(x.at - A, x.force);
      on[index(o)].m += cross(B, -x.force) - Ma / gearRatio(j);
    }
  }
  return on;
}

TEST(Dynamics, EveryBodysForcesBalanceItsInertiaAndTheFrameTakesTheShakingForce) {
  for (const Case c : {Case{"wanzer-inversion-2", true}, Case{"lockstitch-arm-shaft", true},
                       Case{"planet-epicycloid", false}, Case{"curved-guide", true},
                       Case{"gear-four-bar", false}}) {
    const Mechanism m = withMasses(test::example(c.example), 11);
    Kinematics k = loaded(m, c.closedForm);
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok());
    const Vec2 g = m.gravity.value_or(Vec2::Zero());
    for (double deg : {0.0, 47.0, 160.0, 299.0}) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const Forces& r = f.compute(k);
      ASSERT_TRUE(r.status.ok());
      std::vector<Wrench> w = jointWrenches(k, r);
      // The driver's torque on b's body, its reaction on a's.
      const Joint& d = *m.joint(m.driver->joint);
      for (size_t i = 0; i < m.bodies.size(); ++i) {
        if (m.bodies[i].id == m.point(d.b)->body) w[i].m += 1000 * r.driverTorqueNm;
        if (m.bodies[i].id == m.point(d.a)->body) w[i].m -= 1000 * r.driverTorqueNm;
      }
      double scale = 1;
      for (size_t i = 0; i < m.bodies.size(); ++i) {
        const Body& b = m.bodies[i];
        Wrench applied;  // weight, inertia, loads
        if (b.mass) {
          const Kinematics::PointMotion c = k.motionOf(b.id, b.mass->com);
          applied.f = b.mass->kg * (g - c.acceleration / 1000);
          applied.m = cross(c.position, applied.f) - b.mass->jKgMm2 * k.bodyAlpha(b.id) / 1000;
        }
        for (const Load& l : m.loads)
          if (l.activeAt(deg) && (l.point ? m.point(l.point)->body : l.body) == b.id) {
            applied.f += l.forceN;
            applied.m += l.point ? cross(k.position(l.point), l.forceN) : 1000 * l.torqueNm;
          }
        scale = std::max({scale, applied.f.norm(), std::abs(applied.m) / 100});
        if (b.ground) {
          // What the frame takes from the joints and the driver: the shaking force and moment.
          EXPECT_LT((w[i].f - r.shakingForceN).norm(), 1e-12 * scale * 100) << c.example << deg;
          EXPECT_NEAR(w[i].m / 1000, r.shakingMomentNm, 1e-12 * scale * 100) << c.example;
          continue;
        }
        EXPECT_LT((w[i].f + applied.f).norm(), 1e-12 * scale * 100) << c.example << " " << b.name;
        EXPECT_NEAR(w[i].m, -applied.m, 1e-9 * scale * 100) << c.example << " " << b.name;
      }
    }
  }
}

TEST(Dynamics, CentralSliderCrankShakesAsItsNeedleBarAccelerates) {
  // Seed 002: only the needle bar (the block) has mass: the shaking force is -m a_B, vertical,
  // with a_B from the closed form of y = r cos phi + sqrt(l^2 - r^2 sin^2 phi); the driver's
  // torque is m v a / omega (the block's power).
  for (const double lambda : {0.3, 0.5}) {
    const double r = 15, l = r / lambda, mb = 0.12;
    test::SliderCrank s = test::sliderCrank(r, l, 0, 90, Direction::Ccw, 1000);
    s.m.body(s.slider)->mass = Mass{mb, s.m.point(s.B)->pos, 0, ""};
    Kinematics k = loaded(s.m, true);
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok());
    const double w = k.omega();
    for (double deg = 0; deg < 360; deg += 5) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const Forces& out = f.compute(k);
      // From the guide's line (the crank drawn along it, at the top dead centre).
      const double phi = deg * kDeg, c = std::cos(phi), sn = std::sin(phi);
      const double D = std::sqrt(l * l - r * r * sn * sn);
      const double v = -r * w * sn * (1 + r * c / D);
      const double a =
          -r * w * w * (c + r * (c * c - sn * sn) / D + r * r * r * sn * sn * c * c / (D * D * D));
      const double peak = mb * r * w * w * (1 + lambda) / 1000;
      EXPECT_NEAR(out.shakingForceN.x(), 0, 1e-12 * peak) << deg;
      EXPECT_NEAR(out.shakingForceN.y(), -mb * a / 1000, 1e-12 * peak) << lambda << " " << deg;
      EXPECT_NEAR(out.driverTorqueNm * w, mb * v * a * 1e-6, 1e-12 * peak * r * w / 1000) << deg;
    }
  }
}

// A four-bar with its masses placed by the Berkof-Lowen conditions: the centre of mass of the
// whole stays put, so the shaking force is zero.
Mechanism berkofLowen(const test::FourBar& f, double m3, std::complex<double> c3) {
  using C = std::complex<double>;
  Mechanism m = f.m;
  const Vec2 O2 = m.point(f.O2)->pos, A = m.point(f.A)->pos, B = m.point(f.B)->pos,
             O4 = m.point(f.O4)->pos;
  auto z = [](const Vec2& v) { return C(v.x(), v.y()); };
  auto v2 = [](C c) { return Vec2(c.real(), c.imag()); };
  const C a2 = z(A - O2), a3 = z(B - A), a4 = z(B - O4);
  // Offsets as complex multiples of each link's own vector (so they turn with it).
  const double m2 = 0.3, m4 = 0.25;
  const C k3 = c3, k2 = m3 * (k3 - 1.0) / m2, k4 = -m3 * k3 / m4;
  m.body(f.crank)->mass = Mass{m2, v2(z(O2) + k2 * a2), 40, ""};
  m.body(f.coupler)->mass = Mass{m3, v2(z(A) + k3 * a3), 90, ""};
  m.body(f.rocker)->mass = Mass{m4, v2(z(O4) + k4 * a4), 60, ""};
  return m;
}

TEST(Dynamics, AFourBarBalancedByBerkofLowenDoesNotShake) {
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 30, true, 0, 0, Direction::Ccw, 600);
  const Mechanism balanced = berkofLowen(f, 0.2, {0.4, 0.1});
  Mechanism unbalanced = balanced;
  unbalanced.body(f.crank)->mass->com = unbalanced.point(f.A)->pos;
  double peak = 0, worst = 0;
  for (const Mechanism* m : {static_cast<const Mechanism*>(&unbalanced), &balanced}) {
    Kinematics k = loaded(*m, true);
    for (double deg = 0; deg < 360; deg += 2) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      Vec2 F;
      double M;
      shaking(k, F, M);
      (m == &balanced ? worst : peak) = std::max(m == &balanced ? worst : peak, F.norm());
    }
  }
  ASSERT_GT(peak, 1);
  EXPECT_LT(worst, 1e-12 * peak) << peak;
}

TEST(Dynamics, RedundantJointsReactionsAreNotDeterminedAndSaySo) {
  // A parallelogram with a fifth, redundant link: the driver's torque and the shaking force are
  // determined, the shares of the three parallel links are not.
  test::FourBar f = test::fourBar(60, 20, 60, 20, 70);
  Mechanism m = f.m;
  const BodyId extra = m.addBody("extra");
  const Vec2 E(30, 0), F = m.point(f.A)->pos + Vec2(30, 0);
  const PointId cE = m.addPoint(f.coupler, "E", F), gE = m.addPoint(m.ground()->id, "E", E);
  m.addPin(m.addPoint(extra, "F", F), cE);
  m.addPin(m.addPoint(extra, "E", E), gE);
  m = withMasses(m, 3, false);
  Kinematics k = loaded(m, true);
  ASSERT_FALSE(k.structure().redundantJoints.empty());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  const Forces& r = solver.compute(k);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_FALSE(r.undetermined.empty());
  for (JointId j : r.undetermined) EXPECT_TRUE(std::isnan(r.joints[m.jointIndex(j)].force.x()));
  EXPECT_TRUE(std::isfinite(r.driverTorqueNm));
  EXPECT_TRUE(r.shakingForceN.allFinite());
  EXPECT_NEAR(r.driverTorqueNm * driverSpeed(k), powers(k).energyRate - powers(k).loads,
              1e-12 * (1 + std::abs(r.driverTorqueNm * driverSpeed(k))));
}

// The general path solves J^T lambda = Q with the factors its velocity solve made at the pose
// (dense below 64 coordinates, sparse above); the closed-form path group by group: the same
// reactions from two independent solves.
// The groups' solve (RRR and RRP dyads by moments about their outer joints, the rest by
// elimination: analysis/group_forces.h) against the LU of J whole.
void expectGroupsGiveWhatTheFactorsGive(const Mechanism& m, const std::string& what) {
  Kinematics general = loaded(m, false), grouped = loaded(m, true);
  ASSERT_FALSE(general.closedForm()) << what;
  ASSERT_TRUE(grouped.closedForm()) << what;
  ForceSolver a, b;
  ASSERT_TRUE(a.prepare(general).ok());
  ASSERT_TRUE(b.prepare(grouped).ok());
  for (double deg : {0.0, 37.0, 95.0, 181.0, 250.0, 333.0}) {
    ASSERT_TRUE(general.moveTo(deg).ok());
    ASSERT_TRUE(grouped.moveTo(deg).ok());
    const Forces &x = a.compute(general), &y = b.compute(grouped);
    ASSERT_TRUE(x.status.ok() && y.status.ok()) << x.status.message << y.status.message;
    double peak = std::abs(y.driverTorqueNm);
    for (const JointReaction& r : y.joints) peak = std::max(peak, r.force.norm());
    EXPECT_NEAR(x.driverTorqueNm, y.driverTorqueNm, 1e-10 * peak) << what << " " << deg;
    for (size_t j = 0; j < m.joints.size(); ++j) {
      EXPECT_LT((x.joints[j].force - y.joints[j].force).norm(), 1e-10 * peak)
          << what << ", joint " << j << " at " << deg;
      // A couple (N m) is a force times a length under a metre.
      EXPECT_NEAR(x.joints[j].coupleNm, y.joints[j].coupleNm, 1e-10 * peak)
          << what << ", joint " << j << " at " << deg;
    }
  }
}

TEST(Dynamics, TheGroupsGiveWhatTheFactorsGiveOnDyadsOfEveryKind) {
  // RRP (22-A, the arm shaft's needle bar), RRR (the take-up lever, the drop feed), geared
  // (the lockstitch hook shaft), triads (the Wanzer).
  for (const char* name : {"slider-crank-22a-masses", "drop-feed", "lockstitch-arm-shaft",
                           "wanzer-inversion-2-masses", "gear-four-bar"})
    expectGroupsGiveWhatTheFactorsGive(withMasses(test::example(name), 7), name);
}

TEST(Dynamics, TheKinematicsFactorsGiveWhatTheGroupsGive) {
  for (const int loops : {3, 25}) {
    const Mechanism m = withMasses(test::fourBarChain(loops), 13);
    Kinematics general = loaded(m, false), grouped = loaded(m, true);
    ASSERT_FALSE(general.closedForm());
    ASSERT_TRUE(grouped.closedForm());
    ForceSolver a, b;
    ASSERT_TRUE(a.prepare(general).ok());
    ASSERT_TRUE(b.prepare(grouped).ok());
    for (double deg : {0.0, 95.0, 181.0, 333.0}) {
      ASSERT_TRUE(general.moveTo(deg).ok());
      ASSERT_TRUE(grouped.moveTo(deg).ok());
      const Forces &x = a.compute(general), &y = b.compute(grouped);
      ASSERT_TRUE(x.status.ok() && y.status.ok()) << x.status.message << y.status.message;
      double peak = std::abs(y.driverTorqueNm);
      for (const JointReaction& r : y.joints) peak = std::max(peak, r.force.norm());
      EXPECT_NEAR(x.driverTorqueNm, y.driverTorqueNm, 1e-10 * peak) << loops << " " << deg;
      for (size_t j = 0; j < m.joints.size(); ++j)
        EXPECT_LT((x.joints[j].force - y.joints[j].force).norm(), 1e-10 * peak)
            << loops << " loops, joint " << j << " at " << deg;
    }
  }
}

TEST(Dynamics, MassesGravityAndLoadsRoundTripAndBadOnesAreRefused) {
  Mechanism m = withMasses(test::example("wanzer-inversion-2"), 5);
  m.bodies[1].mass->counterweights = {{0.125, Vec2(3, -4.5)}, {0.25, Vec2(-1, 2)}};
  const std::string text = serializeMechanism(m);
  const LoadResult back = parseMechanism(text);
  ASSERT_TRUE(back.mechanism) << back.error;
  EXPECT_EQ(mechanismDifference(m, *back.mechanism), "");
  EXPECT_EQ(serializeMechanism(*back.mechanism), text);
  auto refused = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    const LoadResult r = parseMechanism(t);
    EXPECT_FALSE(r.mechanism);
    return r.error;
  };
  EXPECT_EQ(refused("\"kg\": ", "\"kg\": -").substr(0, 49),
            "bodies[1].mass.kg: expected a number >= 0, got -0");
  EXPECT_EQ(refused("\"gravity\": [0, -9.81]", "\"gravity\": [0]"),
            "gravity: expected [gx, gy] or [gx, gy, gz] with finite numbers (m/s^2), got [0]");
  EXPECT_EQ(refused("\"from_deg\": 40,", ""),
            "loads[0]: a window needs both \"from_deg\" and \"to_deg\"; only \"to_deg\" is given");
  EXPECT_EQ(refused("\"torque_Nm\"", "\"force_N\""),
            "loads[1]: missing required field \"torque_Nm\"");
  EXPECT_NE(refused("\"point\": \"", "\"point\": \"x").find("loads[0].point: no body"),
            std::string::npos);
  EXPECT_EQ(refused("\"kg\": 0.125", "\"kg\": -0.125"),
            "bodies[1].mass.counterweights[0].kg: expected a number >= 0, got -0.125");
  EXPECT_EQ(refused("\"counterweights\": [", "\"counterweights\": 3, \"x\": ["),
            "bodies[1].mass.counterweights: expected an array of {\"kg\", \"at\"}, got 3");
}

// Gravity is [gx, gy] or [gx, gy, gz] (the world's, docs/dynamics.md): written back as it was
// read, two numbers or three; any other shape refused naming it. On a planar machine gz is along
// the drawing's normal: no force in the plane changes (every column of the table is the same);
// the frame bears the weights along the normal, the shaking force's z, with their moments about
// the sketch origin's x and y axes, from the centres of mass where they are.
TEST(Dynamics, GravityHasTwoOrThreeComponentsAndGzChangesNoPlanarForce) {
  const Mechanism flat = withMasses(test::example("wanzer-inversion-2"), 5);
  std::string text = serializeMechanism(flat);
  const std::string two = "\"gravity\": [0, -9.81]";
  const size_t at = text.find(two);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, two.size(), "\"gravity\": [0, -9.81, -4.5]");
  const LoadResult read = parseMechanism(text);
  ASSERT_TRUE(read.mechanism) << read.error;
  const Mechanism& m = *read.mechanism;
  EXPECT_EQ(m.gravityWorld(), Vec3(0, -9.81, -4.5));
  EXPECT_EQ(serializeMechanism(m), text);
  EXPECT_EQ(mechanismDifference(m, flat), "gravity differs");
  auto refusal = [&](const std::string& gravity) {
    std::string t = text;
    t.replace(at, std::string("\"gravity\": [0, -9.81, -4.5]").size(), "\"gravity\": " + gravity);
    const LoadResult r = parseMechanism(t);
    EXPECT_FALSE(r.mechanism) << gravity;
    return r.error;
  };
  const std::string expected =
      "gravity: expected [gx, gy] or [gx, gy, gz] with finite numbers (m/s^2), got ";
  for (const char* bad : {"[0, \"down\", 1]", "[]", "[0, -9.81, null]", "{\"z\": 1}"})
    EXPECT_EQ(refusal(bad).rfind(expected, 0), 0u) << refusal(bad);
  EXPECT_EQ(refusal("[0, -9.81, 1, 2]"), expected + "[0, -9.81, 1, 2]");
  EXPECT_EQ(refusal("[0, -9.81, 1e999]").rfind("gravity[2]: ", 0), 0u);
  Kinematics a = loaded(flat, true), b = loaded(m, true);
  ForceSolver fa, fb;
  ASSERT_TRUE(fa.prepare(a).ok() && fb.prepare(b).ok());
  double kg = 0;
  for (const Body& body : m.bodies)
    if (!body.ground && body.mass) kg += body.mass->kg;
  for (double deg : {0.0, 77.0, 200.0}) {
    ASSERT_TRUE(a.moveTo(deg).ok() && b.moveTo(deg).ok());
    const Forces &x = fa.compute(a), &y = fb.compute(b);
    ASSERT_TRUE(x.status.ok() && y.status.ok());
    EXPECT_EQ(x.driverTorqueNm, y.driverTorqueNm);
    EXPECT_EQ(x.shakingForceN, y.shakingForceN);
    EXPECT_EQ(x.shakingMomentNm, y.shakingMomentNm);
    for (size_t j = 0; j < m.joints.size(); ++j) EXPECT_EQ(x.joints[j].force, y.joints[j].force);
    EXPECT_NEAR(y.shakingForce3N.z(), -4.5 * kg, 1e-12 * kg);
    EXPECT_EQ(x.shakingForce3N.z(), 0);
    Vec2 tilt = Vec2::Zero();  // N m: r x (0, 0, m gz) = (y m gz, -x m gz)
    for (const Body& body : m.bodies) {
      if (body.ground || !body.mass) continue;
      const Vec2 c = b.toWorld(body.id, body.mass->com);
      tilt += body.mass->kg * -4.5 * Vec2(c.y(), -c.x()) / 1000;
    }
    EXPECT_NEAR(y.shakingMoment3Nm.x(), tilt.x(), 1e-12 * tilt.norm()) << deg;
    EXPECT_NEAR(y.shakingMoment3Nm.y(), tilt.y(), 1e-12 * tilt.norm()) << deg;
    EXPECT_EQ(y.shakingMoment3Nm.z(), x.shakingMomentNm);
  }
}

// Issue 26: a mass of 1e300 kg gave forces of 1e303 N with noise of 1e287 N where 0 is meant (the
// others' lost in rounding), 1e308 kg "a singular position". Beyond a thousand tonnes a mass is
// refused, named by its place in the file, as the editor's field refuses it (massRefusal).
TEST(Dynamics, AMassBeyondAThousandTonnesIsRefusedNamingItsPlace) {
  Mechanism m = withMasses(test::example("wanzer-inversion-2"), 5);
  m.bodies[1].mass->kg = 0.5;
  m.bodies[1].mass->jKgMm2 = 20;
  m.bodies[1].mass->counterweights = {{0.125, Vec2(3, -4.5)}};
  const std::string text = serializeMechanism(m);
  auto read = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    return parseMechanism(t);
  };
  const std::string beyond =
      "a mass beyond 1e6 kg (a thousand tonnes): no link of a machine has that, and its forces "
      "would overflow or drown the others' in rounding";
  EXPECT_EQ(massRefusal(1e300), beyond);
  EXPECT_EQ(read("\"kg\": 0.5", "\"kg\": 1e300").error, "bodies[1].mass.kg: " + beyond);
  EXPECT_EQ(read("\"kg\": 0.5", "\"kg\": 1e308").error, "bodies[1].mass.kg: " + beyond);
  EXPECT_EQ(read("\"kg\": 0.125", "\"kg\": 1.5e6").error,
            "bodies[1].mass.counterweights[0].kg: " + beyond);
  EXPECT_EQ(read("\"j_kg_mm2\": 20", "\"j_kg_mm2\": 1e300").error,
            "bodies[1].mass.j_kg_mm2: " + inertiaRefusal(1e300));
  EXPECT_NE(inertiaRefusal(1e300).find("beyond 1e15 kg mm^2"), std::string::npos);
  // A thousand tonnes itself is a mass.
  const LoadResult most = read("\"kg\": 0.5", "\"kg\": 1e6");
  ASSERT_TRUE(most.mechanism) << most.error;
  EXPECT_EQ(most.mechanism->bodies[1].mass->kg, 1e6);
  EXPECT_EQ(massRefusal(1e6), "");
  EXPECT_EQ(inertiaRefusal(1e15), "");
  EXPECT_NE(massRefusal(-1), "");
  EXPECT_NE(massRefusal(NAN), "");
}

// Forces past double's range, from loads (or a speed) no mass bound holds back: BadModel with
// the crank angle and the cause, NaN in the numbers (never inf, never the "singular position"
// the solve's failure on an infinite right-hand side used to be taken for).
TEST(Dynamics, ForcesThatOverflowSaySoAndAreNoNumbers) {
  Mechanism m = test::example("slider-crank-22a-masses");
  Load load;
  load.point = *m.findPoint("needlebar.B");
  load.forceN = Vec2(1e308, 1e308);  // each finite; its magnitude is not
  m.addLoad(load);
  for (int loads : {1, 2}) {  // two: their sum overflows before the solve
    if (loads == 2) m.addLoad(load);
    Kinematics k = loaded(m, true);
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok());
    ASSERT_TRUE(k.moveTo(30).ok());
    const Forces& r = f.compute(k);
    EXPECT_EQ(r.status.code, StatusCode::BadModel) << loads;
    EXPECT_EQ(r.status.message,
              "the forces at crank angle 30 deg overflow (beyond 1e308 N or N m): a speed, a "
              "load or a mass too large to compute with");
    EXPECT_FALSE(finiteForces(r));
    EXPECT_TRUE(std::isnan(r.driverTorqueNm));
    EXPECT_TRUE(std::isnan(r.shakingForceN.x()));
    const ForceSamples s = sampleForces(k, 36);
    EXPECT_EQ(s.status.code, StatusCode::BadModel);
    EXPECT_EQ(s.size(), 0u);
  }
}

TEST(Dynamics, SamplesCoverWholeTurnsAndStopWhereTheCrankCannotPass) {
  const Mechanism m = withMasses(test::example("wanzer-inversion-2"), 11);
  Kinematics k = loaded(m, true);
  const double before = k.crankDeg();
  const ForceSamples s = sampleForces(k, 72, 2, 300);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_TRUE(s.complete);
  ASSERT_EQ(s.size(), 145u);
  EXPECT_EQ(s.rpm, 300);
  EXPECT_EQ(s.crankDeg.back(), 720);
  ASSERT_EQ(s.reactionN.size(), m.joints.size());
  // At another speed every inertia force scales with its square; gravity and loads do not,
  // so compare with a solver at that speed, pose by pose.
  Kinematics probe = k;
  probe.setRpm(300);
  ForceSolver f;
  ASSERT_TRUE(f.prepare(probe).ok());
  for (size_t i = 0; i < s.size(); i += 7) {
    ASSERT_TRUE(probe.moveTo(s.crankDeg[i]).ok());
    const Forces& r = f.compute(probe);
    // The same pose reached in other steps: equal to the solver's last digits.
    const double scale = 1 + r.shakingForceN.norm();
    EXPECT_LT(std::abs(s.driverTorqueNm[i] - r.driverTorqueNm), 1e-9 * scale);
    EXPECT_LT((s.shakingN[i] - r.shakingForceN).norm(), 1e-9 * scale);
    for (size_t j = 0; j < m.joints.size(); ++j)
      EXPECT_LT((s.reactionN[j][i] - r.joints[j].force).norm(), 1e-9 * scale);
  }
  // Periodic: a turn later, the same forces (loads switch by the angle within the turn).
  for (size_t i = 0; i <= 72; i += 9)
    EXPECT_LT(std::abs(s.driverTorqueNm[i] - s.driverTorqueNm[i + 72]),
              1e-9 * (1 + std::abs(s.driverTorqueNm[i])));
  EXPECT_EQ(k.crankDeg(), before) << "the caller's kinematics is not moved";
  // An editor's kinematics with accelerations switched off samples the same.
  k.setAccelerations(false);
  const ForceSamples off = sampleForces(k, 72, 2, 300);
  ASSERT_TRUE(off.complete) << off.status.message;
  EXPECT_EQ(off.driverTorqueNm, s.driverTorqueNm);

  // A crank-rocker drawn too long to turn (non-Grashof: 30 + 60 > 45 + 50) stops on its way.
  const test::FourBar fb = test::fourBar(60, 45, 30, 50, 60);
  Kinematics nk = loaded(withMasses(fb.m, 3, false), true);
  const ForceSamples part = sampleForces(nk, 360);
  EXPECT_FALSE(part.complete);
  EXPECT_FALSE(part.status.ok());
  EXPECT_GT(part.size(), 1u);
  EXPECT_LT(part.size(), 361u);
  for (double t : part.driverTorqueNm) EXPECT_TRUE(std::isfinite(t));
}

}  // namespace
}  // namespace linkage
