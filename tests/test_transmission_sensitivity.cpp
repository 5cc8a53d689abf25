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
      Sensitivity s;
      ASSERT_TRUE(s.prepare(k, dimensions(f.m)).ok());
      ASSERT_EQ(s.dims().size(), 9u);
      for (int deg = 0; deg < 360; deg += 5) {
        ASSERT_TRUE(k.moveTo(deg).ok());
        ASSERT_TRUE(s.at(k).ok());
        const double theta = (start + (dir == Direction::Ccw ? deg : -deg)) * kDeg;
        EXPECT_NEAR(transmissionAngleSensitivity(k, js[0], nullptr, 0, nullptr),
                    lawOfCosines(0, 0, d, 0, a, b, c, theta).real(), 1e-9)
            << deg;
        const std::vector<double> got = transmissionAngleDerivatives(k, js[0], s);
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
  int checked = 0, expected = 0;
  for (const char* name : {"needle-876-alpha-0", "lockstitch-machine", "overedge-needle-arm",
                           "drop-feed", "four-bar-crank-rocker"}) {
    const Mechanism m = test::example(name);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << name;
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dimensions(m)).ok()) << name;
    for (const TransmissionJoint& j : transmissionJoints(m)) {
      expected += j.kind == TransmissionKind::Dyad ? 24 : 0;
      for (int deg = 0; deg < 360; deg += 15) {
        ASSERT_TRUE(k.moveTo(deg).ok()) << name;
        ASSERT_TRUE(s.at(k).ok()) << name;
        const std::vector<double> d = transmissionAngleDerivatives(k, j, s);
        double sum = 0, size = 0;
        for (size_t i = 0; i < d.size(); ++i) {
          if (s.dims()[i].unit != Dimension::Unit::Mm) continue;
          sum += s.dims()[i].value * d[i];
          size += std::abs(s.dims()[i].value * d[i]);
        }
        // A rod along its slot (a centred slider-crank's dead centre) is at 90, stationary.
        if (j.kind != TransmissionKind::Dyad && size <= 1) continue;
        ASSERT_GT(size, 1);  // degrees: the angle does depend on the lengths
        EXPECT_NEAR(sum, 0, 1e-11 * size) << name << " " << j.label << " at " << deg;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, expected);  // every dyad of the five, and the rods' angles
  EXPECT_EQ(expected, 24 * (2 + 2 + 3 + 2 + 1));
}

// The offset slider-crank's rod angle (a block on a slider and a pin in the slot), by the law
// of sines: the slot's line through P0 = (e, 0) + offset n0 at angle alpha, the crank pin
// A = O + r (cos theta, sin theta); the rod of length l makes sin(theta_rod) = cross(d, A - P0) / l
// with the slot, so mu = acos(|cross(d, A - P0)| / l), differentiated by the complex step in
// the ground pivot's x and y, r, l, the slot's offset and its angle (degrees).
C lawOfSines(C ox, C oy, C r, C l, C offset, C alphaDeg, double e, double theta) {
  const C a = alphaDeg * kDeg;
  const C dx = std::cos(a), dy = std::sin(a);
  (void)e;
  const C p0x = -offset, p0y = 0.0;  // (e, 0) moved by offset + e along n0 = (-1, 0)
  const C ax = ox + r * std::cos(theta), ay = oy + r * std::sin(theta);
  C c = dx * (ay - p0y) - dy * (ax - p0x);
  if (c.real() < 0) c = -c;
  return std::acos(c / l) / kDeg;
}

TEST(TransmissionSensitivity, TheSliderCranksLawOfSinesByTheComplexStep) {
  const double r = 20, l = 70, e = 12, start = 30;
  const char* names[] = {"ground.O.x",          "rod.A-B",           "crank.O-A", "ground.O.y",
                         "ground.guide.offset", "ground.guide.angle"};
  for (bool pin : {false, true})
    for (Direction dir : {Direction::Ccw, Direction::Cw}) {
      const test::SliderCrank sc = test::sliderCrank(r, l, e, start, dir, 60, pin);
      Kinematics k;
      ASSERT_TRUE(k.load(sc.m).ok());
      const std::vector<TransmissionJoint> js = transmissionJoints(sc.m);
      ASSERT_EQ(js.size(), 1u);
      EXPECT_EQ(js[0].kind, pin ? TransmissionKind::RodInSlot : TransmissionKind::RodSlider);
      Sensitivity s;
      ASSERT_TRUE(s.prepare(k, dimensions(sc.m)).ok());
      for (int deg = 0; deg < 360; deg += 5) {
        ASSERT_TRUE(k.moveTo(deg).ok());
        ASSERT_TRUE(s.at(k).ok());
        const double theta = (start + (dir == Direction::Ccw ? deg : -deg)) * kDeg;
        const double mu = transmissionAngleSensitivity(k, js[0], nullptr, 0, nullptr);
        EXPECT_NEAR(mu, lawOfSines(0, 0, r, l, -e, 90, e, theta).real(), 1e-9) << deg;
        EXPECT_NEAR(mu, transmissionAngle(k, js[0]).deg, 1e-9) << deg;
        const std::vector<double> got = transmissionAngleDerivatives(k, js[0], s);
        std::vector<double> want;
        double scale = 0;
        for (const Dimension& dim : s.dims()) {
          C x[] = {0, l, r, 0, -e, 90};
          for (int i = 0; i < 6; ++i)
            if (dim.name == names[i]) x[i] += C(0, 1e-30);
          want.push_back(lawOfSines(x[0], x[3], x[2], x[1], x[4], x[5], e, theta).imag() / 1e-30);
          scale = std::max(scale, std::abs(want.back()));
        }
        for (size_t i = 0; i < want.size(); ++i)
          EXPECT_NEAR(got[i], want[i], 1e-10 * scale) << s.dims()[i].name << " at " << deg;
        // Moving the whole frame (every ground point and slot by dx) turns nothing.
        double frame = 0;
        for (size_t i = 0; i < got.size(); ++i) {
          const std::string& n = s.dims()[i].name;
          if (n == "ground.O.x") frame += got[i];
          if (n == "ground.guide.offset") frame -= got[i];  // the slot's normal is -x
        }
        EXPECT_NEAR(frame, 0, 1e-12 * std::max(1.0, scale)) << deg;
      }
    }
}

