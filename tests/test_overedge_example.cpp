// The overedge-needle-arm example (resources/examples/machines.py; seed 004, Przytulski and
// Zajaczkowski): the needle arm's displacement U along its slot and the lower gripper's rocker
// angle a5, with their first and second time derivatives, against closed forms written here from
// the dimensions: the paper's eq. 2a for the needle arm, fed by a four-bar solved by intersecting
// circles, and two four-bars in series for the gripper; rates by the chain rule through the loop
// equations, never by differences. Both solve paths, every 2.5 degrees over two turns, 1e-9 of the
// cycle's peak. Then the slot travel that `linkage-cli slots` and `info` report, against the
// extremes of the same closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>
#include <string>
#include <vector>

#include "examples.h"
#include "linkage/kinematics.h"

#ifdef LINKAGE_CLI
#include "cli_harness.h"
#include "linkage/io/numbers.h"
#endif

namespace linkage {
namespace {

using C = std::complex<double>;
constexpr double kDeg = M_PI / 180;
const C kI(0, 1);
constexpr double kTol = 1e-9;

// The example's numbers (machines.py): main shaft O at the origin, crank R1 drawn straight up.
constexpr double kR1 = 7.5, kL1 = 67, kW1 = 28.5, kW2 = 41.5, kL2 = 16, kXs = 41, kNeedle = 55;
const C kH(0, 71.8), kF(-10, -55), kK(30, -60), kD0(-6, 8);
constexpr double kL3 = 55, kW3 = 24, kW4 = 20, kL4 = 42, kW5 = 22, kP = 52;
const double kPhase2 = std::atan2(7.0, 24.0);   // W2 ahead of W1
const double kPhase4 = std::atan2(-40.0, 9.0);  // W4 from W3

// A rocker O4 -> B of r4 driven through a coupler A -> B of r3 by the pin A, whose position,
// velocity and acceleration are given; B to the left of A -> O4 or to its right. From
// (A - O4) + b = cr, b = B - A, cr = B - O4 differentiated: vA + i w3 b = i w4 cr and
// aA + (i a3 - w3^2) b = (i a4 - w4^2) cr, two real 2 x 2 solves.
struct Rocker {
  C B;
  double w3, w4, a3, a4;
};

std::pair<double, double> solve2(C b, C d, C r) {  // x b + y d = r, x and y real
  const double det = b.real() * d.imag() - b.imag() * d.real();
  return {(r.real() * d.imag() - r.imag() * d.real()) / det,
          (b.real() * r.imag() - b.imag() * r.real()) / det};
}

Rocker rocker(C A, C vA, C aA, C O4, double r3, double r4, bool left) {
  Rocker k;
  const C e = O4 - A;
  const double d = std::abs(e), m = (r3 * r3 - r4 * r4 + d * d) / (2 * d);
  const double h = std::sqrt(r3 * r3 - m * m);
  k.B = A + (m + kI * (left ? h : -h)) * (e / d);
  const C b = k.B - A, cr = k.B - O4;
  std::tie(k.w3, k.w4) = solve2(kI * b, -kI * cr, -vA);
  std::tie(k.a3, k.a4) = solve2(kI * b, -kI * cr, k.w3 * k.w3 * b - k.w4 * k.w4 * cr - aA);
  return k;
}

// An angle and its first two time derivatives.
struct Angle {
  double a, w, al;
};

// W1's angle about H at crank angle phi (rad from the drawing, ccw at w rad/s).
Angle needleRocker(double phi, double w) {
  const C a = std::polar(kR1, M_PI / 2 + phi);
  const Rocker r = rocker(a, kI * w * a, -w * w * a, kH, kL1, kW1, false);
  return {std::arg(r.B - kH), r.w4, r.a4};
}

// Eq. 2a: X_H - X_G - L2 sin b2 - W2 cos a2 = 0, -U + L2 cos b2 - W2 sin a2 = 0, with
// X_H - X_G = 41, a2 W2's angle from x, u pointing down (cos b2 > 0: the arm below W2's end).
// s = sin b2 = (41 - W2 cos a2) / L2, c = cos b2 = sqrt(1 - s^2); U, U', U'' by the chain rule.
struct Travel {
  double u, v, a;
};

Travel needleArm(double phi, double w) {
  const Angle w1 = needleRocker(phi, w);
  const double a2 = w1.a + kPhase2, d1 = w1.w, d2 = w1.al;
  const double ca = std::cos(a2), sa = std::sin(a2);
  const double s = (kXs - kW2 * ca) / kL2;
  const double s1 = kW2 * sa * d1 / kL2, s2 = kW2 * (ca * d1 * d1 + sa * d2) / kL2;
  const double c = std::sqrt(1 - s * s);
  const double c1 = -s * s1 / c, c2 = -(s1 * s1 + s * s2) / c - s * s * s1 * s1 / (c * c * c);
  return {kL2 * c - kW2 * sa, kL2 * c1 - kW2 * ca * d1,
          kL2 * c2 + kW2 * sa * d1 * d1 - kW2 * ca * d2};
}

// The lower gripper: the crank pin D on the main shaft drives W3 about F (four-bar R2 L3 W3);
// W4, on the same body, drives W5 about K through L4 (four-bar W4 L4 W5, its input rocking).
Angle gripperRocker(double phi, double w) {
  const C d = kD0 * std::exp(kI * phi);
  const Rocker r3 = rocker(d, kI * w * d, -w * w * d, kF, kL3, kW3, false);
  const double a4 = std::arg(r3.B - kF) + kPhase4;
  const C q = std::polar(kW4, a4);
  const Rocker r5 =
      rocker(kF + q, kI * r3.w4 * q, (kI * r3.a4 - r3.w4 * r3.w4) * q, kK, kL4, kW5, true);
  return {std::arg(r5.B - kK), r5.w4, r5.a4};
}

struct Peaks {
  double p = 0, v = 0, a = 0;
};

std::vector<Kinematics> bothPaths(const Mechanism& m) {
  std::vector<Kinematics> out;
  for (bool closedForm : {true, false}) {
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics k(opt);
    const Status s = k.load(m);
    EXPECT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(k.closedForm(), closedForm);
    EXPECT_FALSE(k.assembly().moved);  // drawn exactly closed
    EXPECT_EQ(k.structure().mobility, 1);
    out.push_back(std::move(k));
  }
  return out;
}

TEST(OveredgeExample, NeedleArmFollowsEquation2a) {
  const Mechanism m = test::example("overedge-needle-arm");
  const PointId N = *m.findPoint("needlearm.N"), G = *m.findPoint("needlearm.G");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(k.closedForm() ? "closed form" : "general solve");
    const double w = k.omega();
    EXPECT_NEAR(w, 6000 * 2 * M_PI / 60, 1e-12 * w);
    Peaks peak;
    for (int i = 0; i < 360; ++i) {
      const Travel t = needleArm(i * kDeg, w);
      peak = {std::max(peak.p, std::abs(t.u)), std::max(peak.v, std::abs(t.v)),
              std::max(peak.a, std::abs(t.a))};
    }
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const Travel t = needleArm(deg * kDeg, w);
      // The block's pin G is U below H; the needle point 55 below G; both on x = 41.
      const Kinematics::PointMotion n = k.motion(N);
      EXPECT_NEAR(k.position(G).y(), kH.imag() - t.u, kTol * peak.p) << deg;
      EXPECT_NEAR(n.position.x(), kXs, kTol * peak.p) << deg;
      EXPECT_NEAR(n.position.y(), kH.imag() - t.u - kNeedle, kTol * peak.p) << deg;
      EXPECT_NEAR(n.velocity.x(), 0, kTol * peak.v) << deg;
      EXPECT_NEAR(n.velocity.y(), -t.v, kTol * peak.v) << deg;
      EXPECT_NEAR(n.acceleration.x(), 0, kTol * peak.a) << deg;
      EXPECT_NEAR(n.acceleration.y(), -t.a, kTol * peak.a) << deg;
    }
  }
}

