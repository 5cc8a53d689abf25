// Seed 004's overedge machine as its paper draws it (resources/examples/spatial.py writes
// overedge-machine.linkage.json): the needle arm's U(phi1) derived here from the paper's own
// equations 1a, 1b and 2a, solved by Newton with no solver row, and its rates by differentiating
// those equations analytically (never by differences), against the example's solved needle arm.
//
// How the printed equations are read (docs/seed004.md says the same):
// - eq. 1a's third line prints "- R_I sin rho I": it is - R1 sin phi1 (the crank turns in the
//   plane across the main shaft, y and z; the second line has + R1 cos phi1);
// - eq. 1b prints cos^2 eta_v: it is eta_y; "+ -" is one minus; the rockers' axis is inclined
//   at rho (the text once calls it theta);
// - the paper's v12 = pi: W2 is W1 turned half a turn on the rockers' axis. Eq. 2a's signs
//   (-W2 cos a2, -W2 sin a2 against eq. 1a's +W1 cos a1, and +W1 sin a1 along
//   (0, -cos rho, sin rho)) already hold the half turn, so a2 = a1, with u = (0, -cos rho,
//   sin rho), the direction of eq. 1a's sin a1 term; the branch cos b2 > 0 (the paper solves
//   b2 by its arcsine).
// - the measured H1 (y 149.5, z 88.5) lies 0.13 mm off the axis through H that rho gives: the
//   axis is rho's, as eq. 1a's cos rho and sin rho have it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "examples.h"
#include "linkage/grashof.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/slot_travel.h"
#include "linkage/space.h"

