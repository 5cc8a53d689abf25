// Forces on machines in space (linkage/dynamics.h, analysis/space_forces.h) against truths found
// without the solver's rows: the RSSR's rod force from its rocker's equation of motion and the
// closed form of its motion, its bearings' loads from that rod force; the power balance of the
// spatial examples with masses, gravity and loads; the frame's balance in 3D (the shaking force
// and moment are what the bearings put on the ground).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "examples.h"
#include "linkage/dynamics.h"
#include "linkage/force_samples.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"
#include "linkage/tables/force_table.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

// The RSSR example (resources/examples/spatial.py): the crank R on the z axis, its ball at depth
// 5; the rocker W about the axis through H along the normal of the plane (X, Y) inclined 23
// degrees.
using namespace test::rssr;

Vec3 crankA(double phi) {
  return Vec3(kR * std::cos(kPhi0 + phi), kR * std::sin(kPhi0 + phi), kDepth);
}
Vec3 rockerC(double psi) {
  return kH + kW * (std::cos(psi) * kX + std::sin(psi) * kY);
}

// The rocker's angle psi(phi) from its closed form (the root nearest `near`) and its rates by
// the crank angle, derived in spatial_fixtures.h.
using test::Rocker;
Rocker closedForm(double phi, double near, double l) {
  return test::rockerNear(phi, near, l);
}

const Plane& planeOfPoint(const Mechanism& m, const std::string& label) {
  return planeOf(m, m.point(*m.findPoint(label))->body);
}

// Lifts a joint's reaction (in its plane, which is its class's frame in these machines) to the
// world: the force and the moment about the plane's axes through where it acts.
Vec3 worldForce(const Plane& p, const JointReaction& r) {
  return r.force.x() * p.xAxis + r.force.y() * p.yAxis + r.normalN * p.normal();
}

// A massless crank and a rocker of inertia J about its own axis (its centre of mass on it): the
// rod's tension is the rocker's J psi'' over the moment arm of the rod about the rocker's axis,
// psi'' = psi_phiphi omega^2 from the closed form. The bearings then carry the rod's pull.
TEST(SpatialForces, TheRssrRodForceIsTheRockersEquationOfMotion) {
  Mechanism m = test::example("rssr-crank-rocker");
  constexpr double kJ = 2500;  // kg mm^2
  m.body(m.bodyNamed("rocker")->id)->mass = Mass{0.3, Vec2::Zero(), kJ, ""};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok()) << solver.result().status.message;
  const double w = k.omega(), l = (crankA(0) - rockerC(kPsi0)).norm();
  const Vec3 n = kX.cross(kY);
  double psi = kPsi0, peak = 0, worst = 0, worstBearing = 0;
  std::vector<double> tension, got;
  for (int deg = 0; deg < 360; deg += 2) {
    const Rocker r = closedForm(deg * M_PI / 180, psi, l);
    psi = r.psi;
    const Vec3 A = crankA(deg * M_PI / 180), C = rockerC(psi), u = (A - C) / l;
    const double arm = n.dot((C - kH).cross(u));      // mm
    const double T = 1e-3 * kJ * r.d2 * w * w / arm;  // N (kg mm^2/s^2 = 1e-3 N mm)
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const Forces& f = solver.compute(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    tension.push_back(T);
    got.push_back(f.joints[2].axialN);
    peak = std::max(peak, std::abs(T));
    // The rod pulls C towards A by T u and A towards C by -T u; the rocker's bearing at H takes
    // the first (its centre of mass does not move), the crank's at O the second, each with its
    // moment about its plane's axes: what the bodies put on the ground (point a of each pin).
    const Vec3 onC = T * u, onA = -T * u;
    const Vec3 MC = (C - kH).cross(onC) / 1000, MA = A.cross(onA) / 1000;  // N m
    const Plane &pc = planeOfPoint(m, "rocker.H"), &pa = planeOfPoint(m, "crank.O");
    const JointReaction &h = f.joints[1], &o = f.joints[0];
    worst = std::max(worst, (worldForce(pc, h) - onC).norm());
    worst = std::max(worst, (worldForce(pa, o) - onA).norm());
    worstBearing = std::max(worstBearing, std::abs(h.tiltNm.x() - MC.dot(pc.xAxis)) +
                                              std::abs(h.tiltNm.y() - MC.dot(pc.yAxis)) +
                                              std::abs(o.tiltNm.x() - MA.dot(pa.xAxis)) +
                                              std::abs(o.tiltNm.y() - MA.dot(pa.yAxis)));
  }
  ASSERT_GT(peak, 1);  // the rocker's inertia loads the rod
  double rel = 0;
  for (size_t i = 0; i < got.size(); ++i) rel = std::max(rel, std::abs(got[i] - tension[i]) / peak);
  EXPECT_LT(rel, 1e-9);
  EXPECT_LT(worst, 1e-9 * peak);
  EXPECT_LT(worstBearing, 1e-9 * peak * kW / 1000);
  std::printf("[ rssr rod ] peak tension %.6g N, largest difference %.3g of it; bearings %.3g N\n",
              peak, rel, worst);
}

