// A pin's reaction differentiated with respect to the dimensions (linkage/force_sensitivity.h)
// against an offset slider-crank's Newton-Euler closed form, written over std::complex and
// differentiated by the complex step (exact to rounding, independent of the solver's rows):
// the slider's mass pushed along its slot by the rod, the rod's force and moment balance with
// the crank pin's force and the slider pin's, the crank's with its pivot's.
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>
#include <map>
#include <memory>
#include <tuple>

#include "complex_step.h"
#include "examples.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
#include "mechanisms.h"
#include "reaction_checks.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;

struct Pins {
  CVec O, A, B;  // the reactions as linkage/dynamics.h reports them: on the body of point a
  CVec G;        // the guide's on the block (a slider) or on the rod at B (a pin in the slot)
  C couple;      // the guide's couple on the block about B, N m
};

constexpr double kR = 20, kL = 70, kE = 8, kCrankDeg = 30, kRpm = 900;
constexpr double kM1 = 0.1, kM2 = 0.15, kJ2 = 90, kM3 = 0.2;

// The drawn centres: the crank's and the rod's along and across their lines.
struct Drawn {
  double a1, p1, a2, p2;
};

// The block's centre of mass from B (it does not turn: the slot keeps its drawn angle to it).
const Vec2 kBlockCom(1, 2);