TEST(OveredgeExample, GripperRockerFollowsTwoFourBarsInSeries) {
  const Mechanism m = test::example("overedge-needle-arm");
  const BodyId gripper = m.bodyNamed("gripper")->id;
  const PointId P = *m.findPoint("gripper.P");
  for (Kinematics& k : bothPaths(m)) {
    SCOPED_TRACE(k.closedForm() ? "closed form" : "general solve");
    const double w = k.omega(), a50 = gripperRocker(0, w).a;
    Peaks peak;
    for (int i = 0; i < 360; ++i) {
      const Angle g = gripperRocker(i * kDeg, w);
      peak = {std::max(peak.p, std::abs(g.a - a50)), std::max(peak.v, std::abs(g.w)),
              std::max(peak.a, std::abs(g.al))};
    }
    for (double deg = 0; deg <= 720; deg += 2.5) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const Angle g = gripperRocker(deg * kDeg, w);
      EXPECT_NEAR(k.bodyAngle(gripper), g.a - a50, kTol * peak.p) << deg;
      EXPECT_NEAR(k.bodyOmega(gripper), g.w, kTol * peak.v) << deg;
      EXPECT_NEAR(k.bodyAlpha(gripper), g.al, kTol * peak.a) << deg;
      // The gripper point, 52 from K on the line K -> M.
      const C p = kK + std::polar(kP, g.a);
      EXPECT_LT(std::abs(C(k.position(P).x(), k.position(P).y()) - p), kTol * kP) << deg;
    }
  }
}

