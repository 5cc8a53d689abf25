// A dyad's transmission angle's derivatives (linkage/transmission_sensitivity.h) against two
// independent truths:
// - the four-bar's closed form, the law of cosines in the crank angle: with crank a, coupler b,
//   rocker c, ground d = |O4 - O2| at psi = atan2 of O4 - O2, and the crank at theta from +x,
//     mu = acos((b^2 + c^2 - a^2 - d^2 + 2 a d cos(theta - psi)) / (2 b c)),
//   differentiated with respect to every length and ground coordinate by the complex step
//   (f(x + ih) = f(x) + ih f'(x) + O(h^2): Im f(x + ih) / h is f' to the last bit, h = 1e-30);
// - Euler's theorem for homogeneous functions: an angle does not change when every length is
//   scaled, so sum_i L_i d(mu)/d(L_i) = 0 over every length dimension (the ground points'
//   coordinates included; slot angles and gear ratios are not lengths), in the examples.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "examples.h"
#include "linkage/transmission_sensitivity.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using C = std::complex<double>;
constexpr double kDeg = M_PI / 180;

// mu in degrees from the four-bar's lengths and ground points; theta the crank's direction.
C lawOfCosines(C o2x, C o2y, C o4x, C o4y, C a, C b, C c, double theta) {
  const C dx = o4x - o2x, dy = o4y - o2y;
  const C d = std::sqrt(dx * dx + dy * dy), psi = std::atan(dy / dx);  // dx > 0 here
  return std::acos((b * b + c * c - a * a - d * d + 2.0 * a * d * std::cos(theta - psi)) /
                   (2.0 * b * c)) /
         kDeg;
}

// Each dimension's d(mu)/d(dimension) by the complex step; 0 for the coupler point's.
double complexStep(const std::string& name, double d, double a, double b, double c, double theta) {
  const char* names[] = {"ground.O2.x", "ground.O2.y", "ground.O4.x", "ground.O4.y",
                         "crank.O2-A",  "coupler.A-B", "rocker.B-O4"};
  const double h = 1e-30;
  C x[] = {0, 0, d, 0, a, b, c};
  for (int i = 0; i < 7; ++i)
    if (name == names[i]) {
      x[i] += C(0, h);
      return lawOfCosines(x[0], x[1], x[2], x[3], x[4], x[5], x[6], theta).imag() / h;
    }
  return 0;
}

TEST(TransmissionSensitivity, TheFourBarsLawOfCosinesByTheComplexStep) {
  const double d = 60, a = 20, b = 70, c = 50, start = 35;
  double worst = 0;
  for (bool open : {true, false})
    for (Direction dir : {Direction::Ccw, Direction::Cw}) {
      const test::FourBar f = test::fourBar(d, a, b, c, start, open, 35, 25, dir);
      Kinematics k;
      ASSERT_TRUE(k.load(f.m).ok());
      const std::vector<TransmissionJoint> js = transmissionJoints(f.m);
      ASSERT_EQ(js.size(), 1u);
      ASSERT_TRUE(dyadDifferentiable(f.m, js[0]).ok());
      Sensitivity s;
      ASSERT_TRUE(s.prepare(k, dimensions(f.m)).ok());
      ASSERT_EQ(s.dims().size(), 9u);
      for (int deg = 0; deg < 360; deg += 5) {
        ASSERT_TRUE(k.moveTo(deg).ok());
        ASSERT_TRUE(s.at(k).ok());
        const double theta = (start + (dir == Direction::Ccw ? deg : -deg)) * kDeg;
        EXPECT_NEAR(dyadAngleSensitivity(k, js[0], nullptr, 0, nullptr),
                    lawOfCosines(0, 0, d, 0, a, b, c, theta).real(), 1e-9)
            << deg;
        const std::vector<double> got = dyadAngleDerivatives(k, js[0], s);
        std::vector<double> want;
        double scale = 0;
        for (const Dimension& dim : s.dims()) {
          want.push_back(complexStep(dim.name, d, a, b, c, theta));
          scale = std::max(scale, std::abs(want.back()));
        }
        for (size_t i = 0; i < want.size(); ++i) {
          // Relative to the pose's largest: near a zero crossing one derivative alone is tiny.
          EXPECT_NEAR(got[i], want[i], 1e-9 * scale) << s.dims()[i].name << " at " << deg;
          worst = std::max(worst, std::abs(got[i] - want[i]) / scale);
        }
      }
    }
  std::cout << "largest difference / the pose's largest derivative: " << worst << "\n";
}

TEST(TransmissionSensitivity, EulersHomogeneityInTheExamples) {
  int checked = 0;
  for (const char* name : {"needle-876-alpha-0", "lockstitch-machine", "overedge-needle-arm",
                           "drop-feed", "four-bar-crank-rocker"}) {
    const Mechanism m = test::example(name);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dimensions(m)).ok()) << name;
    for (const TransmissionJoint& j : transmissionJoints(m)) {
      if (!dyadDifferentiable(m, j).ok()) continue;
      for (int deg = 0; deg < 360; deg += 15) {
        ASSERT_TRUE(k.moveTo(deg).ok()) << name;
        ASSERT_TRUE(s.at(k).ok()) << name;
        const std::vector<double> d = dyadAngleDerivatives(k, j, s);
        double sum = 0, size = 0;
        for (size_t i = 0; i < d.size(); ++i) {
          if (s.dims()[i].unit != Dimension::Unit::Mm) continue;
          sum += s.dims()[i].value * d[i];
          size += std::abs(s.dims()[i].value * d[i]);
        }
        ASSERT_GT(size, 1);  // degrees: the angle does depend on the lengths
        EXPECT_NEAR(sum, 0, 1e-11 * size) << name << " " << j.label << " at " << deg;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24 * (2 + 2 + 3 + 2 + 1));  // every dyad of the five
}

TEST(TransmissionSensitivity, WhatIsNotADyadBetweenPointsIsRefusedByName) {
  const Mechanism guide = test::example("curved-guide");
  const std::vector<TransmissionJoint> g = transmissionJoints(guide);
  ASSERT_EQ(g.size(), 1u);
  const Status arc = dyadDifferentiable(guide, g[0]);
  EXPECT_EQ(arc.code, StatusCode::BadModel);
  EXPECT_NE(arc.message.find("mu:rod.B is a dyad with ground.guide's centre (an arc slot)"),
            std::string::npos)
      << arc.message;
  const test::SliderCrank sc = test::sliderCrank(20, 70, 12, 30);
  const std::vector<TransmissionJoint> r = transmissionJoints(sc.m);
  ASSERT_EQ(r.size(), 1u);
  const Status rod = dyadDifferentiable(sc.m, r[0]);
  EXPECT_EQ(rod.code, StatusCode::BadModel);
  EXPECT_NE(rod.message.find(r[0].label + " is a rod-slider angle"), std::string::npos)
      << rod.message;
}

}  // namespace
}  // namespace linkage