// A crank driving a block in an arc slot (and a pin in it): the block turns about the arc's
// centre c as a rocker of the radius rho would, so mu at B between B->A and B->c is
// acos((l^2 + rho^2 - |A - c|^2) / (2 l rho)), by the complex step in every dimension.
TEST(TransmissionSensitivity, ACurvedGuidesLawOfCosinesByTheComplexStep) {
  const Vec2 A0(0, 15), B0(-1.1292513648949634, 59.98582878368345);
  const double l = (B0 - A0).norm();
  for (bool pin : {false, true}) {
    Mechanism m;
    const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"), rod = m.addBody("rod");
    const PointId gO = m.addPoint(g, "O", Vec2(0, 0));
    const SlotId guide = m.addArcSlot(g, "guide", Vec2(-4, 17), Vec2(0, 45), Vec2(-4, 73));
    const PointId cO = m.addPoint(crank, "O", Vec2(0, 0)), cA = m.addPoint(crank, "A", A0);
    const PointId rA = m.addPoint(rod, "A", A0), rB = m.addPoint(rod, "B", B0);
    const JointId drive = m.addPin(gO, cO);
    m.addPin(cA, rA);
    if (pin) {
      m.addPinInSlot(rB, guide);
    } else {
      const PointId bB = m.addPoint(m.addBody("block"), "B", B0);
      m.addPin(rB, bB);
      m.addSlider(bB, guide);
    }
    m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const std::vector<TransmissionJoint> js = transmissionJoints(m);
    ASSERT_EQ(js.size(), 1u);
    Sensitivity s;
    ASSERT_TRUE(s.prepare(k, dimensions(m)).ok());
    auto closed = [&](const std::string& name, double theta, C* value) {
      const char* names[] = {"ground.O.x",
                             "ground.O.y",
                             "crank.O-A",
                             "rod.A-B",
                             "ground.guide.centre.x",
                             "ground.guide.centre.y",
                             "ground.guide.radius"};
      C x[] = {0, 0, 15, l, -100, 45, 100};
      for (int i = 0; i < 7; ++i)
        if (name == names[i]) x[i] += C(0, 1e-30);
      const C ax = x[0] + x[2] * std::cos(theta) - x[4], ay = x[1] + x[2] * std::sin(theta) - x[5];
      const C mu = std::acos((x[3] * x[3] + x[6] * x[6] - ax * ax - ay * ay) / (2.0 * x[3] * x[6]));
      if (value) *value = mu / kDeg;
      return (mu / kDeg).imag() / 1e-30;
    };
    for (int deg = 0; deg < 360; deg += 5) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      ASSERT_TRUE(s.at(k).ok());
      const double theta = (90 + deg) * kDeg;
      C mu;
      closed("", theta, &mu);
      EXPECT_NEAR(transmissionAngleSensitivity(k, js[0], nullptr, 0, nullptr), mu.real(), 1e-9);
      const std::vector<double> got = transmissionAngleDerivatives(k, js[0], s);
      double scale = 0, frame = 0;
      for (const Dimension& d : s.dims())
        scale = std::max(scale, std::abs(closed(d.name, theta, 0)));
      for (size_t i = 0; i < got.size(); ++i) {
        const std::string& n = s.dims()[i].name;
        EXPECT_NEAR(got[i], closed(n, theta, nullptr), 1e-10 * scale) << n << " at " << deg;
        if (n == "ground.O.x" || n == "ground.guide.centre.x") frame += got[i];
      }
      EXPECT_NEAR(frame, 0, 1e-12 * std::max(1.0, scale)) << deg;
    }
  }
}

}  // namespace
}  // namespace linkage
