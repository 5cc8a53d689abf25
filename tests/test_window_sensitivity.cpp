// A window's ends' derivatives (linkage/window_sensitivity.h) against the offset slider-crank's
// closed form: with the crank at theta = 30 + phi degrees from +x, the block on x = e is at
//   y = r sin(theta) + S,  S = sqrt(l^2 - (e - r cos(theta))^2),
// and an end phi_e of "y below L" moves by -(dy/dp) / (dy/dtheta) (implicit functions), with
//   dy/dr = sin(theta) + (e - r cos(theta)) cos(theta) / S,  dy/dl = l / S,
//   dy/dtheta = r cos(theta) - (e - r cos(theta)) r sin(theta) / S.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(WindowSensitivity, WhatItCannotDoIsSaid) {
  test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  sc.m.timing.windows.push_back({"turn", LimitMeasure::angleOf(sc.rod), true, 10});
  Kinematics k;
  ASSERT_TRUE(k.load(sc.m).ok());
  EXPECT_NE(windowSensitivity(k, "turn", dimensions(sc.m)).status.message.find("body's angle"),
            std::string::npos);
  EXPECT_NE(windowSensitivity(k, "none", dimensions(sc.m)).status.message.find("no window"),
            std::string::npos);
}

}  // namespace
}  // namespace linkage