// d(kinetic energy)/dt less the power of gravity and of the loads (W), from the bodies' motion
// in the world: what the driver must put in.
double powerNeeded(const Kinematics& k) {
  const Mechanism& m = k.mechanism();
  const Vec3 g = m.gravityWorld();
  double p = 0;
  for (const Body& b : m.bodies) {
    if (b.ground || !b.mass) continue;
    PointId com;
    for (const Point& q : m.points)
      if (q.body == b.id && q.name == "G_com") com = q.id;
    const Kinematics::PointMotion3 c = k.motionInSpace(com);
    const double w = k.bodyOmega(b.id), al = k.bodyAlpha(b.id);
    p += 1e-6 * (b.mass->kg * c.velocity.dot(c.acceleration) + b.mass->jKgMm2 * w * al);
    p -= 1e-3 * b.mass->kg * g.dot(c.velocity);
  }
  for (const Load& l : m.loads) {
    if (!l.activeAt(k.crankDeg())) continue;
    if (l.point) {
      const Plane& pl = planeOf(m, m.point(l.point)->body);
      const Vec3 F = l.forceN.x() * pl.xAxis + l.forceN.y() * pl.yAxis;  // in its body's plane
      p -= 1e-3 * F.dot(k.motionInSpace(l.point).velocity);
    } else {
      p -= l.torqueNm * k.bodyOmega(l.body);
    }
  }
  return p;
}

TEST(SpatialForces, PowerBalanceHoldsOnTheSpatialExamples) {
  for (const char* name : {"rssr-crank-rocker", "overedge-machine", "lockstitch-bevel"}) {
    for (bool closedForm : {true, false}) {
      const Mechanism m = test::withMasses(test::example(name), 11);
      KinematicsOptions opt;
      opt.closedForm = closedForm;
      Kinematics k(opt);
      ASSERT_TRUE(k.load(m).ok()) << name;
      ForceSolver f;
      ASSERT_TRUE(f.prepare(k).ok()) << name << ": " << f.result().status.message;
      const Joint& d = *m.joint(m.driver->joint);
      std::vector<double> input, needed;
      for (double deg = 0; deg < 360; deg += 3) {
        ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
        const Forces& r = f.compute(k);
        ASSERT_TRUE(r.status.ok()) << r.status.message;
        const double speed =
            k.bodyOmega(m.point(d.b)->body) - k.bodyOmega(m.point(d.a)->body);  // rad/s
        input.push_back(r.driverTorqueNm * speed);
        needed.push_back(powerNeeded(k));
      }
      double peak = 0, worst = 0;
      for (double x : input) peak = std::max(peak, std::abs(x));
      ASSERT_GT(peak, 0) << name;
      for (size_t i = 0; i < input.size(); ++i)
        worst = std::max(worst, std::abs(input[i] - needed[i]));
      EXPECT_LT(worst, 1e-12 * peak) << name << (closedForm ? " (closed form)" : "");
      std::printf("[ power ] %s%s: peak %.6g W, largest residual %.3g of it\n", name,
                  closedForm ? " (closed form)" : "", peak, worst / peak);
    }
  }
}

