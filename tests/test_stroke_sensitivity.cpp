// A stroke's derivatives by the envelope theorem (linkage/stroke_sensitivity.h) against the
// offset slider-crank's closed form: the block on x = e rises from sqrt((l - r)^2 - e^2) to
// sqrt((l + r)^2 - e^2), so S = Y1 - Y2 with
//   dS/dr = (l + r) / Y1 + (l - r) / Y2,  dS/dl = (l + r) / Y1 - (l - r) / Y2,
//   dS/de = -e / Y1 + e / Y2
// (the ground's pivot moved by x shifts e the other way; moved by y, nothing).
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/stroke_sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

TEST(StrokeSensitivity, TheOffsetSliderCranksClosedForm) {
  for (double e : {0.0, 12.0, -7.5}) {
    const double r = 20, l = 70;
    const test::SliderCrank sc = test::sliderCrank(r, l, e, 30);
    Kinematics k;
    ASSERT_TRUE(k.load(sc.m).ok());
    const StrokeSensitivity s = strokeSensitivity(k, sc.B, Vec2(0, 1), dimensions(sc.m));
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    const double Y1 = std::sqrt((l + r) * (l + r) - e * e),
                 Y2 = std::sqrt((l - r) * (l - r) - e * e);
    EXPECT_NEAR(s.limits.stroke, Y1 - Y2, 1e-9);
    auto d = [&](const std::string& name) -> double {
      for (size_t i = 0; i < s.dims.size(); ++i)
        if (s.dims[i].name == name) return s.derivative[i];
      ADD_FAILURE() << "no dimension " << name;
      return NAN;
    };
    EXPECT_NEAR(d("crank.O-A"), (l + r) / Y1 + (l - r) / Y2, 1e-9) << e;
    EXPECT_NEAR(d("rod.A-B"), (l + r) / Y1 - (l - r) / Y2, 1e-9) << e;
    EXPECT_NEAR(d("ground.O.x"), -(-e / Y1 + e / Y2), 1e-9) << e;
    EXPECT_NEAR(d("ground.O.y"), 0, 1e-9) << e;
    EXPECT_NEAR(std::abs(d("ground.guide.offset")), std::abs(-e / Y1 + e / Y2), 1e-9) << e;
  }
}

// What holds whatever the mechanism: a stroke is a length, so scaling every length of the drawing
// by 1 + t scales it by as much (Euler: the lengths times their derivatives add up to the
// stroke; angles and ratios do not scale), and moving the whole ground moves both extremes
// alike (the ground points' derivatives add up to 0 where the ground has no slot).
TEST(StrokeSensitivity, LengthsTimesTheirDerivativesAddUpToTheStroke) {
  for (const char* name : {"wanzer-inversion-2", "four-bar-crank-rocker", "drop-feed"}) {
    const LoadResult l = loadMechanismFile(*resolveModel(name));
    ASSERT_TRUE(l.mechanism) << l.error;
    Kinematics k;
    ASSERT_TRUE(k.load(*l.mechanism).ok());
    const PointId p = l.mechanism->outputs.front();
    const StrokeSensitivity s =
        strokeSensitivity(k, p, defaultDirection(*l.mechanism, p), dimensions(*l.mechanism));
    ASSERT_TRUE(s.status.ok()) << name << ": " << s.status.message;
    double euler = 0;
    for (size_t d = 0; d < s.dims.size(); ++d)
      if (s.dims[d].unit == Dimension::Unit::Mm) euler += s.dims[d].value * s.derivative[d];
    EXPECT_NEAR(euler, s.limits.stroke, 1e-9 * std::max(1.0, s.limits.stroke)) << name;
  }
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 0, true, 30, 20);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const StrokeSensitivity s = strokeSensitivity(k, f.P, Vec2(0.6, 0.8), dimensions(f.m));
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  double x = 0, y = 0;
  for (size_t d = 0; d < s.dims.size(); ++d) {
    if (s.dims[d].name.rfind("ground.", 0) != 0) continue;
    (s.dims[d].name.back() == 'x' ? x : y) += s.derivative[d];
  }
  EXPECT_NEAR(x, 0, 1e-12);
  EXPECT_NEAR(y, 0, 1e-12);
}

}  // namespace
}  // namespace linkage
