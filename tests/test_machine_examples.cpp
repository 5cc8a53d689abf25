// The examples of gear and belt couplings and of arc slots (resources/examples/machines.py:
// lockstitch-arm-shaft, gear-four-bar, planet-epicycloid, curved-guide) against closed forms
// written here from their dimensions, not from the solver: a slider-crank, a four-bar solved by
// intersecting two circles with its velocities and accelerations from the loop equations, an
// epicycloid, a rotation at twice the speed; on the closed-form path (what the program takes) and
// on the general Newton path. Each file loads, solves in closed form, is drawn exactly closed at
// crank angle 0 and turns through two whole revolutions; each is as the program saves it.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "examples.h"
#include "linkage/instant_centres.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

using C = std::complex<double>;
constexpr double kDeg = M_PI / 180;
const C kI(0, 1);

// Positions within 1e-12 of the drawing's size (k.size()), velocities and accelerations within
// 1e-12 of that size times omega and omega^2; body angles within 1e-12 rad per radian turned,
// their rates within 1e-12 omega and omega^2. (The solver is within about 1e-14 of all of them.)
constexpr double kTol = 1e-12;

C c(const Vec2& v) {
  return C(v.x(), v.y());
}

Kinematics loaded(const Mechanism& m, bool closedForm = true) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  const Status s = k.load(m);
  EXPECT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(k.closedForm(), closedForm);
  EXPECT_FALSE(k.assembly().moved);  // drawn exactly closed
  EXPECT_EQ(k.structure().mobility, 1);
  return k;
}

// The mechanism solved group by group in closed form (what the program takes for it), and by
// the general Newton solve: both are held to the same closed forms.
std::vector<Kinematics> bothPaths(const Mechanism& m) {
  std::vector<Kinematics> out;
  out.push_back(loaded(m, true));
  out.push_back(loaded(m, false));
  return out;
}

const char* path(const Kinematics& k) {
  return k.closedForm() ? "closed form" : "general solve";
}

PointId pointOf(const Mechanism& m, const std::string& dotted) {
  const std::optional<PointId> p = m.findPoint(dotted);
  EXPECT_TRUE(p.has_value()) << dotted;
  return p.value_or(PointId{});
}

BodyId bodyOf(const Mechanism& m, const std::string& name) {
  const Body* b = m.bodyNamed(name);
  EXPECT_TRUE(b) << name;
  return b ? b->id : BodyId{};
}

// A point's position, velocity and acceleration as complex numbers.
struct Motion {
  C p, v, a;
};

// The solver's motion of p against the closed form: each within tol of scale, scale omega and
// scale omega^2 (scale: the mechanism's size).
void expectMotion(const Kinematics& k, PointId p, const Motion& want, double tol,
                  const std::string& what) {
  const Kinematics::PointMotion got = k.motion(p);
  const double L = k.size(), w = k.omega();
  EXPECT_LT(std::abs(c(got.position) - want.p), tol * L) << what << " position";
  EXPECT_LT(std::abs(c(got.velocity) - want.v), tol * L * w) << what << " velocity";
  EXPECT_LT(std::abs(c(got.acceleration) - want.a), tol * L * w * w) << what << " acceleration";
}

// Solves x b + y d = r for real x, y (b, d, r complex: two real equations).
std::pair<double, double> solve2(C b, C d, C r) {
  const double det = b.real() * d.imag() - b.imag() * d.real();
  return {(r.real() * d.imag() - r.imag() * d.real()) / det,
          (b.real() * r.imag() - b.imag() * r.real()) / det};
}

// A four-bar: crank O2 -> A of length r2 at angle phi turning at the constant rate w2 (rad/s),
// coupler A -> B of r3, rocker O4 -> B of r4, B to the left of A -> O4 or to its right. The
// loop O2 A + A B = O2 O4 + O4 B differentiated once and twice gives the coupler's and the
// rocker's rates w3, w4 and accelerations a3, a4.
struct FourBar {
  C A, B, vA, aA;
  double w3, w4, a3, a4;
  // The coupler's point z (A + z (B - A), z complex, in units of AB) and its motion.
  Motion coupler(C z) const {
    const C ap = z * (B - A);
    return {A + ap, vA + kI * w3 * ap, aA + (kI * a3 - w3 * w3) * ap};
  }
};

