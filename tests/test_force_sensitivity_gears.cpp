// A gear's and a belt's reaction (restated as a tooth force at the pitch point, a run's pull)
// and their shafts' pins' reactions differentiated with respect to the dimensions
// (linkage/force_sensitivity.h), against a two-shaft train's Newton-Euler closed form over
// std::complex by the complex step: the driven shaft's weight and inertia balanced about its
// pivot by the force where the teeth (the run) meet it, which alone fixes that force's size.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "complex_step.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"

namespace linkage {
namespace {

using test::C;
using test::CVec;
using test::kH;

constexpr double kRpm = 600, kM1 = 0.3, kM2 = 0.2, kJ2 = 150, kTorque = 0.8;
const Vec2 kO(0, 0), kQ(60, 10), kC1(5, 3), kC2(7, -4);  // the pivots; the centres from them

struct Train {
  Mechanism m;
  JointId drive, pinion, gear;
};

Train train(double ratio) {
  Train t;
  Mechanism& m = t.m;
  const BodyId ground = m.addBody("ground", true), wheel = m.addBody("wheel"),
               pinion = m.addBody("pinion");
  const PointId o = m.addPoint(wheel, "O", kO), q = m.addPoint(pinion, "Q", kQ);
  t.drive = m.addPin(m.addPoint(ground, "O", kO), o);
  t.pinion = m.addPin(m.addPoint(ground, "Q", kQ), q);
  t.gear = m.addGear(o, q, ratio);
  m.body(wheel)->mass = Mass{kM1, kO + kC1, 40, ""};
  m.body(pinion)->mass = Mass{kM2, kQ + kC2, kJ2, ""};
  // A torque the pinion drives (without it and without gravity it would need no force at all:
  // a steady turn's inertia force has no moment about the pivot).
  Load l;
  l.body = pinion;
  l.torqueNm = kTorque;
  m.addLoad(l);
  m.driver = Driver{t.drive, kRpm, Direction::Ccw, 0, ""};
  return t;
}

struct Reactions {
  CVec gear, at, O, Q;  // the coupling's force on the wheel and where; the pins' on the ground
};

CVec turned(C t, Vec2 v) {
  return {std::cos(t) * v.x() - std::sin(t) * v.y(), std::sin(t) * v.x() + std::cos(t) * v.y()};
}

Reactions closedForm(const std::map<std::string, C>& v, double ratio, double phi, double gy) {
  const CVec O{v.at("ground.O.x"), v.at("ground.O.y")}, Q{v.at("ground.Q.x"), v.at("ground.Q.y")};
  const C r = ratio + v.at("wheel-pinion.ratio"), w = kRpm * M_PI / 30;
  const CVec g{C(0), C(gy * 1000)};
  // The pinion turns r phi from the drawing at r omega, steadily: its centre's acceleration is
  // centripetal. Its weight and inertia force W2, their moment about Q.
  const CVec c2 = turned(r * phi, kC2), a2 = C(-1) * (r * r * w * w) * c2;
  const CVec W2 = C(kM2 / 1000) * (g - a2);
  const C M2 = cross(c2, W2) + 1000 * kTorque;  // N mm; no angular acceleration for kJ2
  const C d = std::sqrt(dot(Q - O, Q - O));
  const CVec u = (C(1) / d) * (Q - O);
  CVec X, e, at;  // where the pinion is pushed, along which line; where the wheel is
  if (ratio < 0) {
    const C toPitch = -r * d / (C(1) - r);
    X = at = O + toPitch * u;
    e = perp(u);
  } else {  // the pulleys as drawn (the drawn centres' distance), the outer tangent
    const double d0 = (kQ - kO).norm();
    const C r0 = ratio >= 1 ? C(d0 / 6) : r * d0 / 6.0,
            r1 = ratio >= 1 ? d0 / (C(6) * r) : d0 / 6.0;
    const C along = (r0 - r1) / d;
    const CVec n = along * u - std::sqrt(C(1) - along * along) * perp(u);
    at = O + r0 * n;
    X = Q + r1 * n;
    e = (C(1) / std::sqrt(dot(X - at, X - at))) * (X - at);
  }
  // The pinion about Q: cross(X - Q, -f e) + M2 = 0; the force on the wheel is f e.
  const CVec F = (M2 / cross(X - Q, e)) * e;
  const CVec W1 = C(kM1 / 1000) * (g - C(-w * w) * turned(C(phi), kC1));
  // Each pin's force on the ground: the shaft's from the ground balances F (-F on the pinion)
  // and the shaft's weight and inertia.
  return {F, at, F + W1, W2 - F};
}

class GearForceSensitivity : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(GearForceSensitivity, TrainMatchesNewtonEulerByComplexStep) {
  const auto [ratio, gy] = GetParam();
  Train t = train(ratio);
  if (gy != 0) t.m.gravity = Vec2(0, gy);
  Kinematics k;
  ASSERT_TRUE(k.load(t.m).ok());
  k.setAccelerations(true);
  const std::vector<Dimension> dims = dimensions(t.m);
  std::map<std::string, C> base;
  for (const Dimension& d : dims) base[d.name] = d.name.starts_with("ground.") ? d.value : 0;
  ASSERT_EQ(base.size(), 5u);
  const JointId joints[3] = {t.gear, t.drive, t.pinion};
  for (int which = 0; which < 3; ++which) {
    std::vector<double> peak(dims.size(), 0), err(dims.size(), 0);
    for (int deg = 0; deg < 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const JointForceSensitivity s = jointForceSensitivity(k, joints[which], dims);
      ASSERT_TRUE(s.status.ok()) << s.status.message;
      const double phi = deg * M_PI / 180;
      auto of = [&](const Reactions& r) { return which == 0 ? r.gear : which == 1 ? r.O : r.Q; };
      const Reactions exact = closedForm(base, ratio, phi, gy);
      const double size = 1 + s.force.norm();
      ASSERT_NEAR(s.force.x(), of(exact).x.real(), 1e-9 * size) << which << " " << deg;
      ASSERT_NEAR(s.force.y(), of(exact).y.real(), 1e-9 * size) << which << " " << deg;
      if (which == 0)
        ASSERT_NEAR((s.reaction.at - Vec2(exact.at.x.real(), exact.at.y.real())).norm(), 0, 1e-9);
      for (size_t d = 0; d < dims.size(); ++d) {
        std::map<std::string, C> v = base;
        v.at(dims[d].name) += C(0, kH);
        const Reactions st = closedForm(v, ratio, phi, gy);
        const Vec2 want(of(st).x.imag() / kH, of(st).y.imag() / kH);
        peak[d] = std::max(peak[d], want.norm());
        err[d] = std::max(err[d], (s.change[d].force - want).norm());
        if (which == 0) {
          const Vec2 at(st.at.x.imag() / kH, st.at.y.imag() / kH);
          EXPECT_LT((s.change[d].at - at).norm(), 1e-12 * (1 + at.norm())) << dims[d].name;
        }
      }
    }
    for (size_t d = 0; d < dims.size(); ++d) {
      std::printf("  ratio %g, joint %d, dF / d %-20s peak %.6g N per unit, worst error %.2e\n",
                  ratio, which, dims[d].name.c_str(), peak[d], err[d]);
      EXPECT_LT(err[d], 1e-9 * std::max(peak[d], 1e-3)) << which << " " << dims[d].name;
    }
  }
}

// A gear pair (ratio < 0) and belts either way round (the larger pulley on either shaft), with
// gravity and without.
INSTANTIATE_TEST_SUITE_P(Trains, GearForceSensitivity,
                         ::testing::Combine(::testing::Values(-1.5, 0.5, 2.0),
                                            ::testing::Values(0.0, -9.81)));

}  // namespace
}  // namespace linkage