TEST(OveredgeExample, NeedleArmAssemblesOverTheWholeSwing) {
  // Eq. 2a closes while |41 - W2 cos a2| <= L2; W2's phase on the rocker was chosen so that it
  // holds with a wide margin over W1's whole swing (under 2.1 of L2's 16), so the needle arm
  // neither locks nor changes branch. a2 is read from the solver's pose of W2's end C.
  const Mechanism m = test::example("overedge-needle-arm");
  Kinematics k = std::move(bothPaths(m).front());
  const PointId Cp = *m.findPoint("needlerock.C");
  double worst = 0;
  for (double deg = 0; deg < 360; deg += 0.5) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const C c = C(k.position(Cp).x(), k.position(Cp).y()) - kH;
    EXPECT_NEAR(std::abs(c), kW2, 1e-12 * kW2);
    worst = std::max(worst, std::abs(kXs - kW2 * std::cos(std::arg(c))));
    EXPECT_NEAR(std::arg(c), needleRocker(deg * kDeg, 1).a + kPhase2, 1e-12) << deg;
  }
  EXPECT_LT(worst, 2.1);
}

// Seed 004's baseline: the paper fits Lagrange polynomials to sampled positions and
// differentiates them. Here the fits are the central 5- and 7-point Lagrange derivatives of the
// needle's positions, as the solver samples them N times a turn, against its exact velocity and
// acceleration (which the tests above hold to the closed form): their errors are those of the
// fits, falling as h^4 and h^6 (16 and 64 times from N = 36 to 72), and still about 1e-4 and
// 4e-6 of the peaks at 36 samples (README.md of the examples gives the numbers).
struct FitErrors {
  double v5 = 0, a5 = 0, v7 = 0, a7 = 0;
};

FitErrors lagrangeErrors(Kinematics& k, PointId N, int n) {
  static const double d5[] = {1, -8, 0, 8, -1}, s5[] = {-1, 16, -30, 16, -1};
  static const double d7[] = {-1, 9, -45, 0, 45, -9, 1}, s7[] = {2, -27, 270, -490, 270, -27, 2};
  std::vector<double> y(n), v(n), a(n);
  for (int i = 0; i < n; ++i) {
    EXPECT_TRUE(k.moveTo(360.0 * i / n).ok());
    y[i] = k.position(N).y(), v[i] = k.velocity(N).y(), a[i] = k.acceleration(N).y();
  }
  const double h = 2 * M_PI / n / k.omega();  // seconds between samples
  double pv = 0, pa = 0;                      // the peaks of |v| and |a| over the turn
  for (int i = 0; i < n; ++i) pv = std::max(pv, std::abs(v[i])), pa = std::max(pa, std::abs(a[i]));
  FitErrors e;
  for (int i = 0; i < n; ++i) {
    double f[4] = {0, 0, 0, 0};
    for (int j = -3; j <= 3; ++j) {
      const double yj = y[(i + j + n) % n];
      if (std::abs(j) <= 2) f[0] += d5[j + 2] * yj, f[1] += s5[j + 2] * yj;
      f[2] += d7[j + 3] * yj, f[3] += s7[j + 3] * yj;
    }
    e.v5 = std::max(e.v5, std::abs(f[0] / (12 * h) - v[i]) / pv);
    e.a5 = std::max(e.a5, std::abs(f[1] / (12 * h * h) - a[i]) / pa);
    e.v7 = std::max(e.v7, std::abs(f[2] / (60 * h) - v[i]) / pv);
    e.a7 = std::max(e.a7, std::abs(f[3] / (180 * h * h) - a[i]) / pa);
  }
  return e;
}

