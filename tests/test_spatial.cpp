// Spatial machines (linkage/space.h): planes in the file, the ball rod, and the RSSR
// crank-rocker (a crank in the drawing plane, a rocker about an axis perpendicular to the crank
// shaft and inclined 23 degrees, joined by a ball rod) against its closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/space.h"
#include "linkage/tables/motion_table.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using namespace test::rssr;
using test::num;
using test::Rocker;
using test::rssrText;
using test::vec;

Mechanism rssr() {
  LoadResult r = parseMechanism(test::rssrText());
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism();
}

Rocker closedForm(double phi, double near, double l) {
  return test::rockerNear(phi, near, l);
}

TEST(Spatial, TheRssrRockerFollowsItsClosedFormWithExactRates) {
  const Mechanism m = rssr();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const BodyId rocker = m.bodyNamed("rocker")->id;
  const Vec3 A0(kR * std::cos(kPhi0), kR * std::sin(kPhi0), kDepth);
  const Vec3 C0 = kH + kW * (std::cos(kPsi0) * kX + std::sin(kPsi0) * kY);
  const double l = (A0 - C0).norm();
  double psi = kPsi0, peak1 = 0, peak2 = 0;
  std::vector<Rocker> expected;
  for (int deg = 0; deg <= 360; ++deg) {
    expected.push_back(closedForm(deg * M_PI / 180, psi, l));
    psi = expected.back().psi;
    peak1 = std::max(peak1, std::abs(expected.back().d1));
    peak2 = std::max(peak2, std::abs(expected.back().d2));
  }
  EXPECT_GT(peak1, 0.05);  // the rocker swings
  const double w = k.omega();
  for (int deg = 0; deg <= 360; ++deg) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const Rocker& e = expected[deg];
    EXPECT_NEAR(k.bodyAngle(rocker), e.psi - kPsi0, 1e-10) << deg;
    EXPECT_NEAR(k.bodyOmega(rocker), e.d1 * w, 1e-9 * peak1 * w) << deg;
    EXPECT_NEAR(k.bodyAlpha(rocker), e.d2 * w * w, 1e-9 * peak2 * w * w) << deg;
  }
}

TEST(Spatial, TheMotionTableGivesTheWorldsNineColumnsAPoint) {
  const Mechanism m = rssr();
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId c = *m.findPoint("rocker.C");
  EXPECT_EQ(motionTableHeader(m, {c}),
            "t_s,crank_deg,rocker.C.x_mm,rocker.C.y_mm,rocker.C.z_mm,rocker.C.vx_mm_s,"
            "rocker.C.vy_mm_s,rocker.C.vz_mm_s,rocker.C.ax_mm_s2,rocker.C.ay_mm_s2,"
            "rocker.C.az_mm_s2");
  const Vec3 A0(kR * std::cos(kPhi0), kR * std::sin(kPhi0), kDepth);
  const double l = (A0 - (kH + kW * (std::cos(kPsi0) * kX + std::sin(kPsi0) * kY))).norm();
  double psi = kPsi0;
  const double w = k.omega();
  for (int deg = 0; deg <= 90; ++deg) {
    const Rocker e = closedForm(deg * M_PI / 180, psi, l);
    psi = e.psi;
    ASSERT_TRUE(k.moveTo(deg).ok());
    const Vec3 u = std::cos(psi) * kX + std::sin(psi) * kY,
               t = -std::sin(psi) * kX + std::cos(psi) * kY;
    const Vec3 at = kH + kW * u, v = kW * e.d1 * w * t;
    const Vec3 acc = kW * (e.d2 * w * w * t - e.d1 * e.d1 * w * w * u);
    const Kinematics::PointMotion3 got = k.motionInSpace(c);
    EXPECT_LT((got.position - at).norm(), 1e-10 * kH.norm()) << deg;
    EXPECT_LT((got.velocity - v).norm(), 1e-9 * kW * w) << deg;
    EXPECT_LT((got.acceleration - acc).norm(), 1e-9 * kW * w * w) << deg;
    // The row as the table writes it: the same nine numbers.
    const std::string row = motionTableRow(k, deg, {c});
    EXPECT_EQ(std::count(row.begin(), row.end(), ','), 10) << row;
  }
}

