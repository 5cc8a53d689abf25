// A window's ends' derivatives (linkage/window_sensitivity.h) against the offset slider-crank's
// closed form: with the crank at theta = 30 + phi degrees from +x, the block on x = e is at
//   y = r sin(theta) + S,  S = sqrt(l^2 - (e - r cos(theta))^2),
// and an end phi_e of "y below L" moves by -(dy/dp) / (dy/dtheta) (implicit functions), with
//   dy/dr = sin(theta) + (e - r cos(theta)) cos(theta) / S,  dy/dl = l / S,
//   dy/dtheta = r cos(theta) - (e - r cos(theta)) r sin(theta) / S.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <string>

#include "linkage/window_sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

TEST(WindowSensitivity, TheSliderCranksClosedForm) {
  const double r = 20, l = 70, e = 12, L = 70;
  for (Direction dir : {Direction::Ccw, Direction::Cw}) {
    test::SliderCrank sc = test::sliderCrank(r, l, e, 30, dir);
    sc.m.timing.windows.push_back({"low", LimitMeasure::along(sc.B, Vec2(0, 1)), true, L});
    Kinematics k;
    ASSERT_TRUE(k.load(sc.m).ok());
    const WindowSensitivity w = windowSensitivity(k, "low", dimensions(sc.m));
    ASSERT_TRUE(w.status.ok()) << w.status.message;
    ASSERT_EQ(w.intervals.size(), 1u);
    auto index = [&](const std::string& name) {
      for (size_t i = 0; i < w.dims.size(); ++i)
        if (w.dims[i].name == name) return i;
      ADD_FAILURE() << name;
      return size_t{0};
    };
    const double sigma = dir == Direction::Ccw ? 1 : -1;  // the crank's turn per crank degree
    for (const auto& [deg, d] : {std::pair{w.intervals[0].fromDeg, &w.intervals[0].dFrom},
                                 std::pair{w.intervals[0].toDeg, &w.intervals[0].dTo}}) {
      const double t = (30 + sigma * deg) * kDeg, c = e - r * std::cos(t);
      const double S = std::sqrt(l * l - c * c);
      ASSERT_NEAR(r * std::sin(t) + S, L, 1e-9);  // an end indeed
      const double dth = sigma * (r * std::cos(t) - c * r * std::sin(t) / S) * kDeg;
      const double dr = std::sin(t) + c * std::cos(t) / S, dl = l / S;
      EXPECT_NEAR((*d)[index("crank.O-A")], -dr / dth, 1e-9) << deg;
      EXPECT_NEAR((*d)[index("rod.A-B")], -dl / dth, 1e-9) << deg;
    }
  }
}

// Windows on the rod's angle and on the block's distance from a ground point Q: each end
// found again in the closed form by Newton's method over complex numbers with one dimension
// stepped by i h (its imaginary part / h the end's exact derivative, the implicit function
// theorem not assumed), the level the output's closed form value at the solver's end.
TEST(WindowSensitivity, ARodsAngleAndADistanceByComplexStep) {
  using C = std::complex<double>;
  const double r = 20, l = 70, e = 12, qx = e + 30, qy = -10, h = 1e-30;
  test::SliderCrank sc = test::sliderCrank(r, l, e, 30);
  const PointId Q = sc.m.addPoint(sc.ground, "Q", Vec2(qx, qy));
  sc.m.timing.windows.push_back({"turn", LimitMeasure::angleOf(sc.rod), true, 5});
  sc.m.timing.windows.push_back({"far", LimitMeasure::distance(sc.B, Q), false, 85});
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  // The rod's angle from +x (its branch's constant aside) and the distance |B - Q|, with their
  // rates in t, the crank's angle from +x; p: r, l, O.x, O.y, Q.x, Q.y.
  struct Out {
    C value, rate;
  };
  auto output = [&](bool angle, C t, const std::array<C, 6>& p) {
    const C ax = p[2] + p[0] * std::cos(t), ay = p[3] + p[0] * std::sin(t);
    const C dx = C(e) - ax, hh = std::sqrt(p[1] * p[1] - dx * dx);
    const C dx1 = p[0] * std::sin(t), h1 = -dx * dx1 / hh, ay1 = p[0] * std::cos(t);
    if (angle) return Out{std::atan(hh / dx), (dx * h1 - hh * dx1) / (p[1] * p[1])};
    const C bx = C(e) - p[4], by = ay + hh - p[5], D = std::sqrt(bx * bx + by * by);
    return Out{D, by * (ay1 + h1) / D};
  };
  const std::array<std::string, 6> names = {"crank.O-A",  "rod.A-B",    "ground.O.x",
                                            "ground.O.y", "ground.Q.x", "ground.Q.y"};
  const std::array<C, 6> p0 = {r, l, 0, 0, qx, qy};
  for (const char* window : {"turn", "far"}) {
    const bool angle = std::string(window) == "turn";
    const WindowSensitivity w = windowSensitivity(k, window, dimensions(sc.m));
    ASSERT_TRUE(w.status.ok()) << window << ": " << w.status.message;
    ASSERT_FALSE(w.intervals.empty()) << window;
    for (const auto& [deg, d] : {std::pair{w.intervals[0].fromDeg, &w.intervals[0].dFrom},
                                 std::pair{w.intervals[0].toDeg, &w.intervals[0].dTo}}) {
      const double te = (30 + deg) * kDeg;
      const C level = output(angle, te, p0).value;
      for (size_t i = 0; i < names.size(); ++i) {
        std::array<C, 6> p = p0;
        p[i] += C(0, h);
        C t = te;
        for (int n = 0; n < 8; ++n) {
          const Out o = output(angle, t, p);
          t -= (o.value - level) / o.rate;
        }
        const double want = t.imag() / h / kDeg;
        size_t at = 0;
        while (w.dims[at].name != names[i]) ++at;
        EXPECT_NEAR((*d)[at], want, 1e-9 * std::max(1.0, std::abs(want)))
            << window << " " << names[i] << " at " << deg;
      }
    }
  }
}

TEST(WindowSensitivity, WhatItCannotDoIsSaid) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  EXPECT_NE(windowSensitivity(k, "none", dimensions(sc.m)).status.message.find("no window"),
            std::string::npos);
}

}  // namespace
}  // namespace linkage
