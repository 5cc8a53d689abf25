// Forces through a cam (issue 28 with issue 17's dynamics): the cam pushes its follower along the
// common normal at the contact, so its reaction is that of its contact row, not of its
// kinematic row (elements/cam_row.h). Against hand derivations:
//   translating roller and knife edge, with and without offset: N cos(alpha) = m a + W along
//                       the slot, the slot's side thrust N sin(alpha), the cam's torque N times
//                       the normal's arm about a;
//   translating flat face, with and without offset: N = m a + W, acting (s' - e) to the side
//                       of b: the slot's couple;
//   oscillating roller, knife edge and flat face: N cross(I - P, n) = J alpha - M about the
//                       pivot, n through the instant centre I (a flat face's normal, turned);
// and by the power balance (the driver's power is the rate of the energy less the loads').
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "linkage/cam_joint.h"
#include "linkage/dynamics.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180, kMass = 0.2, kSpring = 30, kG = 9.81;

Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? std::move(*r.mechanism) : Mechanism{};
}

// The follower of 0.2 kg on its slot's line, pressed down by 30 N at b and by gravity.
test::TranslatingCam loadedTranslating(bool flat = false, double e = 10) {
  test::TranslatingCam t;
  t.flat = flat;
  t.e = e;
  t.followerMass = R"("mass": {"kg": 0.2, "com": [)" + test::num(t.e) + ", " +
                   test::num(t.by() + 20) + R"(], "j_kg_mm2": 30},)";
  t.extra = R"(, "gravity": [0, -9.81], "loads": [{"point": "follower.R", "force_N": [0, -30]}])";
  return t;
}

// Each scalar of a turn's samples against its hand value, to 1e-9 of the largest.
struct Compare {
  std::vector<std::pair<double, double>> pairs;
  void add(double got, double want) { pairs.emplace_back(got, want); }
  void expect(const char* what) const {
    double peak = 0;
    for (const auto& [got, want] : pairs) peak = std::max(peak, std::abs(want));
    ASSERT_GT(peak, 0) << what;
    for (size_t i = 0; i < pairs.size(); ++i)
      EXPECT_NEAR(pairs[i].first, pairs[i].second, 1e-9 * peak) << what << " sample " << i;
  }
};

