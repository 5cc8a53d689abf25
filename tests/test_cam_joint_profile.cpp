// A cam's profile (linkage/cam_geometry.h, what the joint draws and the checks read) against
// closed forms: a translating roller follower's
// pressure angle is the spec's atan((s' - e) / (sqrt((base + roller)^2 - e^2) + s)); its surface
// is the pitch curve less the roller along the normal; a knife edge's surface is its pitch curve;
// a flat face's contact is at base + s from the cam's centre along the follower's motion, s'
// to the side of it; the profile turns with the cam (the pitch point of theta is b turned back
// by theta).
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "linkage/cam_geometry.h"
#include "linkage/cam_joint.h"
#include "linkage/drawing.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

CamJoint camOf(const std::string& text) {
  const LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return *camJoint(*r.mechanism, r.mechanism->joints[2]);
}

Vec2 turned(double a, const Vec2& v) {
  return Rot::of(a) * v;
}

TEST(CamJointProfile, TranslatingRollerFollowersPressureAngleIsTheSpecsFormula) {
  for (double e : {10.0, -6.0, 0.0}) {
    test::TranslatingCam spec;
    spec.e = e;
    const CamJoint c = camOf(spec.text());
    const double d0 = std::sqrt(38.0 * 38.0 - e * e);
    for (const cam::CamPoint& p : cam::camPoints(cam::geometryOf(c), 720)) {
      const double theta = p.camDeg * kDeg;
      const cam::Displacement s = c.program.at(theta);
      EXPECT_NEAR(p.pressureDeg * kDeg, std::atan((s.v - e) / (d0 + s.s)), 1e-14)
          << e << " " << theta;
      // The pitch point: b at s above its drawing, seen from the cam turned by theta.
      const Vec2 b(e, d0 + s.s);
      EXPECT_NEAR((p.pitch - turned(-theta, b)).norm(), 0, 1e-12);
      // The surface: the roller's radius in from the pitch curve, along the common normal the
      // contact's forces act on (cam::contact, written apart).
      EXPECT_NEAR((p.pitch - p.surface).norm(), 8, 1e-12);
      cam::Place at = c.drawn;
      at.b = c.drawn.b + s.s * c.drawn.along;
      const Vec2 n = turned(-theta, cam::contact(c.kind, at, s.v).normal);
      EXPECT_NEAR((p.pitch - p.surface).normalized().dot(n), 1, 1e-14);
    }
  }
  // On the dwells the pitch curve is the circle of base + roller, the surface the base circle.
  const CamJoint c = camOf(test::TranslatingCam{}.text());
  const cam::CamPoint dwell = cam::camPointAt(cam::geometryOf(c), 300 * kDeg);
  EXPECT_NEAR(dwell.pitch.norm(), 38, 1e-12);
  EXPECT_NEAR(dwell.surface.norm(), 30, 1e-12);
}

TEST(CamJointProfile, AKnifeEdgesSurfaceIsItsPitchCurve) {
  test::TranslatingCam spec;
  spec.roller = 0;
  const CamJoint c = camOf(spec.text());
  for (const cam::CamPoint& p : cam::camPoints(cam::geometryOf(c), 90))
    EXPECT_NEAR((p.pitch - p.surface).norm(), 0, 1e-12);
}

// The face is at base + s from a along u; the contact is s' to the right of a's line along u
// (a + s' w is the instant centre; the normal along u passes through it).
TEST(CamJointProfile, AFlatFacesContactIsSPrimeAside) {
  test::TranslatingCam spec;
  spec.flat = true;
  spec.e = 5;
  const CamJoint c = camOf(spec.text());
  for (const cam::CamPoint& p : cam::camPoints(cam::geometryOf(c), 360)) {
    const double theta = p.camDeg * kDeg;
    const cam::Displacement s = c.program.at(theta);
    const Vec2 world = turned(theta, p.surface);  // the guide's frame, a at the origin
    EXPECT_NEAR(world.y(), 30 + s.s, 1e-12) << theta;
    EXPECT_NEAR(world.x(), s.v, 1e-12) << theta;
    EXPECT_NEAR(p.pressureDeg, 0, 1e-15);
  }
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

// The canvas draws the profile it is cut to: the joint's symbol carries the surface and, for a
// roller, the pitch curve a roller's radius outside it, both turning with the cam.
TEST(CamJointProfile, TheDrawingCarriesTheSurfaceAndThePitchCurve) {
  const LoadResult r = parseMechanism(test::TranslatingCam{}.text());
  ASSERT_TRUE(r.mechanism) << r.error;
  const Drawing d = describeSketch(*r.mechanism);
  const JointSymbol* cam = nullptr;
  for (const JointSymbol& s : d.joints)
    if (!s.curve.empty()) cam = &s;
  ASSERT_TRUE(cam);
  ASSERT_EQ(cam->curve.size(), 360u);
  ASSERT_EQ(cam->curve2.size(), 360u);
  const cam::CamGeometry g = cam::geometryOf(*camJoint(*r.mechanism, r.mechanism->joints[2]));
  for (size_t i = 0; i < 360; i += 7) {
    const cam::CamPoint p = cam::camPointAt(g, i * kDeg);
    EXPECT_LT((cam->curve[i] - p.surface).norm(), 1e-12);
    EXPECT_LT((cam->curve2[i] - p.pitch).norm(), 1e-12);
    EXPECT_NEAR((cam->curve2[i] - cam->curve[i]).norm(), 8, 1e-12);
  }
  test::TranslatingCam flat;
  flat.flat = true;
  const LoadResult f = parseMechanism(flat.text());
  for (const JointSymbol& s : describeSketch(*f.mechanism).joints) EXPECT_TRUE(s.curve2.empty());
}

}  // namespace
}  // namespace linkage