TEST(Spatial, PlanesAndThirdNumbersComeBackAsWritten) {
  const Mechanism m = rssr();
  ASSERT_TRUE(m.planes && m.planes->size() == 1);
  EXPECT_TRUE(isSpatial(m));
  const std::string text = serializeMechanism(m);
  LoadResult again = parseMechanism(text);
  ASSERT_TRUE(again.mechanism) << again.error;
  EXPECT_EQ(mechanismDifference(m, *again.mechanism), "");
  EXPECT_EQ(serializeMechanism(*again.mechanism), text);
  EXPECT_NE(text.find("\"plane\": \"rocker\""), std::string::npos);
  EXPECT_EQ((*again.mechanism->planes)[0].yAxis, kY);
  const Mechanism& n = *again.mechanism;
  EXPECT_EQ(worldOf(n, *n.point(*n.findPoint("crank.A"))),
            Vec3(kR * std::cos(kPhi0), kR * std::sin(kPhi0), kDepth));
}

std::string refused(const std::string& from, const std::string& to) {
  std::string text = rssrText();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  LoadResult r = parseMechanism(text);
  return r.mechanism ? std::string("(read)") : r.error;
}

TEST(Spatial, BadPlanesAndJointsAreRefusedNamingThePlace) {
  // A pin between bodies of planes that are not parallel.
  EXPECT_EQ(refused(R"({"type": "ball-rod", "a": "crank.A", "b": "rocker.C"})",
                    R"({"type": "pin", "a": "crank.A", "b": "rocker.C"})")
                .substr(0, 63),
            "joints[2].b: a pin joins bodies of parallel planes only: \"crank");
  // Axes that are not unit, not perpendicular; the drawing redefined; an unknown plane.
  EXPECT_EQ(refused(R"("x_axis": )" + vec(kX), R"("x_axis": [0, 1, 0.5])"),
            "planes.rocker.x_axis: not a unit vector (to 1e-9)");
  EXPECT_EQ(refused(R"("x_axis": )" + vec(kX), R"("x_axis": [0, 0, 1])"),
            "planes.rocker.y_axis: not perpendicular to x_axis (to 1e-9)");
  EXPECT_EQ(refused(R"({"rocker": {)", R"({"drawing": {)").substr(0, 31),
            "planes.drawing: the drawing pla");
  EXPECT_EQ(refused(R"("plane": "rocker")", R"("plane": "rocket")"),
            "bodies[2].plane: no plane \"rocket\"");
  // A ball rod with both ends on one body, or of no length.
  EXPECT_EQ(refused(R"("b": "rocker.C"})", R"("b": "crank.O"})"),
            "joints[2]: both sides are on body \"crank\"");
  const Vec3 A(kR * std::cos(kPhi0), kR * std::sin(kPhi0), kDepth), d = A - kH;
  const std::string onA = "[" + num(d.dot(kX)) + ", " + num(d.dot(kY)) + ", " +
                          num(d.dot(kX.cross(kY))) + "], \"D\": [";
  EXPECT_EQ(refused(R"("C": [)", R"("C": )" + onA),
            "joints[2].b: the ends are closer than 1e-9 mm: a rod of no length keeps nothing");
}