// A pin carries no couple: on the spatial examples with masses and loads, every pin's reaction
// is read where its two points meet in their plane class's frame (a ground point a where the
// rows hold it, projected along that frame's normal: the overedge machine's main shaft's ground
// point is not at its drawing's x, y there), and its couple about that place is 0. Before the
// ground point was read at its drawing's x, y: up to 1,033 N m at the overedge machine's main
// shaft.
TEST(SpatialForces, APinCarriesNoCoupleAndIsReadWhereItsPointsMeet) {
  for (const char* name : {"rssr-crank-rocker", "overedge-machine", "lockstitch-bevel"}) {
    const Mechanism m = test::withMasses(test::example(name), 5);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    k.setAccelerations(true);
    double moved = 0;
    for (double deg = 0; deg < 360; deg += 45) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name;
      const Forces f = computeForces(k);
      ASSERT_TRUE(f.status.ok()) << f.status.message;
      for (size_t j = 0; j < m.joints.size(); ++j) {
        const Joint& jt = m.joints[j];
        if (jt.type != JointType::Pin) continue;
        const JointReaction& r = f.joints[j];
        const bool aGround = m.body(m.point(jt.a)->body)->ground;
        const Vec2 meet = k.position(aGround ? jt.b : jt.a);
        EXPECT_LT((r.at - meet).norm(), 1e-9) << name << " " << jointLabel(m, jt.id);
        EXPECT_LT(std::abs(r.coupleNm), 1e-12 * (1 + r.force.norm()) * 1e3)
            << name << " " << jointLabel(m, jt.id) << " at " << deg;
        if (aGround) moved = std::max(moved, (meet - m.point(jt.a)->pos).norm());
      }
    }
    std::printf("[ pins ] %s: a ground pivot up to %.3g mm from its drawing's x, y in its frame\n",
                name, moved);
    if (std::string(name) == "overedge-machine") EXPECT_GT(moved, 1);
  }
}

// A bearing with no point on its body: an oscillating block's coupler in a plane tilted 30
// degrees about x, guided by a ground pin P in its slot (its one joint with the ground), its
// weight's part along the plane's normal the only load out of the plane. The pin bears that
// force and its moment about P (where the rows hold P in the plane), by hand:
//   fn = m g.n,  tilt = ((c - P)_y, -(c - P)_x) m g.n / 1000,  c the centre of mass in the plane.
// Before, the moment was taken about the coupler's frame origin.
TEST(SpatialForces, ABearingOnAGroundPinInTheBodysSlotIsAtThePin) {
  const std::string text = test::tiltedOscillatingBlock();
  const LoadResult loaded = parseMechanism(text);
  ASSERT_TRUE(loaded.mechanism) << loaded.error;
  const Mechanism& m = *loaded.mechanism;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  k.setAccelerations(true);
  const Vec3 n = Vec3(1, 0, 0).cross(Vec3(0, 0.8660254037844387, 0.5));
  const double Fz = 0.5 * Vec3(0, -9.81, -3).dot(n);
  const BodyId coupler = m.bodyNamed("coupler")->id;
  for (double deg = 0; deg < 360; deg += 40) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Forces f = computeForces(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const JointReaction& r = f.joints[2];
    const Vec2 c = k.motionOf(coupler, Vec2(70, 5)).position, P(60, 0);
    EXPECT_NEAR(r.normalN, Fz, 1e-12);
    EXPECT_NEAR(r.tiltNm.x(), (c - P).y() * Fz / 1000, 1e-12) << deg;
    EXPECT_NEAR(r.tiltNm.y(), -(c - P).x() * Fz / 1000, 1e-12) << deg;
    EXPECT_LT((r.at - P).norm(), 1e-12) << deg;
  }
}

// The RSSR with its crank drawn in a plane parallel to the drawing but turned 30 degrees about z
// (the crank's class is the drawing's: its centre of mass and loads are turned into it).
Mechanism turnedCrank(Mechanism m) {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  m.planes->push_back(Plane{"turned", Vec3::Zero(), Vec3(c, s, 0), Vec3(-s, c, 0), {}});
  Body& crank = *m.body(m.bodyNamed("crank")->id);
  crank.plane = "turned";
  for (Point& p : m.points)
    if (p.body == crank.id)
      p.pos = Vec2(c * p.pos.x() + s * p.pos.y(), -s * p.pos.x() + c * p.pos.y());
  return m;
}

TEST(SpatialForces, PowerBalanceHoldsWithABodyInATurnedParallelPlane) {
  Mechanism m = test::withMasses(turnedCrank(test::example("rssr-crank-rocker")), 5);
  m.addLoad(Load{*m.findPoint("crank.A"), {}, Vec2(5, 2), 0, std::nullopt, std::nullopt, ""});
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver f;
  ASSERT_TRUE(f.prepare(k).ok()) << f.result().status.message;
  double peak = 0, worst = 0;
  for (double deg = 0; deg < 360; deg += 3) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const Forces& r = f.compute(k);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const double input = r.driverTorqueNm * k.bodyOmega(m.bodyNamed("crank")->id);
    peak = std::max(peak, std::abs(input));
    worst = std::max(worst, std::abs(input - powerNeeded(k)));
  }
  ASSERT_GT(peak, 0);
  EXPECT_LT(worst, 1e-12 * peak);
}