Pins closedForm(const std::map<std::string, C>& v, const Drawn& c, double phi, double gy,
                double m3 = kM3) {
  const CVec O{v.at("ground.O.x"), v.at("ground.O.y")};
  const C cr = kR + v.at("crank.O-A"), rl = kL + v.at("rod.A-B");
  const C alpha = M_PI / 2 + v.at("ground.guide.angle") * (M_PI / 180);
  const CVec p0{kE - v.at("ground.guide.offset"), C(0)};
  const CVec dir{std::cos(alpha), std::sin(alpha)}, n = perp(dir);
  const double t = kCrankDeg * M_PI / 180 + phi, w2 = std::pow(kRpm * M_PI / 30, 2);
  const CVec A = O + CVec{cr * std::cos(t), cr * std::sin(t)};
  const CVec wA = A - p0, vA = perp(A - O), aA = O - A;
  const C cc = cross(dir, wA), cv = cross(dir, vA), ca = cross(dir, aA);
  const C root = std::sqrt(rl * rl - cc * cc);
  const CVec B = p0 + (dot(dir, wA) + root) * dir;
  const C s2 = dot(dir, aA) - (cv * cv + cc * ca) / root - cc * cc * cv * cv / (root * root * root);
  // Accelerations at the crank's speed (mm/s^2), the forces in N (kg mm/s^2 / 1000).
  const CVec aB = C(w2) * (s2 * dir), aAt = C(w2) * aA;
  const CVec u = (C(1) / rl) * (B - A), u2 = (C(1) / rl) * (aB - aAt);
  const CVec c2 = A + C(c.a2) * u + C(c.p2) * perp(u);
  const CVec a2 = aAt + C(c.a2) * u2 + C(c.p2) * perp(u2);
  const C psi2 = cross(u, u2);
  const CVec uc = (C(1) / cr) * (A - O), uc2 = (C(1) / cr) * aAt;
  const CVec a1 = C(c.a1) * uc2 + C(c.p1) * perp(uc2);
  (void)uc;
  // The slider: m3 aB = F_Bs + N n, so F_Bs = f dir + beta n with f = m3 aB . dir. The rod:
  // m2 a2 = F_A - F_Bs; kJ2 psi'' = cross(A - c2, F_A) - cross(B - c2, F_Bs). Cramer's rule in
  // (F_A.x, F_A.y, beta).
  // Gravity (0, gy) m/s^2: each mass's weight joins, m (a / 1000 - g) in place of m a / 1000.
  const CVec g{C(0), C(gy * 1000)};
  const C f = C(m3 / 1000) * dot(aB - g, dir);
  const CVec m2a2 = C(kM2 / 1000) * (a2 - g);
  const CVec rA = A - c2, rB = B - c2;
  const C r1 = m2a2.x + f * dir.x, r2 = m2a2.y + f * dir.y,
          r3 = C(kJ2 / 1000) * psi2 + f * cross(rB, dir);
  const C m[3][3] = {{1, 0, -n.x}, {0, 1, -n.y}, {-rA.y, rA.x, -cross(rB, n)}};
  auto det = [](const C(&a)[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const C D = det(m), rhs[3] = {r1, r2, r3};
  C x[3];
  for (int col = 0; col < 3; ++col) {
    C mc[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) mc[i][j] = j == col ? rhs[i] : m[i][j];
    x[col] = det(mc) / D;
  }
  const CVec FA{x[0], x[1]}, FBs = f * dir + x[2] * n;
  // The crank: m1 a1 = F_O - F_A (F_O from the ground at O).
  const CVec FO = C(kM1 / 1000) * (a1 - g) + FA;
  // Reported on the body of each joint's point a: the crank pin's a is the crank's (-F_A), the
  // slider pin's the rod's (-F_Bs), the pivot's the ground's (-F_O).
  // The block: m3 (aB - g) = F_Bs + G, and about B the guide's couple balances the weight's and
  // the inertia's moment at its centre. Without a block (a pin in the slot) G = -F_Bs on the rod.
  const CVec mb = C(m3 / 1000) * (aB - g);
  const CVec G = m3 > 0 ? mb - FBs : C(-1) * FBs;
  const C couple = cross(CVec{C(kBlockCom.x()), C(kBlockCom.y())}, mb) / C(1000);
  return {C(-1) * FO, C(-1) * FA, C(-1) * FBs, G, couple};
}

// The slider-crank with masses on its bodies (the block's: none with a pin in the slot), its
// centres as the closed form reads them, loaded, and its dimensions' values for it.
struct Loaded {
  test::SliderCrank sc;
  Drawn drawn;
  Kinematics k;
  std::vector<Dimension> dims;
  std::map<std::string, C> base;
};

std::unique_ptr<Loaded> loaded(double gy, bool pinInSlot = false) {
  auto out = std::make_unique<Loaded>();
  test::SliderCrank& sc = out->sc =
      test::sliderCrank(kR, kL, kE, kCrankDeg, Direction::Ccw, kRpm, pinInSlot);
  const Vec2 A0 = sc.m.point(sc.A)->pos, B0 = sc.m.point(sc.B)->pos;
  const Vec2 c1(6, 9), c2 = A0 + 0.4 * (B0 - A0) + Vec2(4, -1);
  sc.m.body(sc.crank)->mass = Mass{kM1, c1, 20, ""};
  sc.m.body(sc.rod)->mass = Mass{kM2, c2, kJ2, ""};
  if (!pinInSlot) sc.m.body(sc.slider)->mass = Mass{kM3, B0 + kBlockCom, 0, ""};
  if (gy != 0) sc.m.gravity = Vec2(0, gy);
  const Vec2 u1 = A0.normalized(), u2 = (B0 - A0).normalized();
  out->drawn = {c1.dot(u1), c1.dot(perp(u1)), (c2 - A0).dot(u2), (c2 - A0).dot(perp(u2))};
  EXPECT_TRUE(out->k.load(sc.m).ok());
  out->k.setAccelerations(true);
  out->dims = dimensions(sc.m);
  for (const Dimension& d : out->dims)
    out->base[d.name] = d.name == "ground.O.x" || d.name == "ground.O.y" ? d.value : 0;
  return out;
}

class ForceSensitivity : public ::testing::TestWithParam<double> {};

// Without gravity and with it (the weights' moments about the frames' origins turn with them).
TEST_P(ForceSensitivity, SliderCrankPinsMatchNewtonEulerByComplexStep) {
  const double gy = GetParam();
  const std::unique_ptr<Loaded> l = loaded(gy);
  const test::SliderCrank& sc = l->sc;
  const Drawn& drawn = l->drawn;
  Kinematics& k = l->k;
  const std::vector<Dimension>& dims = l->dims;
  const std::map<std::string, C>& base = l->base;
  const JointId pins[3] = {sc.drive, sc.m.joints[1].id, sc.m.joints[2].id};
  for (int pin = 0; pin < 3; ++pin) {
    std::vector<double> peak(dims.size(), 0), err(dims.size(), 0);
    for (int deg = 0; deg < 360; deg += 10) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const JointForceSensitivity s = jointForceSensitivity(k, pins[pin], dims);
      ASSERT_TRUE(s.status.ok()) << s.status.message;
      auto of = [&](const Pins& p) { return pin == 0 ? p.O : pin == 1 ? p.A : p.B; };
      const CVec exact = of(closedForm(base, drawn, deg * M_PI / 180, gy));
      ASSERT_NEAR(s.force.x(), exact.x.real(), 1e-9 * (1 + s.force.norm())) << pin << " " << deg;
      ASSERT_NEAR(s.force.y(), exact.y.real(), 1e-9 * (1 + s.force.norm())) << pin << " " << deg;
      for (size_t d = 0; d < dims.size(); ++d) {
        std::map<std::string, C> v = base;
        v.at(dims[d].name) += C(0, kH);
        const CVec st = of(closedForm(v, drawn, deg * M_PI / 180, gy));
        const Vec2 want(st.x.imag() / kH, st.y.imag() / kH);
        peak[d] = std::max(peak[d], want.norm());
        err[d] = std::max(err[d], (s.derivative[d] - want).norm());
      }
    }
    for (size_t d = 0; d < dims.size(); ++d) {
      std::printf("  pin %d, d F / d %-20s peak %.6g N per unit, worst error %.2e\n", pin,
                  dims[d].name.c_str(), peak[d], err[d]);
      EXPECT_LT(err[d], 1e-9 * std::max(peak[d], 1e-3)) << pin << " " << dims[d].name;
    }
  }
}

// The slider's reaction (a force normal to its slot that turns with it, and a couple) and a pin in
// a slot's, against the same closed form: every dimension, every 10 degrees.
TEST_P(ForceSensitivity, SliderAndPinInSlotMatchNewtonEulerByComplexStep) {
  const double gy = GetParam();
  for (const bool pinInSlot : {false, true}) {
    const std::unique_ptr<Loaded> l = loaded(gy, pinInSlot);
    const test::SliderCrank& sc = l->sc;
    const Drawn& drawn = l->drawn;
    Kinematics& k = l->k;
    const std::vector<Dimension>& dims = l->dims;
    const std::map<std::string, C>& base = l->base;
    const double m3 = pinInSlot ? 0 : kM3;
    const JointId guide = sc.m.joints.back().id;
    std::vector<double> peak(dims.size(), 0), err(dims.size(), 0);
    for (int deg = 0; deg < 360; deg += 10) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const JointForceSensitivity s = jointForceSensitivity(k, guide, dims);
      ASSERT_TRUE(s.status.ok()) << s.status.message;
      const Pins exact = closedForm(base, drawn, deg * M_PI / 180, gy, m3);
      const double size = 1 + s.force.norm();
      ASSERT_NEAR(s.force.x(), exact.G.x.real(), 1e-9 * size) << pinInSlot << " " << deg;
      ASSERT_NEAR(s.force.y(), exact.G.y.real(), 1e-9 * size) << pinInSlot << " " << deg;
      ASSERT_NEAR(s.reaction.coupleNm, pinInSlot ? 0.0 : exact.couple.real(), 1e-12 * size);
      for (size_t d = 0; d < dims.size(); ++d) {
        std::map<std::string, C> v = base;
        v.at(dims[d].name) += C(0, kH);
        const Pins st = closedForm(v, drawn, deg * M_PI / 180, gy, m3);
        const Eigen::Vector3d want(st.G.x.imag() / kH, st.G.y.imag() / kH,
                                   pinInSlot ? 0.0 : 1000 * st.couple.imag() / kH);
        const Eigen::Vector3d got(s.change[d].force.x(), s.change[d].force.y(),
                                  1000 * s.change[d].coupleNm);  // N mm
        peak[d] = std::max(peak[d], want.norm());
        err[d] = std::max(err[d], (got - want).norm());
        ASSERT_EQ(s.derivative[d], s.change[d].force);
      }
    }
    for (size_t d = 0; d < dims.size(); ++d) {
      std::printf("  %s, d(F, M) / d %-20s peak %.6g per unit, worst error %.2e\n",
                  pinInSlot ? "pin in slot" : "slider", dims[d].name.c_str(), peak[d], err[d]);
      EXPECT_LT(err[d], 1e-9 * std::max(peak[d], 1e-3)) << pinInSlot << " " << dims[d].name;
    }
  }
}

