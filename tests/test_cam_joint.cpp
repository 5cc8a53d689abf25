// The cam joint's motion against its programme (issue 28, "The element"): a follower's position,
// velocity and acceleration from the constraint solves are s(theta), omega s'(theta) and
// omega^2 s''(theta) of linkage/cam.h, to 1e-9 of their peaks, for translating (offset roller,
// knife edge, flat face) and oscillating followers, and for a clockwise driver, which meets the
// segments in reverse order. Every follower the spec names: translating with and without offset
// and oscillating, each with a roller, a knife edge and a flat face.
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "linkage/cam.h"
#include "linkage/cam_joint.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? std::move(*r.mechanism) : Mechanism{};
}

// The programme as the joint reads it, and the peaks of s, s', s'' over a turn (the scales of
// the comparisons).
struct Expected {
  cam::Program program;
  double peak[3] = {0, 0, 0};
  explicit Expected(const Mechanism& m) {
    const std::optional<CamJoint> c = camJoint(m, m.joints.back());
    EXPECT_TRUE(c);
    if (c) program = c->program;
    for (int i = 0; i < 3600; ++i) {
      const cam::Displacement d = program.at(i * 0.1 * kDeg);
      peak[0] = std::max(peak[0], std::abs(d.s));
      peak[1] = std::max(peak[1], std::abs(d.v));
      peak[2] = std::max(peak[2], std::abs(d.a));
    }
  }
};

const double kAngles[] = {0,   3,   22.5,  45,    67.5, 89.999, 90,  120,  150,
                          181, 210, 240.5, 269.9, 270,  300,    333, 359.5};

// A translating follower: its height above the drawing is s(theta), theta = sigma phi.
void expectTranslating(const test::TranslatingCam& spec, double tolerance) {
  const Mechanism m = parsed(spec.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const Expected want(m);
  const PointId R = *m.findPoint("follower.R");
  const double w = k.omega(), sigma = spec.direction == "cw" ? -1 : 1;
  for (double deg : kAngles) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const cam::Displacement d = want.program.at(sigma * deg * kDeg);
    const Kinematics::PointMotion p = k.motion(R);
    EXPECT_NEAR(p.position.x(), spec.e, tolerance * want.peak[0]) << deg;
    EXPECT_NEAR(p.position.y() - spec.by(), d.s, tolerance * want.peak[0]) << deg;
    EXPECT_NEAR(p.velocity.y(), sigma * w * d.v, tolerance * w * want.peak[1]) << deg;
    EXPECT_NEAR(p.acceleration.y(), w * w * d.a, tolerance * w * w * want.peak[2]) << deg;
    EXPECT_NEAR(p.velocity.x(), 0, tolerance * w * want.peak[1]) << deg;
    EXPECT_NEAR(p.acceleration.x(), 0, tolerance * w * w * want.peak[2]) << deg;
  }
}

TEST(CamJoint, TranslatingRollerFollowerIsItsProgramme) {
  expectTranslating(test::TranslatingCam{}, 1e-9);
}

TEST(CamJoint, KnifeEdgeAndFlatFaceFollowersAreTheirProgrammes) {
  test::TranslatingCam knife;
  knife.roller = 0;
  knife.e = -7;
  expectTranslating(knife, 1e-9);
  test::TranslatingCam flat;
  flat.flat = true;
  flat.e = 4;
  flat.motion = R"([{"to_deg": 100, "rise_mm": 12, "law": "modified-trapezoid"},
                    {"to_deg": 260, "rise_mm": -12, "law": "harmonic"}, {"to_deg": 360}])";
  expectTranslating(flat, 1e-9);
}

// Clockwise, the cam turns by -phi: at phi the follower is at s(-phi), so it meets the fall
// (150 to 270 degrees of the programme) first, from phi = 90 to 210, and rises last.
TEST(CamJoint, AClockwiseCamMeetsTheSegmentsInReverseOrder) {
  test::TranslatingCam cw;
  cw.direction = "cw";
  expectTranslating(cw, 1e-9);
  const Mechanism m = parsed(cw.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const PointId R = *m.findPoint("follower.R");
  ASSERT_TRUE(k.moveTo(45).ok());  // theta = 315: the last dwell, at the bottom
  EXPECT_NEAR(k.position(R).y(), cw.by(), 1e-9);
  ASSERT_TRUE(k.moveTo(150).ok());  // theta = 210: half way down the fall, going up
  EXPECT_NEAR(k.position(R).y(), cw.by() + 5, 1e-9);
  EXPECT_GT(k.velocity(R).y(), 0);
  ASSERT_TRUE(k.moveTo(315).ok());  // theta = 45: half way up the rise, going down
  EXPECT_NEAR(k.position(R).y(), cw.by() + 5, 1e-9);
  EXPECT_LT(k.velocity(R).y(), 0);
}

// An oscillating follower turns by sign s(theta) relative to the guide: its angle, angular
// velocity and acceleration.
void expectOscillating(const test::OscillatingCam& spec, double sign) {
  const Mechanism m = parsed(spec.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const Expected want(m);
  const std::optional<CamJoint> c = camJoint(m, m.joints.back());
  ASSERT_TRUE(c);
  EXPECT_EQ(c->kind.sign, sign);
  const BodyId rocker = m.bodyNamed("rocker")->id;
  const double w = k.omega(), sigma = spec.direction == "cw" ? -1 : 1;
  for (double deg : kAngles) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    const cam::Displacement d = want.program.at(sigma * deg * kDeg);
    EXPECT_NEAR(k.bodyAngle(rocker), sign * d.s, 1e-9 * want.peak[0]) << deg;
    EXPECT_NEAR(k.bodyOmega(rocker), sign * sigma * w * d.v, 1e-9 * w * want.peak[1]) << deg;
    EXPECT_NEAR(k.bodyAlpha(rocker), sign * w * w * d.a, 1e-9 * w * w * want.peak[2]) << deg;
  }
}

TEST(CamJoint, OscillatingFollowerIsItsProgramme) {
  // R at 60 degrees about O, the pivot at (60, 0): a rise turns the rocker clockwise (R away
  // from O); with the pivot at (-60, 0): counter-clockwise.
  expectOscillating(test::OscillatingCam{}, -1);
  test::OscillatingCam other;
  other.px = -60;
  other.direction = "cw";
  expectOscillating(other, 1);
  test::OscillatingCam flat;
  flat.flat = true;
  expectOscillating(flat, -1);
}

// The followers the tests above leave out, so that every one the spec names is its programme:
// translating without offset (roller, knife edge, flat face) and an oscillating knife edge.
TEST(CamJoint, CentralFollowersAndAnOscillatingKnifeEdgeAreTheirProgrammes) {
  test::TranslatingCam roller, knife, flat;
  roller.e = knife.e = flat.e = 0;
  knife.roller = 0;
  flat.flat = true;
  expectTranslating(roller, 1e-9);
  expectTranslating(knife, 1e-9);
  expectTranslating(flat, 1e-9);
  test::OscillatingCam edge;
  edge.roller = 0;
  expectOscillating(edge, -1);
}

}  // namespace
}  // namespace linkage