namespace linkage {
namespace {

// The paper's data (metres, as it gives them), in mm.
constexpr double kMm = 1000;
constexpr double kR1 = 0.0075 * kMm, kL1 = 0.067 * kMm, kL2 = 0.016 * kMm;
constexpr double kW1 = 0.0285 * kMm, kW2 = 0.0415 * kMm;
constexpr double kXA1 = 0.138 * kMm, kYA = 0.073 * kMm, kZA = 0.079 * kMm;
constexpr double kXH = 0.111 * kMm, kYH = 0.1345 * kMm, kZH = 0.0535 * kMm;
constexpr double kYH1 = 0.1495 * kMm, kZH1 = 0.0885 * kMm, kXG = 0.070 * kMm;
const double kRho = 23 * M_PI / 180;

// Eqs. 1a and 1b: x = (a1, cos eta_x, cos eta_y, cos eta_z) at the crank angle phi.
using V4 = Eigen::Vector4d;
V4 eq1(const V4& x, double phi) {
  const double a = x[0], cr = std::cos(kRho), sr = std::sin(kRho);
  return {kXH + kW1 * std::cos(a) + kL1 * x[1] - kXA1,
          kYH - kW1 * std::sin(a) * cr - kL1 * x[2] + kR1 * std::cos(phi) - kYA,
          kZH + kW1 * std::sin(a) * sr + kL1 * x[3] - kR1 * std::sin(phi) - kZA,
          x[1] * x[1] + x[2] * x[2] + x[3] * x[3] - 1};
}

Eigen::Matrix4d eq1Jacobian(const V4& x) {
  const double a = x[0], cr = std::cos(kRho), sr = std::sin(kRho);
  Eigen::Matrix4d J;
  J << -kW1 * std::sin(a), kL1, 0, 0,       //
      -kW1 * std::cos(a) * cr, 0, -kL1, 0,  //
      kW1 * std::cos(a) * sr, 0, 0, kL1,    //
      0, 2 * x[1], 2 * x[2], 2 * x[3];
  return J;
}

// The needle arm at phi: a1 and U with their first two derivatives by phi.
struct NeedleArm {
  V4 x, x1, x2;  // eq. 1's unknowns and their derivatives
  double b2, u, u1, u2;
};

// Newton on eqs. 1a and 1b from `start` (the previous angle's solution), then eq. 2a in closed
// form; the rates from the equations differentiated once and twice by phi:
//   J x' = -F_phi,   J x'' = -(F_phiphi + F_xx[x', x'])   (F has no mixed terms).
NeedleArm paper(double phi, V4 start) {
  NeedleArm n;
  V4 x = start;
  for (int it = 0; it < 50; ++it) {
    const V4 dx = eq1Jacobian(x).fullPivLu().solve(eq1(x, phi));
    x -= dx;
    if (dx.norm() < 1e-15) break;
  }
  EXPECT_LT(eq1(x, phi).norm(), 1e-12) << phi;
  const Eigen::Matrix4d J = eq1Jacobian(x);
  const double a = x[0], cr = std::cos(kRho), sr = std::sin(kRho);
  const V4 Fp(0, -kR1 * std::sin(phi), -kR1 * std::cos(phi), 0);
  const V4 x1 = J.fullPivLu().solve(-Fp);
  const double w2 = x1[0] * x1[0];
  const V4 Fpp(0, -kR1 * std::cos(phi), kR1 * std::sin(phi), 0);
  const V4 Fxx(-kW1 * std::cos(a) * w2, kW1 * std::sin(a) * cr * w2, -kW1 * std::sin(a) * sr * w2,
               2 * (x1[1] * x1[1] + x1[2] * x1[2] + x1[3] * x1[3]));
  const V4 x2 = J.fullPivLu().solve(-(Fpp + Fxx));
  n.x = x, n.x1 = x1, n.x2 = x2;
  // Eq. 2a with a2 = a1: X_H - X_G - L2 sin b2 - W2 cos a2 = 0, -U + L2 cos b2 - W2 sin a2 = 0.
  const double a1 = x1[0], a2 = x2[0], ca = std::cos(a), sa = std::sin(a);
  const double b = std::asin((kXH - kXG - kW2 * ca) / kL2), cb = std::cos(b), sb = std::sin(b);
  // Once: -L2 cos b2 b2' + W2 sin a2 a2' = 0; twice: the same with the squares of the rates.
  const double b1 = kW2 * sa * a1 / (kL2 * cb);
  const double bb = (kL2 * sb * b1 * b1 + kW2 * ca * a1 * a1 + kW2 * sa * a2) / (kL2 * cb);
  n.b2 = b;
  n.u = kL2 * cb - kW2 * sa;
  n.u1 = -kL2 * sb * b1 - kW2 * ca * a1;
  n.u2 = -kL2 * cb * b1 * b1 - kL2 * sb * bb + kW2 * sa * a1 * a1 - kW2 * ca * a2;
  return n;
}

// From a guess at phi = 0 (W1 along x, the rod's direction cosines from eq. 1a's three lines
// with that a1), each angle from the one before.
std::vector<NeedleArm> paperTurn(int steps) {
  std::vector<NeedleArm> out;
  V4 x(0, 0, 0, 0);
  x.tail<3>() = (eq1(x, 0).head<3>() / kL1).cwiseProduct(Eigen::Vector3d(-1, 1, -1));
  for (int i = 0; i <= steps; ++i) {
    out.push_back(paper(2 * M_PI * i / steps, x));
    x = out.back().x;
  }
  return out;
}

TEST(Seed004, TheRockersAxisIsRhosAndTheMeasuredH1LiesOffIt) {
  const Vec3 d(0, kYH1 - kYH, kZH1 - kZH), axis(0, std::sin(kRho), std::cos(kRho));
  const double off = (d - d.dot(axis) * axis).norm();
  EXPECT_NEAR(off, 0.132, 0.0005);  // H1's own angle: atan(15 / 35) = 23.2 degrees
  EXPECT_NEAR(std::atan2(15.0, 35.0) * 180 / M_PI, 23.1986, 1e-4);
  // The example's rocker plane: its normal is that axis (pointing the other way), through H.
  const Mechanism m = test::example("overedge-machine");
  const Plane* p = planeNamed(m, "rocker");
  ASSERT_NE(p, nullptr);
  EXPECT_LT((p->normal() + axis).norm(), 1e-15);
  EXPECT_EQ(p->origin, Vec3(kXH, kYH, kZH));
}

TEST(Seed004, TheNeedleArmFollowsThePapersEquationsWithExactRates) {
  const Mechanism m = test::example("overedge-machine");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  EXPECT_FALSE(k.assembly().moved);  // drawn closed at phi1 = 0
  const PointId G = *m.findPoint("needlearm.G"), N = *m.findPoint("needlearm.N");
  const BodyId rock = m.bodyNamed("needlerock")->id;
  const Vec3 H(kXH, kYH, kZH), u(0, -std::cos(kRho), std::sin(kRho));
  const std::vector<NeedleArm> e = paperTurn(720);
  double pu1 = 0, pu2 = 0, pa1 = 0, pa2 = 0, umin = 1e9, umax = -1e9;
  for (const NeedleArm& n : e) {
    pu1 = std::max(pu1, std::abs(n.u1)), pu2 = std::max(pu2, std::abs(n.u2));
    pa1 = std::max(pa1, std::abs(n.x1[0])), pa2 = std::max(pa2, std::abs(n.x2[0]));
    umin = std::min(umin, n.u), umax = std::max(umax, n.u);
  }
  EXPECT_NEAR(umax - umin, 21.825, 0.001);  // the needle arm's stroke
  const double w = k.omega();
  for (size_t i = 0; i < e.size(); ++i) {
    const double deg = 0.5 * i;
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const NeedleArm& n = e[i];
    const Kinematics::PointMotion3 g = k.motionInSpace(G);
    EXPECT_NEAR((g.position - H).dot(u), n.u, 1e-9) << deg;
    EXPECT_NEAR(g.velocity.dot(u), n.u1 * w, 1e-9 * pu1 * w) << deg;
    EXPECT_NEAR(g.acceleration.dot(u), n.u2 * w * w, 1e-9 * pu2 * w * w) << deg;
    // The arm keeps to its line x = X_G in the rockers' plane; the needle point with it.
    EXPECT_NEAR(g.position.x(), kXG, 1e-9) << deg;
    EXPECT_NEAR(k.motionInSpace(N).position.x(), kXG, 1e-9) << deg;
    EXPECT_LT(g.velocity.cross(u).norm(), 1e-9 * pu1 * w) << deg;
    // W1's angle a1 (from the drawing's) and its rates.
    EXPECT_NEAR(k.bodyAngle(rock), n.x[0] - e[0].x[0], 1e-10) << deg;
    EXPECT_NEAR(k.bodyOmega(rock), n.x1[0] * w, 1e-9 * pa1 * w) << deg;
    EXPECT_NEAR(k.bodyAlpha(rock), n.x2[0] * w * w, 1e-9 * pa2 * w * w) << deg;
  }
}

TEST(Seed004, TheDrawingIsThePapersPositionAtPhi1Zero) {
  // The rod L1 is as long as the paper's 67 mm in the drawing, and L2 16 (both to 1e-12).
  const Mechanism m = test::example("overedge-machine");
  auto world = [&](const char* p) { return worldOf(m, *m.point(*m.findPoint(p))); };
  EXPECT_NEAR((world("main.A1") - world("needlerock.B")).norm(), kL1, 1e-12);
  EXPECT_NEAR((world("needlerock.C") - world("needlelink.G")).norm(), kL2, 1e-12);
  EXPECT_NEAR((world("needlerock.B") - Vec3(kXH, kYH, kZH)).norm(), kW1, 1e-12);
  EXPECT_NEAR((world("needlerock.C") - Vec3(kXH, kYH, kZH)).norm(), kW2, 1e-12);
  EXPECT_NEAR((world("main.A1") - Vec3(kXA1, kYA, kZA)).norm(), kR1, 1e-12);
  // W2 opposite W1 (the paper's v12 = pi): H, B and C on one line, H between.
  const Vec3 hb = world("needlerock.B") - Vec3(kXH, kYH, kZH),
             hc = world("needlerock.C") - Vec3(kXH, kYH, kZH);
  EXPECT_LT(hb.cross(hc).norm(), 1e-12 * kW1 * kW2);
  EXPECT_LT(hb.dot(hc), 0);
  const NeedleArm n = paperTurn(1).front();
  EXPECT_NEAR(n.x[0] * 180 / M_PI, 13.3349, 1e-4);
}

TEST(Seed004, ExamplesReadAndSaveByteForByte) {
  for (const char* name : {"overedge-machine", "lockstitch-bevel", "rssr-crank-rocker"}) {
    const std::string path = std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json";
    const Mechanism m = test::example(name);
    std::ifstream f(path);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(serializeMechanism(m), text) << name;
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    EXPECT_FALSE(k.assembly().moved) << name;
    for (int deg = 0; deg <= 720; deg += 5) ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
  }
}

// The paper's own way to the rates: Lagrange polynomials fitted to sampled positions, then
// differentiated. As central 5- and 7-point Lagrange derivatives of U sampled from the solver N
// times a turn, against the paper's exact U' and U'' (the equations above, no solver rate): their
// errors are the fits', falling as h^4 and h^6 (16 and 64 times from 36 to 72 samples), and at
// 36 samples about 1e-4 and 5e-6 of the peaks, where the solver's are 1e-9 at most (the test
// above). docs/seed004.md gives the numbers (scripts/seed004-compare.py).
struct FitErrors {
  double v5 = 0, a5 = 0, v7 = 0, a7 = 0;
};

FitErrors lagrangeErrors(int n) {
  const Mechanism m = test::example("overedge-machine");
  Kinematics k;
  EXPECT_TRUE(k.load(m).ok());
  const PointId G = *m.findPoint("needlearm.G");
  const Vec3 H(kXH, kYH, kZH), u(0, -std::cos(kRho), std::sin(kRho));
  const std::vector<NeedleArm> e = paperTurn(n);
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(k.moveTo(360.0 * i / n).ok());
    y[i] = (k.motionInSpace(G).position - H).dot(u);
  }
  static const double d5[] = {1, -8, 0, 8, -1}, s5[] = {-1, 16, -30, 16, -1};
  static const double d7[] = {-1, 9, -45, 0, 45, -9, 1}, s7[] = {2, -27, 270, -490, 270, -27, 2};
  const double h = 2 * M_PI / n;  // radians of crank between samples: rates by phi1
  double pv = 0, pa = 0;
  for (int i = 0; i < n; ++i)
    pv = std::max(pv, std::abs(e[i].u1)), pa = std::max(pa, std::abs(e[i].u2));
  FitErrors f;
  for (int i = 0; i < n; ++i) {
    double s[4] = {0, 0, 0, 0};
    for (int j = -3; j <= 3; ++j) {
      const double yj = y[(i + j + n) % n];
      if (std::abs(j) <= 2) s[0] += d5[j + 2] * yj, s[1] += s5[j + 2] * yj;
      s[2] += d7[j + 3] * yj, s[3] += s7[j + 3] * yj;
    }
    f.v5 = std::max(f.v5, std::abs(s[0] / (12 * h) - e[i].u1) / pv);
    f.a5 = std::max(f.a5, std::abs(s[1] / (12 * h * h) - e[i].u2) / pa);
    f.v7 = std::max(f.v7, std::abs(s[2] / (60 * h) - e[i].u1) / pv);
    f.a7 = std::max(f.a7, std::abs(s[3] / (180 * h * h) - e[i].u2) / pa);
  }
  return f;
}

TEST(Seed004, ThePapersLagrangeFitsErrAsTheirOrderWhereTheExactRatesDoNot) {
  const FitErrors e36 = lagrangeErrors(36), e72 = lagrangeErrors(72);
  EXPECT_NEAR(e36.v5 / e72.v5, 16, 4);
  EXPECT_NEAR(e36.a5 / e72.a5, 16, 4);
  EXPECT_NEAR(e36.v7 / e72.v7, 64, 16);
  EXPECT_NEAR(e36.a7 / e72.a7, 64, 16);
  EXPECT_NEAR(e36.v5, 8.1e-5, 0.1e-5);  // as docs/seed004.md has them
  EXPECT_NEAR(e36.a7, 5.2e-6, 0.1e-6);
}

// The analyses that measure along a slot or between pivots take a machine's ground points in the
// plane of the joint, as the solver does: the needle arm's travel along its slot u (written in
// the world) is the paper's U, from its smallest to its largest (the roots of eq. 2a's U'); the
// transport's first loop has the frame |B| in the main shaft's plane, 53.23 mm (read in the
// drawing plane, the slot was 107 to 129 mm along and the frame 64.26: the block "left its slot").
TEST(Seed004, SlotTravelAndFourBarFramesAreTakenInTheJointsPlane) {
  const Mechanism m = test::example("overedge-machine");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const SlotTravels t = slotTravel(k);
  ASSERT_TRUE(t.status.ok()) << t.status.message;
  ASSERT_EQ(t.joints.size(), 1u);
  double lo = 1e9, hi = -1e9;
  const std::vector<NeedleArm> e = paperTurn(3600);
  for (size_t i = 0; i + 1 < e.size(); ++i) {
    if ((e[i].u1 > 0) == (e[i + 1].u1 > 0)) continue;
    // U at the root of U' between the two samples: Newton on U' from the nearer one.
    NeedleArm n = e[i];
    double phi = 2 * M_PI * i / 3600;
    for (int it = 0; it < 20; ++it) {
      phi -= n.u1 / n.u2;
      n = paper(phi, n.x);
    }
    lo = std::min(lo, n.u), hi = std::max(hi, n.u);
  }
  EXPECT_NEAR(t.joints[0].min, lo, 1e-9);
  EXPECT_NEAR(t.joints[0].max, hi, 1e-9);
  EXPECT_NEAR(t.joints[0].slotTo, 40, 1e-12);
  EXPECT_TRUE(t.joints[0].inside);
  EXPECT_TRUE(t.allInside());
  const std::vector<FourBarLoop> loops = fourBarLoops(m);
  const BodyId feedrod = m.bodyNamed("feedrod")->id;
  const auto loop = std::find_if(loops.begin(), loops.end(), [&](const FourBarLoop& l) {
    return std::count(l.bodies.begin(), l.bodies.end(), feedrod) > 0;
  });
  ASSERT_NE(loop, loops.end());
  EXPECT_NEAR(loop->lengths[0], std::hypot(48.0, 23.0), 1e-12);
  EXPECT_EQ(loop->kind, GrashofClass::CrankRocker);
}

}  // namespace
}  // namespace linkage