// What the bodies put on the ground through its bearings (each reaction on the ground, lifted
// to the world, with its moment about the plane's axes) and the driver (its torque's reaction)
// is the shaking force and moment found from the bodies' masses and motion alone.
TEST(SpatialForces, TheShakingForceAndMomentInSpaceAreWhatTheBearingsPutOnTheGround) {
  // The crank turned or not; gravity (3, -9.81) or with a z, which the crank's bearing and the
  // rocker's take out of their planes.
  for (const auto& [turned, gz] :
       {std::pair{false, 0.0}, {true, 0.0}, {false, -6.5}, {true, -6.5}}) {
    Mechanism m = test::withMasses(test::example("rssr-crank-rocker"), 3);
    if (turned) m = turnedCrank(m);
    if (gz != 0) m.gravityZ = gz;
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok()) << f.result().status.message;
    EXPECT_TRUE(f.result().outOfPlaneUnsupported.empty());
    double peakF = 0, peakM = 0, worstF = 0, worstM = 0;
    for (double deg = 0; deg < 360; deg += 5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const Forces& r = f.compute(k);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      Vec3 F = Vec3::Zero(), M = -r.driverTorqueNm * Vec3::UnitZ();
      for (int j : {0, 1}) {  // ground.O - crank.O, ground.H - rocker.H: point a on the ground
        // Each reaction in its joint's class frame: the drawing's for the crank, the rocker's.
        const Plane& p = j == 0 ? drawingPlane() : planeOfPoint(m, "rocker.H");
        const JointReaction& x = r.joints[j];
        const Vec3 Fw = worldForce(p, x);
        F += Fw;
        M += p.world(x.at).cross(Fw) / 1000 + x.tiltNm.x() * p.xAxis + x.tiltNm.y() * p.yAxis;
      }
      peakF = std::max(peakF, r.shakingForce3N.norm());
      peakM = std::max(peakM, r.shakingMoment3Nm.norm());
      worstF = std::max(worstF, (F - r.shakingForce3N).norm());
      worstM = std::max(worstM, (M - r.shakingMoment3Nm).norm());
      EXPECT_EQ(r.shakingForceN, r.shakingForce3N.head<2>());
    }
    ASSERT_GT(peakF, 1);
    EXPECT_LT(worstF, 1e-9 * peakF) << turned << " " << gz;
    EXPECT_LT(worstM, 1e-9 * peakM) << turned << " " << gz;
  }
}

// The overedge machine with masses and gravity (3, -9.81, 0): the links with no joint with the
// ground in the inclined rocker plane (the needle link) and in the main plane, whose normal is
// -x (the feed's rods, link and bar), have weights out of their planes that no bearing takes
// under the stated assumption: named, not silently dropped. The gripper's link is not: its plane's
// normal is z, gravity lies in it, and its joints are at one depth. Bodies held to the ground by
// one joint are not named.
TEST(SpatialForces, BodiesWithALoadOutOfTheirPlaneAndNoBearingAreNamed) {
  const Mechanism m = test::withMasses(test::example("overedge-machine"), 2);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver f;
  ASSERT_TRUE(f.prepare(k).ok()) << f.result().status.message;
  std::vector<std::string> named;
  for (BodyId b : f.result().outOfPlaneUnsupported) named.push_back(m.body(b)->name);
  std::printf("[ unsupported ]");
  for (const std::string& n : named) std::printf(" %s", n.c_str());
  std::printf("\n");
  for (const char* held :
       {"main", "needlerock", "needlearm", "upper", "lower", "feedrock1", "feedrock2"})
    EXPECT_EQ(std::count(named.begin(), named.end(), held), 0) << held;
  EXPECT_EQ(std::count(named.begin(), named.end(), "needlelink"), 1);
  for (const char* link : {"feedrod", "feedlink", "liftrod", "feedbar"})
    EXPECT_EQ(std::count(named.begin(), named.end(), link), 1) << link;
  EXPECT_EQ(std::count(named.begin(), named.end(), "lowerlink"), 0);
  ASSERT_TRUE(k.moveTo(30).ok());
  const Forces& r = f.compute(k);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  // Every bearing's load out of its plane is a number (the machine has no redundant joint).
  for (const JointReaction& x : r.joints)
    EXPECT_TRUE(std::isfinite(x.normalN) && x.tiltNm.allFinite());
}

