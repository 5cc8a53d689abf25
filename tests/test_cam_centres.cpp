// A cam's instant centre (issue 28): the cam joint says the centre of the cam and its follower is
// on the common normal (a line at each pose, CentreRule::PoseLine), and Kennedy's rule meets it
// with the line of the cam's and the follower's centres with the guide. Checked against the
// velocity ratio: a translating follower moves at omega times the centre's distance from the cam's
// centre (along the line through it normal to the slot); an oscillating one turns at omega times
// the ratio of the centre's distances from the two pivots.
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "linkage/cam_joint.h"
#include "linkage/drawing.h"
#include "linkage/instant_centres.h"
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

TEST(CamCentres, TranslatingFollowersCentreIsWhereTheNormalMeetsTheLineNormalToItsSlot) {
  for (const char* direction : {"ccw", "cw"}) {
    test::TranslatingCam spec;
    spec.direction = direction;
    const Mechanism m = parsed(spec.text());
    Kinematics k;
    ASSERT_TRUE(k.load(m).ok());
    const cam::Program program = camJoint(m, m.joints[2])->program;
    const PointId R = *m.findPoint("follower.R");
    const double w = k.omega(), sigma = spec.direction == "cw" ? -1 : 1;
    const BodyId cam = m.bodyNamed("cam")->id;
    for (double deg = 0; deg < 360; deg += 7.5) {
      ASSERT_TRUE(k.moveTo(deg).ok());
      const InstantCentres ics = computeInstantCentres(k);
      ASSERT_TRUE(ics.status.ok()) << ics.status.message;
      EXPECT_TRUE(ics.disagreements.empty()) << deg;
      const InstantCentre* c = ics.find(2, 3);
      ASSERT_TRUE(c && c->determined) << deg;
      EXPECT_EQ(c->status, CentreStatus::Kennedy) << deg;
      EXPECT_EQ(c->lines[1].joint, m.joints[2].id) << deg;  // the cam's common normal
      // At a + s' w: w = (1, 0) to the right of the rise, a at the origin.
      const double sPrime = program.at(sigma * deg * kDeg).v;
      EXPECT_NEAR(c->point().x(), sPrime, 1e-9 * 40) << deg;
      EXPECT_NEAR(c->point().y(), 0, 1e-9 * 40) << deg;
      // The follower moves as the cam's point at the centre: v = omega_cam x distance.
      EXPECT_NEAR(k.velocity(R).y(), k.bodyOmega(cam) * c->point().x(), 1e-9 * w * 40) << deg;
    }
  }
}

TEST(CamCentres, OscillatingFollowersCentreIsOnTheLineOfThePivots) {
  const test::OscillatingCam spec;
  const Mechanism m = parsed(spec.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  const BodyId cam = m.bodyNamed("cam")->id, rocker = m.bodyNamed("rocker")->id;
  const Vec2 A(0, 0), P(spec.px, spec.py), d = (P - A).normalized();
  for (double deg = 0; deg < 360; deg += 7.5) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const InstantCentres ics = computeInstantCentres(k);
    ASSERT_TRUE(ics.status.ok()) << ics.status.message;
    EXPECT_TRUE(ics.disagreements.empty()) << deg;
    const InstantCentre* c = ics.find(2, 3);
    ASSERT_TRUE(c && c->determined && !c->atInfinity()) << deg;
    EXPECT_EQ(c->status, CentreStatus::Kennedy) << deg;
    const Vec2 I = c->point();
    EXPECT_NEAR(cross(I - A, d), 0, 1e-9 * 60) << deg;  // on the line of the pivots
    // Equal velocities there: omega_cam (I - A) = omega_rocker (I - P) along the line.
    EXPECT_NEAR(k.bodyOmega(rocker) * (I - P).dot(d), k.bodyOmega(cam) * (I - A).dot(d),
                1e-9 * k.omega() * 60)
        << deg;
  }
}

// The canvas draws the common normal Kennedy used: a line of the drawing's centre 2,3 through
// the contact, along the normal.
TEST(CamCentres, TheDrawingShowsTheCommonNormal) {
  const Mechanism m = parsed(test::TranslatingCam{}.text());
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.moveTo(40).ok());
  const InstantCentres ics = computeInstantCentres(k);
  const Drawing d = describeDrawing(k, &ics);
  const Vec2 b = k.position(*m.findPoint("follower.R"));
  bool found = false;
  for (const Drawing::Centre& c : d.centres) {
    if (c.i != 2 || c.j != 3) continue;
    for (const Drawing::KennedyLine& l : c.lines) {
      if (l.k != 0) continue;
      found = true;
      const Vec2 p(l.through[0].x(), l.through[0].y()), n(l.through[1].x(), l.through[1].y());
      EXPECT_NEAR((p - b).norm(), 0, 1e-9);           // a roller's normal passes through its centre
      EXPECT_NEAR(cross(c.at - p, n), 0, 1e-9 * 40);  // and through the centre found
    }
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace linkage
