// Instant centres of a machine in space: Kennedy within each plane class (bodies of parallel
// planes together, the ground in every class), none between bodies of planes that are not
// parallel. The mechanism: an RSSR crank-rocker (crank in the drawing plane, rocker about an
// axis along x in a plane inclined 23 degrees, a ball rod between) whose rocker drives a
// four-bar in its own plane, the output lever in a parallel plane 5 mm deeper whose axes are
// turned 30 degrees (so that the class frame's mapping is exercised). Each centre is checked
// against its definition, independently of how it was found: the two bodies' velocities in the
// world (from the points' motion) agree at it.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/instant_centres.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::num;
using test::vec;
using test::vec2;
using test::rssr::kH;
using test::rssr::kX;
using test::rssr::kY;
constexpr double kTurn = 30 * M_PI / 180;
const Vec3 kN = kX.cross(kY);
const Vec2 kD(0, 15), kF(35, 0);
constexpr double kCoupler = 30, kLever = 20;

// E, where the coupler from D and the lever from F meet (the upper branch), in the rocker plane.
Vec2 jointE() {
  const Vec2 d = kF - kD;
  const double l = d.norm(), a = (kCoupler * kCoupler - kLever * kLever + l * l) / (2 * l);
  const double h = std::sqrt(kCoupler * kCoupler - a * a);
  return kD + a * d / l + h * Vec2(-d.y(), d.x()) / l;
}

std::string machineText() {
  const Vec3 x2 = std::cos(kTurn) * kX + std::sin(kTurn) * kY;
  const Vec3 y2 = -std::sin(kTurn) * kX + std::cos(kTurn) * kY;
  const Rot back = Rot::of(-kTurn);  // rocker-plane coordinates to the lever's plane's
  const Vec2 e = jointE();
  return R"({"format": "linkage", "version": 1, "name": "RSSR and a four-bar",
  "planes": {"rocker": {"origin": )" +
         vec(kH) + R"(, "x_axis": )" + vec(kX) + R"(, "y_axis": )" + vec(kY) + R"(},
             "lever": {"origin": )" +
         vec(Vec3(kH + 5 * kN)) + R"(, "x_axis": )" + vec(x2) + R"(, "y_axis": )" + vec(y2) + R"(}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0], "H": )" +
         vec(kH) + R"(, "F": )" + vec(Vec3(kH + kF.x() * kX + kF.y() * kY + 5 * kN)) + R"(}},
    {"name": "crank", "points": {"O": [0, 0], "A": [6.49519052838329, 3.75, 5]}},
    {"name": "rocker", "plane": "rocker", "points": {"H": [0, 0],
       "C": [-26.781239692398387, 9.747574084781563], "D": )" +
         vec2(kD) + R"(}},
    {"name": "coupler", "plane": "rocker", "points": {"D": )" +
         vec2(kD) + R"(, "E": )" + vec2(e) + R"(}},
    {"name": "lever", "plane": "lever", "points": {"F": )" +
         vec2(Vec2(back * kF)) + R"(, "E": )" + vec2(Vec2(back * e)) + R"(}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "ground.H", "b": "rocker.H"},
    {"type": "ball-rod", "a": "crank.A", "b": "rocker.C"},
    {"type": "pin", "a": "rocker.D", "b": "coupler.D"},
    {"type": "pin", "a": "coupler.E", "b": "lever.E"},
    {"type": "pin", "a": "ground.F", "b": "lever.F"}
  ],
  "driver": {"joint": 0, "rpm": 90, "direction": "ccw"}
})";
}

// A body's velocity field in the world, from two of its points' motion: v(X) = v_P + omega n x
// (X - P), omega about its plane's normal n.
struct Field {
  Vec3 at = Vec3::Zero(), v = Vec3::Zero(), n = Vec3::UnitZ();
  double omega = 0;
  Vec3 operator()(const Vec3& x) const { return v + omega * n.cross(x - at); }
};
Field fieldOf(const Kinematics& k, const Mechanism& m, const std::string& body) {
  const Body* b = m.bodyNamed(body);
  if (b->ground) return {};
  std::vector<PointId> pts;
  for (const Point& p : m.points)
    if (p.body == b->id) pts.push_back(p.id);
  const Kinematics::PointMotion3 p = k.motionInSpace(pts[0]), q = k.motionInSpace(pts[1]);
  const Vec3 n = planeOf(m, b->id).normal(), d = q.position - p.position;
  return {p.position, p.velocity, n, (q.velocity - p.velocity).dot(n.cross(d)) / d.squaredNorm()};
}

TEST(SpatialCentres, KennedyWithinEachPlaneClassNoneAcrossThem) {
  LoadResult r = parseMechanism(machineText());
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const std::vector<std::string> names{"ground", "crank", "rocker", "coupler", "lever"};
  for (double deg : {0.0, 37.0, 145.0, 250.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const InstantCentres ics = computeInstantCentres(k);
    ASSERT_TRUE(ics.status.ok()) << ics.status.message;
    ASSERT_EQ(ics.classes.frames.size(), 2u);
    EXPECT_TRUE(ics.disagreements.empty()) << deg;
    double fastest = 0;
    for (const std::string& b : names)
      fastest = std::max(fastest, std::abs(fieldOf(k, m, b).omega));
    for (const InstantCentre& c : ics.centres) {
      const std::string a = m.body(c.bodyI)->name, b = m.body(c.bodyJ)->name;
      const bool crankSide = a == "crank" || b == "crank";
      const bool across = crankSide && !(a == "ground" || b == "ground");
      EXPECT_EQ(c.across, across) << a << "-" << b;
      if (across) {
        EXPECT_FALSE(c.determined) << a << "-" << b;
        continue;
      }
      ASSERT_TRUE(c.determined && !c.atInfinity()) << a << "-" << b << " at " << deg;
      EXPECT_EQ(c.planeClass, crankSide ? 0 : 1) << a << "-" << b;
      EXPECT_NE(c.status, CentreStatus::Velocity) << a << "-" << b << " at " << deg;
      const Plane& f = ics.classes.frames[c.planeClass];
      const Vec3 x = f.world(c.point(), 0);
      const Vec3 rel = fieldOf(k, m, b)(x) - fieldOf(k, m, a)(x);
      EXPECT_LT(rel.norm(), 1e-9 * fastest * 100) << a << "-" << b << " at " << deg;
    }
    // The lever's centre with the rocker is a secondary one, through the coupler and ground.
    const InstantCentre* rl =
        ics.find(ics.numberOf(m.bodyNamed("rocker")->id), ics.numberOf(m.bodyNamed("lever")->id));
    ASSERT_NE(rl, nullptr);
    EXPECT_EQ(rl->status, CentreStatus::Kennedy);
  }
}

}  // namespace
}  // namespace linkage