// Gravity straight down the world's z, [0, 0, -9.81], on a crank turning in a plane inclined
// rho about x: its part in the plane, g sin(rho) down the plane's y, loads the crank's planar
// equations (the driver holds the weight's moment m g sin(rho) c_x about the pin); its part along
// the normal, -g cos(rho), is the bearing's (fn) with its moments about the plane's axes through
// the pin; the frame takes the weight and the centrifugal force in 3D. By hand from the crank's
// angle alone, at the driver's constant speed.
TEST(SpatialForces, GravityInThreeComponentsOnACrankInAnInclinedPlane) {
  namespace ic = test::inclined_crank;
  const LoadResult read = parseMechanism(ic::text("[0, 0, -9.81]"));
  ASSERT_TRUE(read.mechanism) << read.error;
  const Mechanism& m = *read.mechanism;
  EXPECT_EQ(m.gravityWorld(), Vec3(0, 0, -9.81));
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok()) << solver.result().status.message;
  const Vec3 g(0, 0, -9.81);
  const double w = ic::kRpm * M_PI / 30, gin = g.dot(ic::kY),
               gn = g.dot(ic::kN);  // gx in the plane is 0
  ASSERT_NEAR(gin, -9.81 * std::sin(ic::kRho), 1e-15);
  struct Worst {
    double got = 0, peak = 0;
    void add(double a, double b) {
      got = std::max(got, std::abs(a - b)), peak = std::max(peak, std::abs(b));
    }
    double rel() const { return got / peak; }
  } torque, force, normal, tilt, shake, moment;
  for (int deg = 0; deg < 360; deg += 10) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const Forces& f = solver.compute(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const double t = deg * M_PI / 180;
    const Vec2 c(std::cos(t) * ic::kCom.x() - std::sin(t) * ic::kCom.y(),
                 std::sin(t) * ic::kCom.x() + std::cos(t) * ic::kCom.y());  // mm, in the plane
    // The crank's balance: the pin's force on it, P, with m (g_in + w^2 c) = -P; the driver's
    // torque and the weight's moment about the pin sum to J alpha = 0.
    torque.add(f.driverTorqueNm, -ic::kKg * (c.x() * gin - c.y() * 0) / 1000);
    const Vec2 onGround = ic::kKg * (Vec2(0, gin) + w * w * c / 1000);  // N, the crank's on the pin
    force.add(f.joints[0].force.x(), onGround.x());
    force.add(f.joints[0].force.y(), onGround.y());
    // Out of the plane: the weight's normal part at the centre of mass, on the ground through
    // the bearing, with its moment about the plane's x and y axes through the pin.
    const double Fn = ic::kKg * gn;
    normal.add(f.joints[0].normalN, Fn);
    tilt.add(f.joints[0].tiltNm.x(), c.y() * Fn / 1000);
    tilt.add(f.joints[0].tiltNm.y(), -c.x() * Fn / 1000);
    // The frame: the weight and the centrifugal force, in the world, and its moment about the
    // origin (the pin).
    const Vec3 cw = c.x() * ic::kX + c.y() * ic::kY;
    const Vec3 F = ic::kKg * g + ic::kKg * w * w * cw / 1000;
    for (int i = 0; i < 3; ++i) shake.add(f.shakingForce3N[i], F[i]);
    const Vec3 M = cw.cross(F) / 1000;
    for (int i = 0; i < 3; ++i) moment.add(f.shakingMoment3Nm[i], M[i]);
  }
  EXPECT_LT(torque.rel(), 1e-9);
  EXPECT_LT(force.rel(), 1e-9);
  EXPECT_LT(normal.rel(), 1e-9);
  EXPECT_LT(tilt.rel(), 1e-9);
  EXPECT_LT(shake.rel(), 1e-9);
  EXPECT_LT(moment.rel(), 1e-9);
  EXPECT_NEAR(normal.peak, 0.4 * 9.81 * std::cos(ic::kRho), 1e-12);
  std::printf("[ inclined crank ] torque %.3g, pin %.3g, fn %.3g, tilt %.3g, shaking %.3g, %.3g\n",
              torque.rel(), force.rel(), normal.rel(), tilt.rel(), shake.rel(), moment.rel());
}