TEST(Spatial, WhatIsNotComputedInSpaceYetSaysSoInsteadOfNumbers) {
  const Mechanism m = rssr();
  // A file that names planes but puts nothing in them is planar for every analysis.
  Mechanism flat = m;
  flat.planes.emplace();
  EXPECT_EQ(notInSpaceYet(flat, "x"),
            "x of a machine in space (body \"rocker\" moves in plane "
            "\"rocker\") are not computed yet: the motion table and "
            "the kinematics are");
  for (Body& b : flat.bodies) b.plane.clear();
  for (Point& p : flat.points) p.third.reset();
  EXPECT_EQ(notInSpaceYet(flat, "x"), "");
}

TEST(Spatial, ABallRodIsAKindOfTheTableAndNothingElse) {
  const ElementKind* k = elementKindNamed("ball-rod");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(&elementKind(k->type), k);
  EXPECT_TRUE(k->anyPlanes);
  EXPECT_EQ(k->equations, 1);
}

// A bevel pair about the ground: the RSSR's rocker geared to a wheel in the drawing plane (the
// planes' normals x and z: at right angles). theta_wheel = ratio theta_rocker, each about its own
// plane's normal, so the wheel's angle and rates are the rocker's closed form times the ratio:
// its acceleration is not zero, as it would be behind a crank turning at constant speed.
constexpr double kRatio = -1.5;
const Vec2 kWheel(50, 0);

std::string bevelText(const std::string& gearExtra = "") {
  std::string text = rssrText();
  text.replace(text.find(R"(  ],
  "joints")"),
               3, R"(,
    {"name": "wheel", "points": {"W": [50, 0], "P": [60, 0]}}
  ])");
  text.replace(text.find(R"(  ],
  "driver")"),
               3,
               R"(,
    {"type": "pin", "a": "ground.W", "b": "wheel.W"},
    {"type": "gear", "a": "rocker.H", "b": "wheel.W", "ratio": -1.5)" +
                   gearExtra + R"(}
  ])");
  text.replace(text.find(R"("H": [0, 0, 80]})"), 16, R"("H": [0, 0, 80], "W": [50, 0]})");
  return text;
}

TEST(Spatial, ABevelPairTurnsTheWheelRatioTimesTheRockerWithExactRates) {
  LoadResult r = parseMechanism(bevelText());
  ASSERT_TRUE(r.mechanism) << r.error;
  const Mechanism& m = *r.mechanism;
  EXPECT_FALSE(
      parallel(planeOf(m, m.bodyNamed("rocker")->id), planeOf(m, m.bodyNamed("wheel")->id)));
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const BodyId wheel = m.bodyNamed("wheel")->id;
  const PointId P = *m.findPoint("wheel.P");
  const Vec3 A0(kR * std::cos(kPhi0), kR * std::sin(kPhi0), kDepth);
  const double l = (A0 - (kH + kW * (std::cos(kPsi0) * kX + std::sin(kPsi0) * kY))).norm();
  double psi = kPsi0, peak1 = 0, peak2 = 0;
  std::vector<Rocker> e;
  for (int deg = 0; deg <= 720; ++deg) {
    e.push_back(closedForm(deg * M_PI / 180, psi, l));
    psi = e.back().psi;
    peak1 = std::max(peak1, std::abs(kRatio * e.back().d1));
    peak2 = std::max(peak2, std::abs(kRatio * e.back().d2));
  }
  const double w = k.omega();
  for (int deg = 0; deg <= 720; deg += 2) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const double th = kRatio * (e[deg].psi - kPsi0);
    EXPECT_NEAR(k.bodyAngle(wheel), th, 1e-10) << deg;
    EXPECT_NEAR(k.bodyOmega(wheel), kRatio * e[deg].d1 * w, 1e-9 * peak1 * w) << deg;
    EXPECT_NEAR(k.bodyAlpha(wheel), kRatio * e[deg].d2 * w * w, 1e-9 * peak2 * w * w) << deg;
    // The wheel's point, 10 from its axis, in the world: position and rates from th alone.
    const Vec3 u(std::cos(th), std::sin(th), 0), t(-std::sin(th), std::cos(th), 0);
    const double th1 = kRatio * e[deg].d1 * w, th2 = kRatio * e[deg].d2 * w * w;
    const Kinematics::PointMotion3 got = k.motionInSpace(P);
    EXPECT_LT((got.position - (Vec3(kWheel.x(), kWheel.y(), 0) + 10 * u)).norm(), 1e-9) << deg;
    EXPECT_LT((got.velocity - 10 * th1 * t).norm(), 1e-9 * 10 * peak1 * w) << deg;
    EXPECT_LT((got.acceleration - 10 * (th2 * t - th1 * th1 * u)).norm(),
              1e-9 * 10 * (peak2 + peak1 * peak1) * w * w)
        << deg;
  }
}