TEST(OveredgeExample, LagrangeFitsOfSampledPositionsErrAsTheirOrder) {
  const Mechanism m = test::example("overedge-needle-arm");
  Kinematics k = std::move(bothPaths(m).front());
  const PointId N = *m.findPoint("needlearm.N");
  const FitErrors e36 = lagrangeErrors(k, N, 36), e72 = lagrangeErrors(k, N, 72);
  EXPECT_NEAR(e36.v5 / e72.v5, 16, 4);
  EXPECT_NEAR(e36.a5 / e72.a5, 16, 4);
  EXPECT_NEAR(e36.v7 / e72.v7, 64, 16);
  EXPECT_NEAR(e36.a7 / e72.a7, 64, 16);
  EXPECT_GT(e36.v5, 1e-5);  // far from the exact derivatives' 1e-9
  EXPECT_GT(e36.a7, 1e-6);  // (7.7e-5 and 3.3e-6 when written)
}

#ifdef LINKAGE_CLI
using test::CliResult;

class OveredgeCli : public test::CliTest {};

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> v;
  std::istringstream s(line);
  for (std::string f; std::getline(s, f, ',');) v.push_back(f);
  return v;
}

// The extremes of U over a turn: the roots of U' (exact, from the closed form), bisected.
std::pair<double, double> travelExtremes() {
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 360; ++i) {
    double a = i * kDeg, b = (i + 1) * kDeg;
    const bool rising = needleArm(a, 1).v > 0;
    if (rising == (needleArm(b, 1).v > 0)) continue;
    for (int it = 0; it < 80; ++it) {
      const double mid = (a + b) / 2;
      ((needleArm(mid, 1).v > 0) == rising ? a : b) = mid;
    }
    const double u = needleArm((a + b) / 2, 1).u;
    lo = std::min(lo, u), hi = std::max(hi, u);
  }
  return {lo, hi};
}

TEST_F(OveredgeCli, NeedleArmStaysInsideItsSlot) {
  // The slot u runs from (41, 75) down to (41, 30): the block's arc length from its first end is
  // 75 - y_G = 75 - 71.8 + U.
  const auto [ulo, uhi] = travelExtremes();
  const CliResult r = run("slots overedge-needle-arm");
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 2u) << r.out;
  const std::vector<std::string> f = fields(lines[1]);
  ASSERT_EQ(f.size(), 6u) << lines[1];
  EXPECT_EQ(f[0], "needlearm.G");
  const double from = 75 - kH.imag();
  EXPECT_NEAR(*parseNumber(f[1]), from + ulo, 1e-9 * 45);
  EXPECT_NEAR(*parseNumber(f[2]), from + uhi, 1e-9 * 45);
  EXPECT_EQ(*parseNumber(f[3]), 0);
  EXPECT_NEAR(*parseNumber(f[4]), 45, 1e-12);
  EXPECT_EQ(f[5], "yes");
  // With a margin of more than 10 mm at each end.
  EXPECT_GT(from + ulo, 10);
  EXPECT_LT(from + uhi, 35);
  const CliResult info = run("info overedge-needle-arm");
  ASSERT_EQ(info.exit, 0) << info.err;
  EXPECT_NE(info.out.find("slot travel: needlearm.G in ground.u: "), std::string::npos) << info.out;
  EXPECT_EQ(info.out.find("leaves the slot"), std::string::npos) << info.out;
  // Grashof, the crank shortest (7.5 + 71.8 < 67 + 28.5): the needle drive's crank turns fully.
  EXPECT_NE(info.out.find("four-bar loop ground-main-needlerod-needlerock: frame 71.8, input 7.5, "
                          "coupler 67, output 28.5 mm: crank-rocker"),
            std::string::npos)
      << info.out;
}
// The crank angles (degrees, in [0, 360)) where f crosses zero, bisected to the last bit.
template <class F>
std::vector<double> roots(F f) {
  std::vector<double> out;
  for (int i = 0; i < 3600; ++i) {
    double a = i / 10.0, b = (i + 1) / 10.0;
    const bool neg = f(a) < 0;
    if (neg == (f(b) < 0)) continue;
    for (int it = 0; it < 80; ++it) {
      const double mid = (a + b) / 2;
      ((f(mid) < 0) == neg ? a : b) = mid;
    }
    out.push_back((a + b) / 2);
  }
  return out;
}