FourBar fourBar(C O2, C O4, double r2, double r3, double r4, double phi, double w2, bool left) {
  FourBar f;
  const C a = std::polar(r2, phi);
  f.A = O2 + a;
  const C e = O4 - f.A;
  const double d = std::abs(e), m = (r3 * r3 - r4 * r4 + d * d) / (2 * d);
  const double h = std::sqrt(r3 * r3 - m * m);
  f.B = f.A + (m + kI * (left ? h : -h)) * (e / d);
  const C b = f.B - f.A, cr = f.B - O4;
  f.vA = kI * w2 * a;
  f.aA = -w2 * w2 * a;
  // i w2 a + i w3 b = i w4 cr.
  std::tie(f.w3, f.w4) = solve2(b, -cr, -w2 * a);
  // -w2^2 a + (i a3 - w3^2) b = (i a4 - w4^2) cr.
  const C rhs = kI * (f.w4 * f.w4 * cr - f.w3 * f.w3 * b - w2 * w2 * a);
  std::tie(f.a3, f.a4) = solve2(b, -cr, rhs);
  return f;
}

// A point turning about the fixed centre o at angle theta(t) = theta0 + n t from the drawing
// (dtheta/dt = n w): where the drawn point p0 is.
Motion turning(C o, C p0, double n, double t, double w) {
  const C r = (p0 - o) * std::exp(kI * n * t);
  return {o + r, kI * n * w * r, -n * n * w * w * r};
}

TEST(MachineExamples, LockstitchNeedleBarIsTheSliderCrank) {
  // Crank 16 from the arm shaft O = (0, 0), drawn straight up and turning counter-clockwise:
  // A = (-r sin t, r cos t); rod 45 down to B on the guide x = e = 0; the needle point 131 below
  // B: y = r cos t - sqrt(l^2 - (r sin t + e)^2) - 131, with its t-derivatives by the chain rule.
  const Mechanism m = test::example("lockstitch-arm-shaft");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const PointId N = pointOf(m, "needlebar.N");
    const double r = 16, l = 45, e = 0, needle = 131, w = k.omega();
    EXPECT_NEAR(w, 1200 * 2 * M_PI / 60, 1e-12 * w);
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = deg * kDeg;
      const double s = r * std::sin(t) + e, s1 = r * std::cos(t), s2 = -r * std::sin(t);
      const double root = std::sqrt(l * l - s * s);
      const double y = r * std::cos(t) - root - needle;
      const double y1 = -r * std::sin(t) + s * s1 / root;
      const double y2 =
          -r * std::cos(t) + (s1 * s1 + s * s2) / root + s * s * s1 * s1 / std::pow(root, 3);
      expectMotion(k, N, {C(e, y), C(0, w * y1), C(0, w * w * y2)}, kTol,
                   "needle at " + std::to_string(deg));
    }
    // Top dead centre in the drawing, bottom dead centre half a turn on: a 32 mm stroke.
    ASSERT_TRUE(k.moveTo(180).ok());
    EXPECT_NEAR(k.position(N).y(), -192, kTol * 200);
  }
}

