// Slots of the ground written in the world on a machine in space (docs/spatial.md): a slot along z
// and an arc in a plane square to the drawing, whose x, y alone are a point and a line. A
// slider-crank along z against its closed form; a pin in a ground arc against the four-bar whose
// rocker, pivoted at the arc's centre with the arc's radius, stands for the arc (the same motion
// from other rows: pins and a rocker's body instead of the arc's OnCircle row).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "changed_design.h"
#include "clearance_checks.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission_sensitivity.h"
#include "spatial_fixtures.h"

namespace linkage {
namespace {

using test::num;
using test::vec;
using test::vec2;

// A vertical plane (normal along -x), its axes turned in it: x, y of anything in it are one line.
const Vec3 kOrigin(6, 2, -3), kX(0, 0.6, 0.8), kY(0, 0.8, -0.6);
Vec3 world(const Vec2& p) {
  return kOrigin + p.x() * kX + p.y() * kY;
}

std::string planes() {
  return R"("planes": {"side": {"origin": )" + vec(kOrigin) + R"(, "x_axis": )" + vec(kX) +
         R"(, "y_axis": )" + vec(kY) + "}},\n";
}

std::string header() {
  return R"({"format": "linkage", "version": 1, "name": "arc slots in space", )" + planes();
}

Mechanism load(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error << "\n" << text;
  return r.mechanism ? *r.mechanism : Mechanism();
}

std::string loadError(const std::string& text) {
  LoadResult r = parseMechanism(text);
  return r.mechanism ? std::string("(loaded)") : r.error;
}

// Crank r about O, rod l to the block B that runs along the plane's x axis (the world's
// direction kX) in a ground slot written in the world, 9 mm off the plane along its normal.
constexpr double kR = 10, kL = 40;
std::string sliderCrank(const Vec3& slotEnd0, const Vec3& slotEnd1) {
  return header() + R"("bodies": [
    {"name": "ground", "ground": true, "points": {"O": )" +
         vec(world({0, 0})) + R"(}, "slots": {"s": [)" + vec(slotEnd0) + ", " + vec(slotEnd1) +
         R"(]}},
    {"name": "crank", "plane": "side", "points": {"O": [0, 0], "A": [10, 0]}},
    {"name": "rod", "plane": "side", "points": {"A": [10, 0], "B": [50, 0]}},
    {"name": "block", "plane": "side", "points": {"B": [50, 0]}}],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "rod.A"},
    {"type": "pin", "a": "rod.B", "b": "block.B"},
    {"type": "slider", "a": "block.B", "slot": "ground.s"}],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}})";
}

const Vec3 kNormal = kX.cross(kY);

TEST(SpatialArcSlots, ASliderCrankRunsInAGroundSlotAlongTheWorldsZ) {
  // The slot's ends differ in y and z only (x, y alone: two points on a vertical line; here the
  // plane is turned so that they differ in y too); along z alone they would be one point.
  const Vec3 e0 = world({20, 0}) + 9 * kNormal, e1 = world({70, 0}) + 9 * kNormal;
  const Mechanism m = load(sliderCrank(e0, e1));
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok()) << k.load(m).message;
  const PointId A = *m.findPoint("crank.A"), B = *m.findPoint("block.B");
  double worst = 0;
  for (int deg = 0; deg < 360; deg += 15) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const Kinematics::PointMotion3 a = k.motionInSpace(A), b = k.motionInSpace(B);
    // The crank's angle and rate as the solve placed it, in the plane.
    const Vec3 ra = a.position - kOrigin;
    const double c = ra.dot(kX) / kR, s = ra.dot(kY) / kR;
    const double w = (c * a.velocity.dot(kY) - s * a.velocity.dot(kX)) / kR;
    const double D = kL * kL - kR * kR * s * s;
    const double x = kR * c + std::sqrt(D);
    const double dx = -kR * s - kR * kR * s * c / std::sqrt(D);
    const double ddx = -kR * c - kR * kR * (c * c - s * s) / std::sqrt(D) -
                       std::pow(kR * kR * s * c, 2) / std::pow(D, 1.5);
    worst = std::max(worst, (b.position - world({x, 0})).norm() / kL);
    worst = std::max(worst, (b.velocity - dx * w * kX).norm() / (kR * w));
    worst = std::max(worst, (b.acceleration - ddx * w * w * kX).norm() / (kR * w * w));
  }
  EXPECT_LT(worst, 1e-11);
}