// A translating roller or knife edge: the normal through b, d0 = sqrt((base + roller)^2 - e^2).
void expectTranslatingContact(const test::TranslatingCam& spec) {
  const Mechanism m = parsed(spec.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  const cam::Program program = camJoint(m, m.joints[2])->program;
  const double w = k.omega(), d0 = spec.by();
  Compare contact, side, along, camFx, camFy, camCouple, torque;
  for (double deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Forces& f = solver.compute(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const cam::Displacement s = program.at(deg * kDeg);
    // The common normal at b, w = (1, 0) to the right of the rise u = (0, 1):
    // n = ((e - s') w + (d0 + s) u) / |...|; cos(alpha) = n . u.
    const Vec2 n = Vec2(spec.e - s.v, d0 + s.s).normalized();
    const double N = (kMass * w * w * s.a / 1000 + kSpring + kMass * kG) / n.y();
    contact.add(f.joints[2].contactN, N);
    // The slot's force on the follower: the side thrust, nothing along the slot.
    side.add(f.joints[1].force.x(), -N * n.x());
    along.add(f.joints[1].force.y(), 0);
    // On the cam: -N n; its moment about a, and the driver's torque that balances it.
    const Vec2 b(spec.e, d0 + s.s);
    camFx.add(f.joints[2].force.x(), -N * n.x());
    camFy.add(f.joints[2].force.y(), -N * n.y());
    camCouple.add(f.joints[2].coupleNm, cross(b, -N * n) / 1000);
    torque.add(f.driverTorqueNm, cross(b, N * n) / 1000);
    EXPECT_GT(f.joints[2].contactN, 0) << deg;  // the spring keeps it in compression
  }
  contact.expect("contact force");
  side.expect("side thrust");
  camFx.expect("force on the cam, x");
  camFy.expect("force on the cam, y");
  camCouple.expect("its moment about the cam's centre");
  torque.expect("driver torque");
  for (const auto& [got, want] : along.pairs) EXPECT_NEAR(got, want, 1e-9 * kSpring);
}

TEST(CamForces, TranslatingRollerFollowersContactForceAndSideThrustAreTheHandDerivation) {
  expectTranslatingContact(loadedTranslating());
}

// The same hand derivation without offset, and for a knife edge (a roller of no radius) with
// and without it.
TEST(CamForces, CentralAndKnifeEdgeFollowersContactForceIsTheHandDerivation) {
  for (double e : {10.0, 0.0})
    for (double roller : {8.0, 0.0}) {
      if (e == 10 && roller == 8) continue;  // the test above
      test::TranslatingCam spec = loadedTranslating(false, e);
      spec.roller = roller;
      SCOPED_TRACE("e " + test::num(e) + ", roller " + test::num(roller));
      expectTranslatingContact(spec);
    }
}

// A flat face takes the force along the slot at the contact, s' - e to the side of b: the slot
// holds its moment about b.
void expectFlatContact(const test::TranslatingCam& spec) {
  const Mechanism m = parsed(spec.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  const cam::Program program = camJoint(m, m.joints[2])->program;
  const double w = k.omega();
  Compare contact, side, couple;
  for (double deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Forces& f = solver.compute(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const cam::Displacement s = program.at(deg * kDeg);
    const double N = kMass * w * w * s.a / 1000 + kSpring + kMass * kG;
    contact.add(f.joints[2].contactN, N);
    side.add(f.joints[1].force.x(), 0);
    couple.add(f.joints[1].coupleNm, -N * (s.v - spec.e) / 1000);
  }
  contact.expect("contact force");
  couple.expect("the slot's couple");
  for (const auto& [got, want] : side.pairs) EXPECT_NEAR(got, want, 1e-9 * kSpring);
}

TEST(CamForces, AFlatFacesContactMovesAcrossTheFaceAndTheSlotTakesItsMoment) {
  expectFlatContact(loadedTranslating(true, 6));
  SCOPED_TRACE("no offset");
  expectFlatContact(loadedTranslating(true, 0));
}

// The rocker (its mass centre on its pivot P, J 50 kg mm^2, a spring torque of 1.5 N m
// counter-clockwise: its rise turns it clockwise) turns as J alpha = N cross(C - P, n) + M, C on
// the common normal n. The normal passes through the instant centre of the cam and the rocker,
// on the line a P where their velocities agree: I = k P / (k - 1), k = sign s' the rocker's
// turn per the cam's (a at the origin). A roller's or a knife edge's normal runs from I through
// b; a flat face's is the face's normal, b0 / |b0| turned with the rocker (sign s).
void expectOscillatingContact(const test::OscillatingCam& spec) {
  const std::string mass = R"("name": "rocker", "mass": {"kg": 0.1, "com": [60, 0], )"
                           R"("j_kg_mm2": 50},)";
  std::string text = spec.text();
  text.replace(text.find(R"("name": "rocker",)"), 17, mass);
  text.insert(text.rfind('}'), R"(, "loads": [{"body": "rocker", "torque_Nm": 1.5}])");
  const Mechanism m = parsed(text);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  const std::optional<CamJoint> c = camJoint(m, m.joints[2]);
  const BodyId rocker = m.bodyNamed("rocker")->id;
  const PointId R = *m.findPoint("rocker.R");
  const Vec2 P(60, 0), nu0 = k.position(R).normalized();  // the drawing
  Compare contact;
  for (double deg = 0; deg < 360; deg += 5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Forces& f = solver.compute(k);
    ASSERT_TRUE(f.status.ok()) << f.status.message;
    const cam::Displacement s = c->program.at(deg * kDeg);
    const double kk = c->kind.sign * s.v;
    const Vec2 b = k.position(R), I = kk * P / (kk - 1);
    const Vec2 n = spec.flat ? Vec2(Rot::of(c->kind.sign * s.s) * nu0) : (b - I).normalized();
    const double N = (1e-3 * 50 * k.bodyAlpha(rocker) - 1500) / cross(I - P, n);
    contact.add(f.joints[2].contactN, N);
    EXPECT_GT(f.joints[2].contactN, 0) << deg;
  }
  contact.expect("contact force");
}

TEST(CamForces, OscillatingRollerFollowersContactForceTurnsItsRocker) {
  expectOscillatingContact(test::OscillatingCam{});
}

TEST(CamForces, OscillatingKnifeEdgeAndFlatFacesContactForceTurnsItsRocker) {
  test::OscillatingCam knife, flat;
  knife.roller = 0;
  flat.flat = true;
  SCOPED_TRACE("knife edge");
  expectOscillatingContact(knife);
  SCOPED_TRACE("flat face");
  expectOscillatingContact(flat);
}

// The driver's power is the rate of the kinetic and potential energy less the loads' power, to
// 1e-12 of its peak, for every kind of follower.
TEST(CamForces, PowerBalances) {
  test::TranslatingCam flat = loadedTranslating(true, 0);
  flat.followerMass = R"("mass": {"kg": 0.2, "com": [3, 45], "j_kg_mm2": 30},)";
  test::OscillatingCam rocker;
  rocker.flat = true;
  rocker.extra = R"(, "gravity": [0, -9.81])";
  std::string oscillating = rocker.text();
  oscillating.replace(oscillating.find(R"("name": "rocker",)"), 17,
                      R"("name": "rocker", "mass": {"kg": 0.1, "com": [40, 20], )"
                      R"("j_kg_mm2": 50},)");
  for (const std::string& text : {loadedTranslating().text(), flat.text(), oscillating}) {
    const Mechanism m = parsed(text);
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    ForceSolver solver;
    ASSERT_TRUE(solver.prepare(k).ok());
    std::vector<double> input, balance;
    for (double deg = 0; deg < 360; deg += 3) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const Forces& f = solver.compute(k);
      ASSERT_TRUE(f.status.ok()) << f.status.message;
      double rate = 0, loads = 0;
      for (const Body& b : m.bodies) {
        if (b.ground || !b.mass) continue;
        const Kinematics::PointMotion c = k.motionOf(b.id, b.mass->com);
        const double w = k.bodyOmega(b.id), al = k.bodyAlpha(b.id);
        rate += 1e-6 * (b.mass->kg * c.velocity.dot(c.acceleration) + b.mass->jKgMm2 * w * al);
        rate -= 1e-3 * b.mass->kg * m.gravity.value_or(Vec2::Zero()).dot(c.velocity);
      }
      for (const Load& l : m.loads) loads += 1e-3 * l.forceN.dot(k.velocity(l.point));
      input.push_back(f.driverTorqueNm * k.omega());
      balance.push_back(rate - loads);
    }
    double peak = 0;
    for (double x : input) peak = std::max(peak, std::abs(x));
    ASSERT_GT(peak, 0) << m.name;
    for (size_t i = 0; i < input.size(); ++i)
      EXPECT_NEAR(input[i], balance[i], 1e-12 * peak) << m.name << " at " << 3 * i << " deg";
  }
}

}  // namespace
}  // namespace linkage
