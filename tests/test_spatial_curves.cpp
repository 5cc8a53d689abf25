// Curves of a machine in space (linkage/motion_samples.h): the distance between two points in
// space and a component along a direction out of the x-y plane, order by order, against the
// RSSR's closed form (spatial_fixtures.h: the rocker's angle and its rates from its equation,
// no solver row used); and two points that meet, whose distance has no rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "examples.h"
#include "linkage/extremes.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/motion_samples.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using namespace test::rssr;

// The rocker's point C: its position and first two derivatives by the crank angle, from the
// rocker's closed form.
struct Motion3 {
  Vec3 p, d1, d2;
};
std::vector<Motion3> rockerPointC(int steps) {
  std::vector<Motion3> out;
  const double l = test::rssrRod();
  double psi = kPsi0;
  for (int i = 0; i <= steps; ++i) {
    const test::Rocker r = test::rockerNear(2 * M_PI * i / steps, psi, l);
    psi = r.psi;
    const Vec3 e = std::cos(psi) * kX + std::sin(psi) * kY,
               t = -std::sin(psi) * kX + std::cos(psi) * kY;
    out.push_back({kH + kW * e, kW * r.d1 * t, kW * (r.d2 * t - r.d1 * r.d1 * e)});
  }
  return out;
}

struct SpatialCurvesOfTheRssr : ::testing::Test {
  void SetUp() override {
    LoadResult r = parseMechanism(test::rssrText());
    ASSERT_TRUE(r.mechanism) << r.error;
    m = *r.mechanism;
    ASSERT_TRUE(k.load(m).ok());
    C = *m.findPoint("rocker.C");
    O = *m.findPoint("ground.O");
    SampleSpec spec;
    spec.points = {C, O};
    spec.steps = 360;
    spec.world = true;
    s = sampleMotion(k, spec);
    ASSERT_TRUE(s.complete()) << s.status.message;
    truth = rockerPointC(360);
  }
  // The closed form's value of each order at sample i, from f(position, d/dphi, d2/dphi2).
  template <class F>
  void expectCurve(const Quantity& q, F f) {
    const double w = k.omega();
    for (int o = 0; o < 3; ++o) {
      const Curve c = curveOf(s, q, static_cast<Order>(o));
      ASSERT_TRUE(c.status.ok()) << c.status.message;
      double peak = 0;
      for (const Motion3& t : truth) peak = std::max(peak, std::abs(f(t)[o]));
      for (size_t i = 0; i < truth.size(); ++i)
        EXPECT_NEAR(c.values[i], f(truth[i])[o] * std::pow(w, o), 1e-9 * peak * std::pow(w, o))
            << "order " << o << " at " << i;
    }
  }
  Mechanism m;
  Kinematics k;
  PointId C, O;
  MotionSamples s;
  std::vector<Motion3> truth;
};

TEST_F(SpatialCurvesOfTheRssr, TheDistanceBetweenTwoPointsInSpaceAndItsRatesAreTheClosedForms) {
  // |C - O| with O the origin: d = |C|, d' = C . C' / d, d'' = (C' . C' + C . C'' - d'^2) / d.
  auto distance = [](const Motion3& t) {
    const double d = t.p.norm(), d1 = t.p.dot(t.d1) / d;
    return std::array<double, 3>{d, d1, (t.d1.squaredNorm() + t.p.dot(t.d2) - d1 * d1) / d};
  };
  Quantity q = Quantity::distance(C, O);
  q.world = true;
  expectCurve(q, distance);
  // The extremes are where the closed form's rate is zero.
  const Extremes e = extremesOf(s, q, Order::Position);
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_GT(e.range(), 1.0);
  for (const Extreme& x : {e.max, e.min}) {
    const test::Rocker r = test::rockerNear(x.crankDeg * M_PI / 180, kPsi0, test::rssrRod());
    const Vec3 c = kH + kW * (std::cos(r.psi) * kX + std::sin(r.psi) * kY);
    const Vec3 c1 = kW * r.d1 * (-std::sin(r.psi) * kX + std::cos(r.psi) * kY);
    EXPECT_NEAR(c.norm(), x.value, 1e-9);
    EXPECT_NEAR(c.dot(c1) / c.norm(), 0, 1e-7) << x.crankDeg;
  }
  // Between samples, at a cursor: exact.
  Kinematics at = s.kinematics;
  ASSERT_TRUE(at.moveTo(137.25).ok());
  const test::Rocker r = test::rockerNear(137.25 * M_PI / 180, kPsi0, test::rssrRod());
  EXPECT_NEAR(valueAt(at, q, Order::Position),
              (kH + kW * (std::cos(r.psi) * kX + std::sin(r.psi) * kY)).norm(), 1e-10);
}

TEST_F(SpatialCurvesOfTheRssr, AComponentAlongADirectionOutOfThePlaneIsOfTheWorld) {
  const Vec3 u = Vec3(0.3, -0.5, 0.8).normalized();
  const Quantity q = Quantity::ofPoint(C, Quantity::Component::Along, Vec3(0.3, -0.5, 0.8));
  EXPECT_TRUE(q.inWorld());
  expectCurve(q, [&](const Motion3& t) {
    return std::array<double, 3>{u.dot(t.p), u.dot(t.d1), u.dot(t.d2)};
  });
}

TEST(SpatialCurves, PointsThatMeetHaveADistanceButNoRate) {
  const Mechanism m = test::example("four-bar-crank-rocker");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const Joint* pin = nullptr;  // a pin between two moving bodies: its points always meet
  for (const Joint& j : m.joints)
    if (j.type == JointType::Pin && m.point(j.a)->body != m.ground()->id &&
        m.point(j.b)->body != m.ground()->id)
      pin = &j;
  ASSERT_NE(pin, nullptr);
  SampleSpec spec;
  spec.points = {pin->a, pin->b};
  spec.steps = 36;
  const MotionSamples s = sampleMotion(k, spec);
  const Quantity q = Quantity::distance(pin->a, pin->b);
  const Curve d = curveOf(s, q, Order::Position);
  ASSERT_TRUE(d.status.ok());
  EXPECT_LT(*std::max_element(d.values.begin(), d.values.end()), 1e-9);
  const Curve v = curveOf(s, q, Order::Velocity);
  EXPECT_FALSE(v.status.ok());
  EXPECT_NE(v.status.message.find("meet"), std::string::npos) << v.status.message;
  EXPECT_TRUE(v.values.empty());
}

}  // namespace
}  // namespace linkage