TEST(SpatialArcSlots, AGroundSlotWrittenInTheWorldIsRefusedOnlyWhereItIsNoCurve) {
  const Vec3 e = world({20, 0});
  EXPECT_NE(loadError(sliderCrank(e, e)).find("zero-length slot"), std::string::npos);
  // An arc whose three points are on one line in the world, though no two coincide.
  const std::string line =
      "[" + vec(world({0, 0})) + ", " + vec(world({1, 0})) + ", " + vec(world({3, 0})) + "]";
  const std::string text = header() + R"("bodies": [{"name": "ground", "ground": true,
    "points": {"O": [0, 0]}, "slots": {"arc": )" +
                           line + R"(}}], "joints": []})";
  EXPECT_NE(loadError(text).find("bodies[0].slots.arc: its three points lie on one line"),
            std::string::npos)
      << loadError(text);
}

// The four-bar O-A-B-C (crank 10, coupler 35, rocker 30, C 40 from O along the plane's x): the
// coupler's B in a ground arc of radius 30 about C (written in the world, shifted along the
// normal), or B on a rocker pinned at C.
constexpr double kRocker = 30, kCoupler = 35;
const Vec2 kA(10, 0), kC(40, 0);
// B where the coupler and the rocker meet, above the line AC.
Vec2 drawnB() {
  const double d = (kC - kA).norm(),
               along = (kCoupler * kCoupler - kRocker * kRocker + d * d) / (2 * d);
  return kA + along * Vec2::UnitX() +
         std::sqrt(kCoupler * kCoupler - along * along) * Vec2::UnitY();
}

std::string fourBar(bool arc) {
  auto onArc = [](double deg) -> Vec3 {
    const double a = deg * M_PI / 180;
    return world(kC + kRocker * Vec2(std::cos(a), std::sin(a))) - 4 * kNormal;
  };
  const std::string ground = arc ? R"("points": {"O": )" + vec(world({0, 0})) +
                                       R"(}, "slots": {"arc": [)" + vec(onArc(60)) + ", " +
                                       vec(onArc(110)) + ", " + vec(onArc(160)) + "]}"
                                 : R"("points": {"O": )" + vec(world({0, 0})) + R"(, "C": )" +
                                       vec(world(kC) + 7 * kNormal) + "}";
  const std::string B = vec2(drawnB());
  const std::string rocker =
      R"(,
    {"name": "rocker", "plane": "side", "points": {"C": )" +
      vec2(kC) + R"(, "B": )" + B + "}}";
  const std::string closing =
      arc ? R"({"type": "pin-in-slot", "a": "coupler.B", "slot": "ground.arc"})"
          : R"({"type": "pin", "a": "coupler.B", "b": "rocker.B"},
    {"type": "pin", "a": "ground.C", "b": "rocker.C"})";
  return header() + R"("bodies": [
    {"name": "ground", "ground": true, )" +
         ground + R"(},
    {"name": "crank", "plane": "side", "points": {"O": [0, 0], "A": [10, 0]}},
    {"name": "coupler", "plane": "side", "points": {"A": [10, 0], "B": )" +
         B + "}}" + (arc ? "" : rocker) + R"(],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "crank.A", "b": "coupler.A"},
    )" + closing +
         R"(],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}})";
}