TEST_F(OveredgeCli, TimingWindowsOfTheNeedleAndTheGripperPoint) {
  // docs/timing.md's command: the needle point below y = 0 (roots of 71.8 - U - 55) and the
  // gripper point right of the needle's line x = 41 (roots of K_x + 52 cos a5 - 41).
  const std::vector<double> needle =
      roots([](double deg) { return kH.imag() - needleArm(deg * kDeg, 1).u - kNeedle; });
  const std::vector<double> grip = roots(
      [](double deg) { return kK.real() + kP * std::cos(gripperRocker(deg * kDeg, 1).a) - kXs; });
  ASSERT_EQ(needle.size(), 2u);
  ASSERT_EQ(grip.size(), 2u);
  const CliResult r =
      run("timing overedge-needle-arm --window 'needle=needlearm.N:y<0' "
          "--window 'gripper=gripper.P:x>41' --conflict needle,gripper");
  EXPECT_EQ(r.exit, 4) << r.err;  // the windows overlap: the gripper takes the needle's loop
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[0], "window,from_deg,to_deg");
  // The needle goes below first (it descends), the gripper point crosses going right and comes
  // back after the turn: its window wraps past 360.
  const double want[3][2] = {
      {needle[0], needle[1]}, {grip[1], grip[0] + 360}, {grip[1], needle[1]}};
  const char* names[3] = {"needle", "gripper", "conflict:needle+gripper"};
  for (int i = 0; i < 3; ++i) {
    const std::vector<std::string> f = fields(lines[i + 1]);
    ASSERT_EQ(f.size(), 3u) << lines[i + 1];
    EXPECT_EQ(f[0], names[i]);
    EXPECT_NEAR(*parseNumber(f[1]), want[i][0], 1e-9) << f[0];
    EXPECT_NEAR(*parseNumber(f[2]), want[i][1], 1e-9) << f[0];
  }
}

// The same two windows are the file's own (issue 26): `timing` with no option prints them,
// without the conflict (their overlap is the loop-taking, wanted), exit 0.
TEST_F(OveredgeCli, ShipsTheNeedleAndGripperWindows) {
  const std::vector<double> needle =
      roots([](double deg) { return kH.imag() - needleArm(deg * kDeg, 1).u - kNeedle; });
  const std::vector<double> grip = roots(
      [](double deg) { return kK.real() + kP * std::cos(gripperRocker(deg * kDeg, 1).a) - kXs; });
  ASSERT_EQ(needle.size(), 2u);
  ASSERT_EQ(grip.size(), 2u);
  const CliResult r = run("timing overedge-needle-arm");
  EXPECT_EQ(r.exit, 0) << r.err;
  const std::vector<std::string> lines = r.lines();
  ASSERT_EQ(lines.size(), 3u) << r.out;
  const double want[2][2] = {{needle[0], needle[1]}, {grip[1], grip[0] + 360}};
  const char* names[2] = {"needle", "gripper"};
  for (int i = 0; i < 2; ++i) {
    const std::vector<std::string> f = fields(lines[i + 1]);
    ASSERT_EQ(f.size(), 3u) << lines[i + 1];
    EXPECT_EQ(f[0], names[i]);
    EXPECT_NEAR(*parseNumber(f[1]), want[i][0], 1e-9) << f[0];
    EXPECT_NEAR(*parseNumber(f[2]), want[i][1], 1e-9) << f[0];
  }
}
#endif

}  // namespace
}  // namespace linkage