TEST(MachineExamples, LockstitchHookShaftTurnsTwiceAsFastAsTheArmShaft) {
  // The toothed belt (ratio +2): the hook's angle is exactly twice the arm shaft's, the same
  // way; the hook point K = (12, -191) turns about L = (0, -200) at 2 omega.
  const Mechanism m = test::example("lockstitch-arm-shaft");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const BodyId arm = bodyOf(m, "armshaft"), hook = bodyOf(m, "hook");
    const PointId K = pointOf(m, "hook.K");
    const double w = k.omega();
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = deg * kDeg;
      EXPECT_NEAR(k.bodyAngle(arm), t, kTol * (1 + t));
      EXPECT_NEAR(k.bodyAngle(hook), 2 * k.bodyAngle(arm), kTol * (1 + 2 * t)) << deg;
      EXPECT_NEAR(k.bodyOmega(hook), 2 * w, kTol * w) << deg;
      EXPECT_NEAR(k.bodyAlpha(hook), 0, kTol * w * w) << deg;
      expectMotion(k, K, turning(C(0, -200), C(12, -191), 2, t, w), kTol,
                   "hook point at " + std::to_string(deg));
    }
    // The hook point, drawn at atan2(9, 12) about L, is at the top of its circle (0, -185), on the
    // needle's line, when atan2(9, 12) + 2 t = 90 + 360 degrees: 26.57 degrees past the needle's
    // bottom dead centre (the loop-taking position).
    const double meet = 180 + (90 - std::atan2(9.0, 12.0) / kDeg) / 2;
    ASSERT_TRUE(k.moveTo(meet).ok());
    EXPECT_LT(std::abs(c(k.position(K)) - C(0, -185)), kTol * 200);
  }
}

TEST(MachineExamples, LockstitchTakeUpEyeIsTheCrankRockersCouplerPoint) {
  // Second crank pin T = 16 (4/5, 3/5) on the arm shaft, lever T-R 45, link R-Q 55 to
  // Q = (-20, 48), R to the right of T -> Q; the eye 80 along T -> R.
  const Mechanism m = test::example("lockstitch-arm-shaft");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const PointId E = pointOf(m, "takeup.E");
    const double w = k.omega(), t0 = std::atan2(3.0, 4.0);
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const FourBar f = fourBar(0, C(-20, 48), 16, 45, 55, t0 + deg * kDeg, w, false);
      expectMotion(k, E, f.coupler(80.0 / 45), kTol, "take-up eye at " + std::to_string(deg));
      EXPECT_NEAR(k.bodyOmega(bodyOf(m, "takeup")), f.w3, kTol * w) << deg;
      EXPECT_NEAR(k.bodyAlpha(bodyOf(m, "link")), f.a4, kTol * w * w) << deg;
    }
  }
}

TEST(MachineExamples, GearFourBarIsTheFourBarAtHalfThePinionsAngle) {
  // Pinion at (-45, 0) turning clockwise, ratio -1/2: the gear on O2 = (0, 0) turns
  // counter-clockwise at half the speed; its crank pin, drawn at 60 degrees, drives the four-bar
  // 20, 70, 50 on O2 O4 = 60, B above; the coupler point 35 along and 25 left of A -> B.
  const Mechanism m = test::example("gear-four-bar");
  Kinematics direct = loaded(test::example("four-bar-crank-rocker"));
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const BodyId pinion = bodyOf(m, "pinion"), gear = bodyOf(m, "gear");
    const PointId P = pointOf(m, "coupler.P");
    const double w = k.omega();
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = deg * kDeg;
      EXPECT_NEAR(k.bodyAngle(pinion), -t, kTol * (1 + t));
      EXPECT_NEAR(k.bodyAngle(gear), -0.5 * k.bodyAngle(pinion), kTol * (1 + t)) << deg;
      const FourBar f = fourBar(0, C(60, 0), 20, 70, 50, 60 * kDeg + t / 2, w / 2, true);
      const Motion want = f.coupler(C(35, 25) / 70.0);
      expectMotion(k, P, want, kTol, "coupler point at " + std::to_string(deg));
      // And the four-bar-crank-rocker example itself, driven directly at half the angle and at
      // 60 rpm, the gear's speed.
      ASSERT_TRUE(direct.moveTo(deg / 2).ok());
      const Kinematics::PointMotion d = direct.motion(*direct.mechanism().findPoint("coupler.P"));
      EXPECT_LT(std::abs(c(d.position) - want.p), kTol * k.size()) << deg;
      EXPECT_LT(std::abs(c(d.velocity) - want.v), kTol * k.size() * w) << deg;
      EXPECT_LT(std::abs(c(d.acceleration) - want.a), kTol * k.size() * w * w) << deg;
    }
  }
}