TEST(SpatialArcSlots, APinInAGroundArcSquareToTheDrawingMovesAsTheRockerItStandsFor) {
  const Mechanism arc = load(fourBar(true)), rocker = load(fourBar(false));
  Kinematics ka, kr;
  ASSERT_TRUE(ka.load(arc).ok()) << ka.load(arc).message;
  ASSERT_TRUE(kr.load(rocker).ok()) << kr.load(rocker).message;
  const PointId a = *arc.findPoint("coupler.B"), r = *rocker.findPoint("coupler.B");
  double worst = 0;
  for (int deg = 0; deg < 360; deg += 10) {
    ASSERT_TRUE(ka.moveTo(deg).ok()) << deg;
    ASSERT_TRUE(kr.moveTo(deg).ok()) << deg;
    const Kinematics::PointMotion3 p = ka.motionInSpace(a), q = kr.motionInSpace(r);
    const double w = std::abs(ka.omega());
    worst = std::max(worst, (p.position - q.position).norm() / kRocker);
    worst = std::max(worst, (p.velocity - q.velocity).norm() / (kRocker * w));
    worst = std::max(worst, (p.acceleration - q.acceleration).norm() / (kRocker * w * w));
  }
  EXPECT_LT(worst, 1e-10);
}

// The ground arc's own dimensions: its centre in the world and its radius.
TEST(SpatialArcSlots, AGroundArcsDimensionsAreItsCentreInTheWorldAndItsRadius) {
  const Mechanism m = load(fourBar(true));
  std::map<std::string, double> value;
  for (const Dimension& d : dimensions(m)) value[d.name] = d.value;
  const Vec3 c = world(kC) - 4 * kNormal;
  EXPECT_NEAR(value.at("ground.arc.centre.x"), c.x(), 1e-12);
  EXPECT_NEAR(value.at("ground.arc.centre.y"), c.y(), 1e-12);
  EXPECT_NEAR(value.at("ground.arc.centre.z"), c.z(), 1e-12);
  EXPECT_NEAR(value.at("ground.arc.radius"), kRocker, 1e-12);
}

// The pin in the ground arc and the rocker standing for it, each solved and its sensitivities
// prepared in the world; standIn[d]: the rocker model's dimension for the arc model's d (the
// arc's centre: the rocker's pivot; its radius: the rocker's length; any other: its own name).
class ArcAndRocker : public ::testing::Test {
 protected:
  void SetUp() override {
    std::map<std::string, int> index;
    for (size_t d = 0; d < dr.size(); ++d) index[dr[d].name] = static_cast<int>(d);
    static const std::map<std::string, std::string> to{{"ground.arc.centre.x", "ground.C.x"},
                                                       {"ground.arc.centre.y", "ground.C.y"},
                                                       {"ground.arc.centre.z", "ground.C.z"},
                                                       {"ground.arc.radius", "rocker.C-B"}};
    for (const Dimension& d : da) {
      auto it = to.find(d.name);
      auto at = index.find(it == to.end() ? d.name : it->second);
      ASSERT_NE(at, index.end()) << d.name;
      standIn.push_back(at->second);
    }
    ASSERT_TRUE(ka.load(arc).ok() && kr.load(rocker).ok());
    ASSERT_TRUE(sa.prepare(ka, da, Sensitivity::Space::World).ok());
    ASSERT_TRUE(sr.prepare(kr, dr, Sensitivity::Space::World).ok());
  }
  // Both at crank angle deg, their sensitivities there.
  bool at(double deg) {
    return ka.moveTo(deg).ok() && kr.moveTo(deg).ok() && sa.at(ka).ok() && sr.at(kr).ok();
  }
  const Mechanism arc = load(fourBar(true)), rocker = load(fourBar(false));
  const std::vector<Dimension> da = dimensions(arc), dr = dimensions(rocker);
  std::vector<int> standIn;
  Kinematics ka, kr;
  Sensitivity sa, sr;
};

