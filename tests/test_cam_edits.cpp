// The cam table's edits (linkage/cam_edits.h): a cam made for a follower as drawn, its base
// moving the follower to its new lowest position, its roller keeping the pitch curve, its
// programme checked; each against the drawing's own geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "cam_fixtures.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"

namespace linkage {
namespace {

Mechanism parsed(const std::string& text) {
  LoadResult r = parseMechanism(text);
  EXPECT_TRUE(r.mechanism) << r.error;
  return r.mechanism ? std::move(*r.mechanism) : Mechanism{};
}

JointId camOf(const Mechanism& m) {
  for (const Joint& j : m.joints)
    if (j.type == elementKindNamed("cam")->type) return j.id;
  return {};
}

// The fixture without its cam joint: a follower as a user has drawn it.
Mechanism withoutCam(const std::string& text) {
  Mechanism m = parsed(text);
  m.remove(camOf(m));
  return m;
}

// Made, loaded, read back from its file text unchanged.
CamJoint madeAndLoaded(Mechanism& m, const char* follower, bool flat) {
  const PointId b = *m.findPoint(follower);
  std::string why;
  const std::vector<BodyId> cams = camBodiesFor(m, b, &why);
  EXPECT_EQ(cams.size(), 1u) << why;
  EXPECT_EQ(m.body(cams.at(0))->name, "cam");
  const JointId j = addCam(m, b, cams.at(0), flat, &why);
  EXPECT_TRUE(j) << why;
  Kinematics k;
  {
    const Status st = k.load(m);
    EXPECT_TRUE(st.ok()) << st.message;
  }
  const LoadResult back = parseMechanism(serializeMechanism(m));
  EXPECT_TRUE(back.mechanism && mechanismDifference(m, *back.mechanism).empty()) << back.error;
  const std::optional<CamJoint> c = camJoint(m, *m.joint(j), &why);
  EXPECT_TRUE(c) << why;
  return c ? *c : CamJoint{};
}

TEST(CamEdits, ACamIsMadeForAFollowerAsDrawn) {
  // Translating roller: b = (10, sqrt(38^2 - 10^2)): the pitch circle through it is 38.
  Mechanism t = withoutCam(test::TranslatingCam{}.text());
  const CamJoint ct = madeAndLoaded(t, "follower.R", false);
  EXPECT_NEAR(ct.kind.base + ct.kind.roller, 38, 1e-12);
  EXPECT_NEAR(ct.kind.roller, 38.0 / 4, 1e-12);
  EXPECT_EQ(ct.program.segments().size(), 4u);
  // Its first rise: a quarter of the base, rounded (28.5 / 4 = 7.1 mm).
  EXPECT_EQ(ct.program.segments()[0].rise, 7);
  // Flat: the face's distance from the cam's centre along the slot, any offset.
  test::TranslatingCam flat;
  flat.flat = true;
  Mechanism f = withoutCam(flat.text());
  EXPECT_NEAR(madeAndLoaded(f, "follower.R", true).kind.base, 30, 1e-12);
  // Oscillating: R at 38 from O; it rises 10 degrees.
  Mechanism o = withoutCam(test::OscillatingCam{}.text());
  const CamJoint co = madeAndLoaded(o, "rocker.R", false);
  EXPECT_TRUE(co.kind.oscillating);
  EXPECT_NEAR(co.kind.base + co.kind.roller, 38, 1e-12);
  EXPECT_EQ(co.program.segments()[0].rise, 10);
  // A second cam on the follower is refused.
  std::string why;
  EXPECT_FALSE(addCam(o, *o.findPoint("rocker.R"), o.bodyNamed("cam")->id, false, &why));
  EXPECT_NE(why.find("has a cam already"), std::string::npos) << why;
}

TEST(CamEdits, ABodyHeldByTwoJointsIsNoFollower) {
  Mechanism o = withoutCam(test::OscillatingCam{}.text());
  const BodyId rocker = o.bodyNamed("rocker")->id;
  o.addPin(*o.findPoint("rocker.R"),
           o.addPoint(o.bodyNamed("cam")->id, "R", o.point(*o.findPoint("rocker.R"))->pos));
  std::string why;
  EXPECT_TRUE(camBodiesFor(o, o.pointNamed(rocker, "R")->id, &why).empty());
  EXPECT_NE(why.find("more than one"), std::string::npos) << why;
}

TEST(CamEdits, ANewBaseMovesTheFollowerToItsLowestPosition) {
  // Translating, e = 10: b from sqrt(38^2 - 100) to sqrt(48^2 - 100) above the foot (10, 0).
  Mechanism t = parsed(test::TranslatingCam{}.text());
  std::string why;
  ASSERT_TRUE(setCamBase(t, camOf(t), 40, &why)) << why;
  EXPECT_NEAR(t.point(*t.findPoint("follower.R"))->pos.y(), std::sqrt(48.0 * 48 - 100), 1e-12);
  EXPECT_EQ(t.point(*t.findPoint("follower.R"))->pos.x(), 10);
  Kinematics k;
  {
    const Status st = k.load(t);
    EXPECT_TRUE(st.ok()) << st.message;
  }
  // Oscillating: R turned about P = (60, 0) onto the circle of 43 about O, the arm kept.
  Mechanism o = parsed(test::OscillatingCam{}.text());
  const Vec2 R0 = o.point(*o.findPoint("rocker.R"))->pos, P(60, 0);
  ASSERT_TRUE(setCamBase(o, camOf(o), 35, &why)) << why;
  const Vec2 R = o.point(*o.findPoint("rocker.R"))->pos;
  EXPECT_NEAR(R.norm(), 43, 1e-12);
  EXPECT_NEAR((R - P).norm(), (R0 - P).norm(), 1e-12);
  EXPECT_EQ(o.point(*o.findPoint("rocker.P"))->pos, P);
  // The smaller of the two turns that reach the circle: R stays on the side it was drawn.
  EXPECT_GT(R.y(), 0);
  {
    const Status st = k.load(o);
    EXPECT_TRUE(st.ok()) << st.message;
  }
  // Out of reach: the arm of |R0 - P| = 52.9 about P reaches no more than 112.9 from O.
  const Mechanism before = o;
  EXPECT_FALSE(setCamBase(o, camOf(o), 200, &why));
  EXPECT_NE(why.find("cannot reach"), std::string::npos) << why;
  EXPECT_TRUE(mechanismDifference(o, before).empty());
}

TEST(CamEdits, ANewRollerKeepsThePitchCurve) {
  Mechanism t = parsed(test::TranslatingCam{}.text());
  const Vec2 R = t.point(*t.findPoint("follower.R"))->pos;
  std::string why;
  ASSERT_TRUE(setCamRoller(t, camOf(t), 12, &why)) << why;
  const std::optional<CamJoint> c = camJoint(t, *t.joint(camOf(t)), &why);
  ASSERT_TRUE(c) << why;
  EXPECT_EQ(c->kind.base, 26);
  EXPECT_EQ(c->kind.roller, 12);
  EXPECT_EQ(t.point(*t.findPoint("follower.R"))->pos, R);
  EXPECT_FALSE(setCamRoller(t, camOf(t), 38, &why));
  test::TranslatingCam flat;
  flat.flat = true;
  Mechanism f = parsed(flat.text());
  EXPECT_FALSE(setCamRoller(f, camOf(f), 2, &why));
  EXPECT_NE(why.find("flat face"), std::string::npos) << why;
}

TEST(CamEdits, AProgrammeIsCheckedBeforeItIsTaken) {
  Mechanism t = parsed(test::TranslatingCam{}.text());
  const Mechanism before = t;
  std::string why;
  const cam::Segment open[] = {{100, 8, cam::Law::Harmonic}, {360, 0, {}}};
  EXPECT_FALSE(setCamMotion(t, camOf(t), open, &why));
  EXPECT_NE(why.find("motion"), std::string::npos) << why;
  EXPECT_TRUE(mechanismDifference(t, before).empty());
  const cam::Segment closed[] = {
      {100, 8, cam::Law::Harmonic}, {200, -8, cam::Law::ModifiedSine}, {360, 0, {}}};
  ASSERT_TRUE(setCamMotion(t, camOf(t), closed, &why)) << why;
  const std::optional<CamJoint> c = camJoint(t, *t.joint(camOf(t)), &why);
  ASSERT_TRUE(c) << why;
  EXPECT_EQ(c->program.segments(), std::vector<cam::Segment>(std::begin(closed), std::end(closed)));
  Kinematics k;
  {
    const Status st = k.load(t);
    ASSERT_TRUE(st.ok()) << st.message;
  }
  ASSERT_TRUE(k.moveTo(100).ok());
  EXPECT_NEAR(
      k.position(*t.findPoint("follower.R")).y() - t.point(*t.findPoint("follower.R"))->pos.y(), 8,
      1e-9);
}

}  // namespace
}  // namespace linkage