// A counterweight's share of every joint's reaction (what optimize's force target reads over
// counterweights) against the design with the counterweight written in as a mass of its body
// (addCounterweights, solved by the dynamics again), and its derivatives by the static moment
// against central differences of the share (the mass |s| / R following it).
TEST_P(ForceSensitivity, ACounterweightsShareIsTheMassWrittenIn) {
  const std::unique_ptr<Loaded> l = loaded(GetParam());
  Counterweight cw;
  ASSERT_TRUE(counterweightOn(l->sc.m, l->sc.crank, cw).ok());
  auto with = [&](const Vec2& s) {
    Counterweight c = cw;
    c.staticMoment = s;
    c.kg = s.norm() / c.maxRadiusMm;
    return c;
  };
  const Vec2 s0(1.5, -2);
  Mechanism heavier = l->sc.m;
  addCounterweights(heavier, {with(s0)});
  Kinematics kh;
  ASSERT_TRUE(kh.load(heavier).ok());
  double largest = 0;
  for (int deg = 0; deg < 360; deg += 30) {
    ASSERT_TRUE(l->k.moveTo(deg).ok() && kh.moveTo(deg).ok());
    const Forces before = computeForces(l->k), after = computeForces(kh);
    for (size_t j = 0; j < l->sc.m.joints.size(); ++j) {
      const JointId id = l->sc.m.joints[j].id;
      const CounterweightShare sh = counterweightShare(l->k, id, with(s0));
      ASSERT_TRUE(sh.status.ok()) << sh.status.message;
      const Vec2 dF = after.joints[j].force - before.joints[j].force;
      const double dM = after.joints[j].coupleNm - before.joints[j].coupleNm;
      largest = std::max(largest, dF.norm());
      const double size = 1e-9 * (1 + after.joints[j].force.norm());
      EXPECT_LT((sh.share.force - dF).norm(), size) << j << " at " << deg;
      EXPECT_NEAR(sh.share.coupleNm, dM, size) << j << " at " << deg;
      for (int e = 0; e < 2; ++e) {
        const double h = 1e-6;
        const CounterweightShare p = counterweightShare(l->k, id, with(s0 + h * Vec2::Unit(e)));
        const CounterweightShare q = counterweightShare(l->k, id, with(s0 - h * Vec2::Unit(e)));
        const Vec2 want = (p.share.force - q.share.force) / (2 * h);
        const Vec2 got = e == 0 ? sh.perX.force : sh.perY.force;
        EXPECT_LT((got - want).norm(), 1e-7 * (1 + want.norm())) << j << " " << e << " " << deg;
      }
    }
  }
  EXPECT_GT(largest, 1.0);  // the counterweight moves the reactions by newtons
}

// The share's derivatives by every dimension (the counterweight fixed in its body's drawing)
// against the share on the changed designs: on the drop feed's feed rocker (a driven crank's
// share is its own weight and spin whatever the dimensions), with gravity and without.
TEST(ForceSensitivityShare, ACounterweightsShareMovesAsChangedDesignsDo) {
  for (double gy : {-9.81, 0.0}) {
    Mechanism m = test::example("drop-feed");
    m.gravity = Vec2(0, gy);
    Counterweight cw;
    ASSERT_TRUE(counterweightOn(m, m.bodyNamed("feedrock")->id, cw).ok());
    cw.staticMoment = Vec2(1.5, -2);
    cw.kg = cw.staticMoment.norm() / cw.maxRadiusMm;
    double largest = 0;
    test::expectShareMovesAsChangedDesignsDo(m, cw, largest);
    EXPECT_GT(largest, 1e-2) << gy;
  }
}

INSTANTIATE_TEST_SUITE_P(Gravity, ForceSensitivity, ::testing::Values(0.0, -9.81));

}  // namespace
}  // namespace linkage