// Every dimension's derivative of the pin's world position, velocity and acceleration equals
// the rocker model's for the dimension standing for it, each relative to the largest over the
// turn.
TEST_F(ArcAndRocker, TheGroundArcsSensitivitiesAreTheRockers) {
  const PointId a = *arc.findPoint("coupler.B"), r = *rocker.findPoint("coupler.B");
  double worst = 0, peak = 0;
  int compared = 0;
  for (int deg = 0; deg < 360; deg += 20) {
    ASSERT_TRUE(at(deg)) << deg;
    const double w = std::abs(ka.omega());
    for (size_t d = 0; d < da.size(); ++d) {
      const int e = standIn[d], i = static_cast<int>(d);
      const Vec3 pa[3] = {sa.point3(ka, a, i), sa.velocity3(ka, a, i) / w,
                          sa.acceleration3(ka, a, i) / (w * w)};
      const Vec3 pr[3] = {sr.point3(kr, r, e), sr.velocity3(kr, r, e) / w,
                          sr.acceleration3(kr, r, e) / (w * w)};
      for (int q = 0; q < 3; ++q) {
        worst = std::max(worst, (pa[q] - pr[q]).norm());
        peak = std::max(peak, pr[q].norm());
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 18 * 10);
  EXPECT_GT(peak, 0.5);
  EXPECT_LT(worst, 1e-9 * peak);
}

// The transmission angle at the pin in the arc (between the coupler and the arc's radius) is
// the rocker model's at its pin, and so are its derivatives.
TEST_F(ArcAndRocker, TheTransmissionAngleAtTheArcIsTheRockersAndSoAreItsDerivatives) {
  const std::vector<TransmissionJoint> ja = transmissionJoints(arc),
                                       jr = transmissionJoints(rocker);
  ASSERT_EQ(ja.size(), 1u);
  ASSERT_EQ(jr.size(), 1u);
  EXPECT_EQ(ja[0].label, jr[0].label);
  double worst = 0, peak = 0;
  for (int deg = 0; deg < 360; deg += 20) {
    ASSERT_TRUE(at(deg)) << deg;
    const TransmissionReading ra = transmissionAngle(ka, ja[0]), rr = transmissionAngle(kr, jr[0]);
    EXPECT_NEAR(ra.deg, rr.deg, 1e-9) << deg;
    EXPECT_NEAR(ra.perDeg, rr.perDeg, 1e-9) << deg;
    const std::vector<double> ga = transmissionAngleDerivatives(ka, ja[0], sa),
                              gr = transmissionAngleDerivatives(kr, jr[0], sr);
    for (size_t d = 0; d < da.size(); ++d) {
      worst = std::max(worst, std::abs(ga[d] - gr[standIn[d]]));
      peak = std::max(peak, std::abs(gr[standIn[d]]));
    }
  }
  EXPECT_GT(peak, 0.5);
  EXPECT_LT(worst, 1e-9 * peak);
}

// A slotted crank in a plane parallel to the rocker's, 5 mm out along the normal, turned 40
// degrees in it and shifted: the crank O-X (8) carries an arc of radius 30 about X; the rocker
// C-B (25, C 35 from O) runs its pin B in it, a four-bar O-X-B-C.
const Vec3 kX2 = std::cos(0.7) * kX + std::sin(0.7) * kY,
           kY2 = -std::sin(0.7) * kX + std::cos(0.7) * kY;
const Vec3 kOrigin2 = kOrigin + 5 * kNormal + 3 * kX - 2 * kY;
Vec2 inTurned(const Vec2& side) {
  const Vec3 w = world(side) + 5 * kNormal - kOrigin2;
  return Vec2(w.dot(kX2), w.dot(kY2));
}

std::string slottedCrank() {
  const Vec2 X(8, 0), C(35, 0);
  const double along = (30.0 * 30 - 25.0 * 25 + 27.0 * 27) / (2 * 27);
  const Vec2 B = X + Vec2(along, std::sqrt(30.0 * 30 - along * along));
  auto onArc = [&](double deg) {
    const double a = deg * M_PI / 180;
    return vec2(inTurned(X + 30 * Vec2(std::cos(a), std::sin(a))));
  };
  return R"({"format": "linkage", "version": 1, "name": "slotted crank in space",
  "planes": {"side": {"origin": )" +
         vec(kOrigin) + R"(, "x_axis": )" + vec(kX) + R"(, "y_axis": )" + vec(kY) +
         R"(}, "turned": {"origin": )" + vec(kOrigin2) + R"(, "x_axis": )" + vec(kX2) +
         R"(, "y_axis": )" + vec(kY2) + R"(}},
  "bodies": [
    {"name": "ground", "ground": true, "points": {"O": )" +
         vec(world({0, 0})) + R"(, "C": )" + vec(world(C)) + R"(, "Q": )" +
         vec(world({20, -20}) + 10 * kNormal) + R"(}},
    {"name": "crank", "plane": "turned", "points": {"O": )" +
         vec2(inTurned({0, 0})) + R"(}, "slots": {"arc": [)" + onArc(10) + ", " + onArc(60) + ", " +
         onArc(110) + R"(]}},
    {"name": "rocker", "plane": "side", "points": {"C": )" +
         vec2(C) + R"(, "B": )" + vec2(B) +
         R"(}}],
  "joints": [{"type": "pin", "a": "ground.O", "b": "crank.O"},
    {"type": "pin", "a": "ground.C", "b": "rocker.C"},
    {"type": "pin-in-slot", "a": "rocker.B", "slot": "crank.arc"}],
  "driver": {"joint": 0, "rpm": 60, "direction": "ccw"}})";
}

// Every dimension of the slotted crank (the arc's centre and radius in the turned plane, both
// planes' origins among them) against the changed designs: the pin's world position and the
// transmission angle at it, central differences.
TEST(SpatialArcSlots, AnArcOnABodyInATurnedPlaneMovesAsChangedDesignsDo) {
  const Mechanism m = load(slottedCrank());
  const std::vector<Dimension> dims = dimensions(m);
  std::vector<std::string> names;
  for (const Dimension& d : dims) names.push_back(d.name);
  for (const char* want : {"crank.arc.centre.x", "crank.arc.centre.y", "crank.arc.radius"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  ASSERT_EQ(js.size(), 1u);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok()) << k.load(m).message;
  Sensitivity s;
  ASSERT_TRUE(s.prepare(k, dims, Sensitivity::Space::World).ok());
  const PointId B = *m.findPoint("rocker.B");
  const double h = 1e-6;
  double largest = 0;
  for (double deg : {0.0, 100.0, 230.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok() && s.at(k).ok());
    const std::vector<double> mu = transmissionAngleDerivatives(k, js[0], s);
    for (size_t d = 0; d < dims.size(); ++d) {
      Vec3 p[2];
      double angle[2];
      Kinematics kc[2];
      ASSERT_TRUE(test::loadChangedPair(m, dims, d, h, kc)) << dims[d].name;
      for (int side = 0; side < 2; ++side) {
        ASSERT_TRUE(kc[side].moveTo(deg).ok()) << dims[d].name;
        p[side] = kc[side].motionInSpace(B).position;
        angle[side] = transmissionAngle(kc[side], transmissionJoints(kc[side].mechanism())[0]).deg;
      }
      const Vec3 want = (p[1] - p[0]) / (2 * h);
      const double wantMu = (angle[1] - angle[0]) / (2 * h);
      largest = std::max(largest, want.norm());
      EXPECT_LT((s.point3(k, B, static_cast<int>(d)) - want).norm(), 1e-6 * (1 + want.norm()))
          << dims[d].name << " at " << deg;
      EXPECT_NEAR(mu[d], wantMu, 1e-6 * (1 + std::abs(wantMu))) << dims[d].name << " at " << deg;
    }
  }
  EXPECT_GT(largest, 0.5);
}

// The least distance from a ground point 10 mm off the planes to the crank's arc, and from the
// four-bar's coupler point A to the ground's arc (4 mm off its plane), against the changed
// designs' closest approaches.
TEST(SpatialArcSlots, TheClearanceToAnArcMovesAsChangedDesignsDo) {
  const Mechanism crank = load(slottedCrank()), bar = load(fourBar(true));
  auto slotOf = [](const Mechanism& m, const char* label) {
    for (const Slot& s : m.slots)
      if (m.slotLabel(s.id) == label) return s.id;
    return SlotId{};
  };
  test::expectClosestMovesAsChangedDesignsDo(
      crank, {*crank.findPoint("ground.Q"), ClearancePart::of(slotOf(crank, "crank.arc")), {}},
      1e-5);
  test::expectClosestMovesAsChangedDesignsDo(
      bar, {*bar.findPoint("coupler.A"), ClearancePart::of(slotOf(bar, "ground.arc")), {}}, 1e-5);
}

}  // namespace
}  // namespace linkage