TEST(MachineExamples, PlanetPointTracesTheEpicycloid) {
  // Sun 20 fixed, planet 10 on the arm (ratio -2, carrier the arm): the planet turns 3 t, its
  // rim point P = 30 e^{it} + 10 e^{3it}, a nephroid with cusps at t = 90 and 270 degrees.
  const Mechanism m = test::example("planet-epicycloid");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const PointId P = pointOf(m, "planet.P");
    const BodyId planet = bodyOf(m, "planet");
    const double w = k.omega();
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = deg * kDeg;
      const C e1 = std::exp(kI * t), e3 = std::exp(3.0 * kI * t);
      const Motion want{30.0 * e1 + 10.0 * e3, w * (30.0 * kI * e1 + 30.0 * kI * e3),
                        w * w * (-30.0 * e1 - 90.0 * e3)};
      expectMotion(k, P, want, kTol, "planet point at " + std::to_string(deg));
      EXPECT_NEAR(k.bodyAngle(planet), 3 * t, kTol * (1 + 3 * t)) << deg;
      EXPECT_NEAR(k.bodyOmega(planet), 3 * w, kTol * w) << deg;
    }
    ASSERT_TRUE(k.moveTo(90).ok());  // a cusp: P on the sun's pitch circle, at rest
    EXPECT_LT(std::abs(c(k.position(P)) - C(0, 20)), kTol * 40);
    EXPECT_LT(k.velocity(P).norm(), kTol * 40 * w);
  }
}

TEST(MachineExamples, CurvedGuidesBlockTurnsAboutTheArcsCentre) {
  // Crank 15 drawn straight up, rod 45; the guide is the arc of radius 100 about
  // C = (-100, 45) through (-4, 17), (0, 45), (-4, 73): the block turns about C with the radius,
  // as the rocker of the four-bar 15, 45, 100 on O C would, B above A (right of A -> C).
  const Mechanism m = test::example("curved-guide");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(path(k));
    const PointId B = pointOf(m, "block.B");
    const BodyId block = bodyOf(m, "block");
    const C Cc(-100, 45), B0 = c(m.point(B)->pos);
    const double w = k.omega();
    EXPECT_NEAR(std::abs(B0 - Cc), 100, 1e-13 * 100);
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const FourBar f = fourBar(0, Cc, 15, 45, 100, 90 * kDeg + deg * kDeg, w, false);
      expectMotion(k, B, f.coupler(1), kTol, "block at " + std::to_string(deg));
      EXPECT_NEAR(std::abs(c(k.position(B)) - Cc), 100, kTol * 100) << deg;
      // The block keeps its angle to the radius: it turns as C -> B does.
      EXPECT_NEAR(k.bodyAngle(block), std::arg((f.B - Cc) / (B0 - Cc)), kTol) << deg;
      EXPECT_NEAR(k.bodyOmega(block), f.w4, kTol * w) << deg;
      EXPECT_NEAR(k.bodyAlpha(block), f.a4, kTol * w * w) << deg;
    }
  }
}

const char* const kExamples[] = {"lockstitch-arm-shaft", "gear-four-bar", "planet-epicycloid",
                                 "curved-guide", "overedge-needle-arm"};

TEST(MachineExamples, FilesAreAsTheProgramSavesThem) {
  for (const char* name : kExamples) {
    const std::string path = std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json";
    std::ifstream f(path);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(serializeMechanism(test::example(name)), text) << path;
  }
}

TEST(MachineExamples, InstantCentresAgreeWithTheVelocities) {
  for (const char* name : kExamples) {
    Kinematics k = loaded(test::example(name));
    for (double deg : {0.0, 37.0, 133.0, 250.0}) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      const InstantCentres ics = computeInstantCentres(k);
      ASSERT_TRUE(ics.status.ok()) << name << ": " << ics.status.message;
      EXPECT_TRUE(ics.disagreements.empty()) << name << " " << deg;
    }
  }
}

}  // namespace
}  // namespace linkage
