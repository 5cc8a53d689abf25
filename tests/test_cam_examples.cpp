// The cam examples of a sewing machine (issue 28, "Examples and tests";
// resources/examples/cams.py): the lockstitch machine's thread take-up cam (arm shaft) and
// feed-lift cam (lower shaft, belted 1:1), and the chain-stitch looper's cam with a flat-faced
// follower. Each loads and is as the program saves it; it solves every half degree of a whole turn;
// each follower turns by its programme's s(theta) with omega s' and omega^2 s'' (its point on the
// circle about its pivot), to 1e-9 of their peaks, theta the cam's turn taken from the gear's
// ratio, not the solver; its checks keep the usual limits (35 degrees for an oscillating follower)
// and do not undercut.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "examples.h"
#include "linkage/cam_checks.h"
#include "linkage/cam_joint.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

// A follower of an example: its cam joint, its body, the point whose path is watched, its pivot
// and the cam's turn per turn of the crank (the belt's ratio).
struct Follower {
  const char* file;
  size_t joint;
  const char* body;
  const char* point;
  Vec2 pivot;
  double ratio;
};

// Every follower of the examples rises by turning clockwise (its point b left of its pivot or
// on the far side of it going up, away from the cam's centre, cams.py): its angle is -s.
const Follower kFollowers[] = {
    {"lockstitch-cams", 5, "takeup", "takeup.E", Vec2(32, 31), 1},
    {"lockstitch-cams", 9, "feedlift", "feedlift.F", Vec2(-35, -205), 1},
    {"chainstitch-looper-cam", 2, "looper", "looper.L", Vec2(50, 30), 1},
};

// The peaks of s, s', s'' over a turn: the scales of the comparisons.
std::array<double, 3> peaks(const cam::Program& p) {
  std::array<double, 3> peak{0, 0, 0};
  for (int i = 0; i < 3600; ++i) {
    const cam::Displacement d = p.at(i * 0.1 * kDeg);
    peak = {std::max(peak[0], std::abs(d.s)), std::max(peak[1], std::abs(d.v)),
            std::max(peak[2], std::abs(d.a))};
  }
  return peak;
}

TEST(CamExamples, EachFollowerTurnsByItsProgrammeOverAWholeTurn) {
  for (const Follower& f : kFollowers) {
    const Mechanism m = test::example(f.file);
    ASSERT_LT(f.joint, m.joints.size()) << f.file;
    const std::optional<CamJoint> c = camJoint(m, m.joints[f.joint]);
    ASSERT_TRUE(c) << f.file << " joints[" << f.joint << "]";
    ASSERT_TRUE(c->kind.oscillating) << f.file;
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok()) << f.file;
    const BodyId body = m.bodyNamed(f.body)->id;
    const PointId point = *m.findPoint(f.point);
    const Vec2 p0 = k.position(point) - f.pivot;  // the drawing: s = 0
    const std::array<double, 3> peak = peaks(c->program);
    ASSERT_GT(peak[0], 2 * kDeg) << f.file;  // a real swing
    const double w = k.omega() * f.ratio, L = p0.norm();
    for (int i = 0; i <= 720; ++i) {
      const double deg = i * 0.5;
      ASSERT_TRUE(k.moveTo(deg).ok()) << f.file << " at " << deg;
      const cam::Displacement d = c->program.at(std::fmod(f.ratio * deg, 360) * kDeg);
      const std::string at = std::string(f.file) + " " + f.body + " at " + std::to_string(deg);
      EXPECT_NEAR(k.bodyAngle(body), -d.s, 1e-9 * peak[0]) << at;
      EXPECT_NEAR(k.bodyOmega(body), -w * d.v, 1e-9 * w * peak[1]) << at;
      EXPECT_NEAR(k.bodyAlpha(body), -w * w * d.a, 1e-9 * w * w * peak[2]) << at;
      // The watched point on its circle about the pivot, turned by -s.
      const Vec2 want = f.pivot + Rot::of(-d.s) * p0;
      EXPECT_NEAR((k.position(point) - want).norm(), 0, 1e-9 * L * peak[0]) << at;
      EXPECT_NEAR(k.velocity(point).norm(), L * w * std::abs(d.v), 1e-9 * L * w * peak[1]) << at;
    }
  }
}

TEST(CamExamples, ChecksAreWithinTheLimitsAndNoneUndercuts) {
  for (const Follower& f : kFollowers) {
    const Mechanism m = test::example(f.file);
    const std::optional<CamJoint> c = camJoint(m, m.joints[f.joint]);
    ASSERT_TRUE(c) << f.file;
    const cam::CamGeometry g = cam::geometryOf(*c);
    ASSERT_EQ(cam::checkCamGeometry(g), "") << f.file;
    const cam::CamChecks checks = cam::camChecks(g);
    EXPECT_FALSE(checks.undercut) << f.file << " " << f.body << ": " << checks.undercutWhy;
    // Realistic sizes: cams of 15 to 40 mm base radius.
    EXPECT_GE(g.baseMm, 15) << f.file;
    EXPECT_LE(g.baseMm, 40) << f.file;
    if (c->kind.flat) {
      ASSERT_TRUE(checks.surfaceRadiusMin.found) << f.file;
      EXPECT_GT(checks.surfaceRadiusMin.value, 5) << f.file << " " << f.body;
      continue;
    }
    ASSERT_TRUE(checks.pressureMax.found) << f.file;
    EXPECT_LT(checks.pressureMax.value, 35) << f.file << " " << f.body;
    EXPECT_GT(checks.pressureMax.value, 5) << f.file << " " << f.body;  // it is computed
    ASSERT_TRUE(checks.pitchRadiusMin.found) << f.file;
    EXPECT_GT(checks.pitchRadiusMin.value, g.rollerMm) << f.file << " " << f.body;
  }
}

// The cam's body turns with the crank as the belt (a gear of ratio 1) says: theta above is the
// crank's angle for the lower shaft's cam too.
TEST(CamExamples, TheLowerShaftTurnsWithTheArmShaft) {
  const Mechanism m = test::example("lockstitch-cams");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const BodyId lower = m.bodyNamed("lowershaft")->id, arm = m.bodyNamed("armshaft")->id;
  for (double deg = 0; deg < 360; deg += 7.5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    EXPECT_NEAR(std::remainder(k.bodyAngle(lower) - deg * kDeg, 2 * M_PI), 0, 1e-12) << deg;
    EXPECT_NEAR(std::remainder(k.bodyAngle(arm) - deg * kDeg, 2 * M_PI), 0, 1e-12) << deg;
  }
}

TEST(CamExamples, AreAsTheProgramSavesThem) {
  for (const char* name : {"lockstitch-cams", "chainstitch-looper-cam"}) {
    std::ifstream f(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const LoadResult r = parseMechanism(text);
    ASSERT_TRUE(r.mechanism) << name << ": " << r.error;
    EXPECT_EQ(serializeMechanism(*r.mechanism), text) << name;
  }
}

}  // namespace
}  // namespace linkage