// The spatial examples' power balance and the frame's balance with gravity in three components
// (the in-plane part of each body's plane loads its equations; the rest its bearing).
TEST(SpatialForces, PowerAndFrameBalanceHoldWithGravityInThreeComponents) {
  for (const char* name : {"rssr-crank-rocker", "overedge-machine", "lockstitch-bevel"}) {
    Mechanism m = test::withMasses(test::example(name), 17);
    m.gravityZ = -6.5;
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    ForceSolver f;
    ASSERT_TRUE(f.prepare(k).ok()) << name << ": " << f.result().status.message;
    const Joint& d = *m.joint(m.driver->joint);
    double peak = 0, worst = 0;
    for (double deg = 0; deg < 360; deg += 3) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      const Forces& r = f.compute(k);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      const double speed = k.bodyOmega(m.point(d.b)->body) - k.bodyOmega(m.point(d.a)->body);
      const double input = r.driverTorqueNm * speed;
      peak = std::max(peak, std::abs(input));
      worst = std::max(worst, std::abs(input - powerNeeded(k)));
    }
    ASSERT_GT(peak, 0) << name;
    EXPECT_LT(worst, 1e-12 * peak) << name;
    std::printf("[ power, gz ] %s: peak %.6g W, largest residual %.3g of it\n", name, peak,
                worst / peak);
  }
}

// The editor's force plots on a machine in space draw what `linkage-cli dynamics` writes, in the
// world: the samples' shaking force and moment are the solver's; each joint's force lifted from
// its plane class's frame (with what it bears along the normal) is, summed over the joints on the
// ground, the frame's load: the shaking force (the bodies' masses and motion alone); the rod's is
// its tension along the rod; a bevel pair has its couple and no force.
TEST(SpatialForces, TheForceSamplesOfAMachineInSpaceAreInTheWorld) {
  Kinematics k;
  ASSERT_TRUE(k.load(test::withMasses(turnedCrank(test::example("rssr-crank-rocker")), 1)).ok());
  const ForceSamples s = sampleForces(k, 36);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_TRUE(s.complete && s.inSpace);
  ASSERT_EQ(s.shaking3N.size(), 37u);
  ASSERT_EQ(s.reaction3N.size(), 3u);
  double peak = 0, frame = 0, rod = 0;
  Kinematics at = k;
  for (size_t i = 0; i < s.size(); ++i) {
    ASSERT_TRUE(at.moveTo(s.crankDeg[i]).ok());
    Vec3 F, M;
    shaking(at, F, M);
    EXPECT_EQ(s.shaking3N[i], F);
    EXPECT_EQ(s.shakingMoment3Nm[i], M);
    EXPECT_EQ(s.shakingN[i], F.head<2>());
    // joints 0 and 1: pins with point a on the ground (the force on the ground); 2: the rod.
    frame = std::max(frame, (s.reaction3N[0][i] + s.reaction3N[1][i] - F).norm());
    peak = std::max(peak, F.norm());
    const Vec3 A = at.motionInSpace(*at.mechanism().findPoint("crank.A")).position,
               C = at.motionInSpace(*at.mechanism().findPoint("rocker.C")).position;
    const Vec3 pull = s.reaction3N[2][i];
    rod = std::max(rod, pull.cross(C - A).norm() / (C - A).norm() +
                            std::abs(pull.dot(C - A) / (C - A).norm() - s.axialOrCouple[2][i]));
    EXPECT_TRUE(std::isnan(s.axialOrCouple[0][i]));
  }
  ASSERT_GT(peak, 1);
  EXPECT_LT(frame, 1e-9 * peak);
  EXPECT_LT(rod, 1e-9 * peak);
  // The lockstitch machine's bevel pairs (joints 5 and 7): the couple, no tooth force.
  ASSERT_TRUE(k.load(test::withMasses(test::example("lockstitch-bevel"), 2)).ok());
  const ForceSamples b = sampleForces(k, 8);
  ASSERT_TRUE(b.complete) << b.status.message;
  for (int j : {5, 7})
    for (size_t i = 0; i < b.size(); ++i) {
      EXPECT_TRUE(std::isnan(b.reaction3N[j][i].x())) << j;
      EXPECT_TRUE(std::isfinite(b.axialOrCouple[j][i])) << j;
    }
  // A planar machine's samples have nothing in space.
  ASSERT_TRUE(k.load(test::example("slider-crank-22a-masses")).ok());
  const ForceSamples p = sampleForces(k, 8);
  EXPECT_FALSE(p.inSpace);
  EXPECT_TRUE(p.shaking3N.empty() && p.reaction3N.empty());
}

}  // namespace
}  // namespace linkage