TEST(Spatial, ABevelPairOnAMovingCarrierOrOffItsPivotIsRefusedNamingTheJoint) {
  LoadResult r = parseMechanism(bevelText(R"(, "carrier": "crank")"));
  EXPECT_FALSE(r.mechanism);
  EXPECT_EQ(r.error,
            "joints[4].carrier: a bevel pair (bodies of planes that are not parallel) turns about "
            "the ground only, and a carrier joins bodies of its own plane");
  // Its centres are where its bodies are pinned to the ground.
  std::string text = bevelText();
  text.replace(text.find(R"("a": "rocker.H", "b": "wheel.W")"), 31,
               R"("a": "rocker.C", "b": "wheel.W")");
  r = parseMechanism(text);
  EXPECT_FALSE(r.mechanism);
  EXPECT_EQ(r.error,
            "joints[4].a: \"rocker.C\" is not where body \"rocker\" is pinned to the carrier "
            "\"ground\": a gear's centres are its bodies' pivots on the carrier");
}

// What issue 27 lists and the test above does not: a slider or a pin in a slot across planes,
// a pin between planes whose normals are opposite, axes off by more than 1e-9 (and by less: read),
// a ball rod with both ends on the ground.
TEST(Spatial, MoreBadPlanesAndJointsAreRefusedNamingThePlace) {
  const std::string rod = R"({"type": "ball-rod", "a": "crank.A", "b": "rocker.C"})";
  const std::string slot = R"("points": {"O": [0, 0], "A": [)";
  auto withSlot = [&](const std::string& joint) {
    std::string text = rssrText();
    text.replace(text.find(slot), slot.size(), R"("slots": {"s": [[0, 0], [5, 0]]}, )" + slot);
    text.replace(text.find(rod), rod.size(), joint);
    const LoadResult r = parseMechanism(text);
    return r.mechanism ? std::string("(read)") : r.error;
  };
  EXPECT_EQ(withSlot(R"({"type": "slider", "a": "rocker.C", "slot": "crank.s"})"),
            "joints[2].slot: a slider joins bodies of parallel planes only: \"rocker\" moves in "
            "plane \"rocker\", \"crank\" in \"drawing\" (a ball rod joins any planes)");
  EXPECT_EQ(withSlot(R"({"type": "pin-in-slot", "a": "rocker.C", "slot": "crank.s"})"),
            "joints[2].slot: a pin-in-slot joins bodies of parallel planes only: \"rocker\" "
            "moves in plane \"rocker\", \"crank\" in \"drawing\" (a ball rod joins any planes)");
  // The rocker's plane turned to face the other way from the drawing's: normal -z.
  std::string text = rssrText();
  text.replace(text.find(rod), rod.size(), R"({"type": "pin", "a": "crank.A", "b": "rocker.C"})");
  for (const auto& [from, to] : {std::pair{R"("x_axis": )" + vec(kX), R"("x_axis": [1, 0, 0])"},
                                 std::pair{R"("y_axis": )" + vec(kY), R"("y_axis": [0, -1, 0])"}})
    text.replace(text.find(from), from.size(), to);
  LoadResult r = parseMechanism(text);
  EXPECT_FALSE(r.mechanism);
  EXPECT_EQ(r.error,
            "joints[2].b: a pin joins bodies of parallel planes only: \"crank\" moves in plane "
            "\"drawing\", \"rocker\" in \"rocker\" (a ball rod joins any planes)");
  // The axes to 1e-9: y not unit, y not perpendicular to x; off by 1e-11, read.
  EXPECT_EQ(refused(R"("y_axis": )" + vec(kY), R"("y_axis": )" + vec(kY * (1 + 2e-9))),
            "planes.rocker.y_axis: not a unit vector (to 1e-9)");
  EXPECT_EQ(refused(R"("y_axis": )" + vec(kY), R"("y_axis": )" + vec(kY + 2e-9 * kX)),
            "planes.rocker.y_axis: not perpendicular to x_axis (to 1e-9)");
  EXPECT_EQ(refused(R"("y_axis": )" + vec(kY), R"("y_axis": )" + vec(kY * (1 + 1e-11))), "(read)");
  EXPECT_EQ(refused(R"("y_axis": )" + vec(kY), R"("y_axis": )" + vec(kY + 1e-11 * kX)), "(read)");
  EXPECT_EQ(refused(rod, R"({"type": "ball-rod", "a": "ground.O", "b": "ground.H"})"),
            "joints[2]: both sides are on body \"ground\"");
}

// A block in a plane across the drawing's, in a slot of the ground: the slot must lie in a
// direction of the block's plane. Ends written [x, y] are in the drawing plane (z = 0); they were
// not checked, so a slot across the block's plane was read, and the block solved on the slot's
// shadow. Here the block's plane is x = 0 (normal +x), the slot along y: read; turned a little
// towards x, with two numbers or three, refused; an arc slot whose middle leaves the plane too.
TEST(Spatial, AGroundSlotMustLieInItsBlocksPlaneWrittenInTwoNumbersOrThree) {
  auto file = [](const std::string& slot) {
    return R"({"format": "linkage", "version": 1, "name": "block across",
  "planes": {"side": {"origin": [0, 0, 0], "x_axis": [0, 0, -1], "y_axis": [0, 1, 0]}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": [0, 0]}, "slots": {"g": )" +
           slot + R"(}},
    {"name": "crank", "plane": "side", "points": {"O": [0, 0], "A": [0, 10]}},
    {"name": "rod", "plane": "side", "points": {"A": [0, 10], "B": [0, -30]}},
    {"name": "block", "plane": "side", "points": {"B": [0, -30]}}
  ],
  "joints": [
    {"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "rod.A"},
    {"type": "pin", "a": "rod.B", "b": "block.B"},
    {"type": "slider", "a": "block.B", "slot": "ground.g"}
  ],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}
})";
  };
  auto error = [&](const std::string& slot) {
    const LoadResult r = parseMechanism(file(slot));
    return r.mechanism ? std::string("(read)") : r.error;
  };
  const std::string why =
      "joints[3].slot: the ground's slot ground.g is not parallel to plane \"side\" of its "
      "block (to 1e-9)";
  EXPECT_EQ(error("[[0, -20], [0, -50]]"), "(read)");
  EXPECT_EQ(error("[[0, -20, 5], [0, -50, 5]]"), "(read)");
  EXPECT_EQ(error("[[0, -20], [1, -50]]"), why);
  EXPECT_EQ(error("[[0, -20, 0], [1, -50, 0]]"), why);
  EXPECT_EQ(error("[[0, -20, 0], [0, -50, 1e-6]]"), "(read)");  // along z: in the plane
  EXPECT_EQ(error("[[0, -20], [1, -35], [0, -50]]"), why);      // an arc leaving it midway
  // An arc in it: its x, y alone are three points on a line (tests/test_spatial_arc_slots.cpp).
  EXPECT_EQ(error("[[0, -20, 0], [0, -35, 5], [0, -50, 0]]"), "(read)");
}

}  // namespace
}  // namespace linkage
