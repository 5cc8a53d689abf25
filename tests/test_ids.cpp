// Ids that hold: an id of another mechanism (foreign) or of an entity that is no longer there
// (stale) is refused by every query and command, as NaN, false, nullptr or BadModel, never taken
// for one of the mechanism's own; and derived objects refuse a mechanism they have not seen.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"
#include "linkage/velocity_chain.h"
#include "mechanisms.h"

namespace linkage {
namespace {

bool isNaN(const Vec2& v) {
  return std::isnan(v.x()) && std::isnan(v.y());
}

// Every query and command of k refuses the point p and the body b.
void expectQueriesRefused(const Kinematics& k, PointId p, BodyId b, const char* what) {
  EXPECT_FALSE(k.contains(p)) << what;
  EXPECT_FALSE(k.contains(b)) << what;
  EXPECT_TRUE(isNaN(k.position(p))) << what;
  EXPECT_TRUE(isNaN(k.velocity(p))) << what;
  EXPECT_TRUE(isNaN(k.acceleration(p))) << what;
  const Kinematics::PointMotion m = k.motion(p);
  EXPECT_TRUE(isNaN(m.position) && isNaN(m.velocity) && isNaN(m.acceleration)) << what;
  EXPECT_TRUE(std::isnan(k.bodyAngle(b))) << what;
  EXPECT_TRUE(std::isnan(k.bodyOmega(b))) << what;
  EXPECT_TRUE(std::isnan(k.bodyAlpha(b))) << what;
  const Transform T = k.bodyTransform(b);
  EXPECT_TRUE(std::isnan(T.R.c) && isNaN(T.t)) << what;
  EXPECT_TRUE(isNaN(k.toWorld(b, Vec2(1, 2)))) << what;
  EXPECT_TRUE(isNaN(k.toSketch(b, Vec2(1, 2)))) << what;
  const Status s = k.checkDetermined({p});
  EXPECT_EQ(s.code, StatusCode::BadModel) << what << ": " << s.message;
  Kinematics copy = k;
  const Kinematics::DragResult d = copy.dragTo(p, Vec2(0, 0));
  EXPECT_EQ(d.status.code, StatusCode::BadModel) << what << ": " << d.status.message;
  if (k.valid()) EXPECT_EQ(copy.crankDeg(), k.crankDeg()) << what;
  EXPECT_EQ(copy.flipBranch(b).code, StatusCode::BadModel) << what;
  for (const Point& q : k.mechanism().points) EXPECT_EQ(copy.position(q.id), k.position(q.id));
}

// The same, and the instant centres and velocity chains of k.
void expectRefused(const Kinematics& k, PointId p, BodyId b, const char* what) {
  expectQueriesRefused(k, p, b, what);
  // The centres know nothing of them either.
  const InstantCentres ics = computeInstantCentres(k);
  ASSERT_TRUE(ics.status.ok()) << ics.status.message;
  EXPECT_EQ(ics.numberOf(b), 0) << what;
  const VelocityChain ch = velocityChain(k, ics, p);
  EXPECT_EQ(ch.status.code, StatusCode::BadModel) << what << ": " << ch.status.message;
}

TEST(Ids, AnotherMechanismsIdsAreRefusedEverywhere) {
  // Two four-bars built the same way: their ids have the same values, other owners.
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto other = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  ASSERT_EQ(f.P.value, other.P.value);
  ASSERT_NE(f.P, other.P);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(40).ok());
  // The own ids answer (the refusals below are not of everything).
  EXPECT_TRUE(k.contains(f.P));
  EXPECT_FALSE(isNaN(k.position(f.P)));
  EXPECT_TRUE(std::isfinite(k.bodyAngle(f.coupler)));
  expectRefused(k, other.P, other.coupler, "foreign");
  // A slot and a joint of another mechanism.
  auto s = test::sliderCrank(20, 60, 5, 30);
  auto t = test::sliderCrank(20, 60, 5, 30);
  Kinematics ks;
  ASSERT_TRUE(ks.load(s.m).ok());
  EXPECT_TRUE(isNaN(ks.slotEnds(t.m.slots[0].id).p0));
  EXPECT_FALSE(isNaN(ks.slotEnds(s.m.slots[0].id).p0));
  EXPECT_FALSE(ks.contains(t.drive));
  EXPECT_TRUE(ks.contains(s.drive));
  // The mechanism itself: lookups and labels.
  EXPECT_EQ(f.m.point(other.P), nullptr);
  EXPECT_EQ(f.m.body(other.coupler), nullptr);
  EXPECT_EQ(f.m.joint(other.drive), nullptr);
  EXPECT_EQ(f.m.jointIndex(other.drive), -1);
  EXPECT_EQ(f.m.pointLabel(other.P), "?");
}

TEST(Ids, RemovedEntitiesAreStaleAfterTheEdit) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(40).ok());
  Mechanism m = f.m;
  m.remove(f.coupler);
  ASSERT_TRUE(k.edit(m).ok());
  expectRefused(k, f.P, f.coupler, "removed");
  // Still there: the crank.
  EXPECT_TRUE(std::isfinite(k.bodyAngle(f.crank)));
}

TEST(Ids, EntitiesCopiedWithAnotherMechanismsIdsAreABadModel) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  auto other = test::fourBar(60, 20, 70, 50, 60);
  Mechanism m = f.m;
  m.points.push_back(other.m.points.back());  // copied with its id, not by name
  m.points.back().body = f.coupler;
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const double before = k.position(f.P).x();
  const Status s = k.load(m);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("another mechanism"), std::string::npos) << s.message;
  EXPECT_EQ(k.edit(m).code, StatusCode::BadModel);
  EXPECT_TRUE(k.valid());
  EXPECT_EQ(k.position(f.P).x(), before);
}

TEST(Ids, CentresPreparedForOneRevisionRefuseAnother) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  InstantCentreSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  ASSERT_TRUE(solver.compute(k).status.ok());
  const std::uint64_t first = k.revision();
  EXPECT_NE(first, 0u);
  EXPECT_EQ(solver.compute(k).revision, first);
  // Turning the crank is the same revision: the centres follow.
  ASSERT_TRUE(k.moveTo(90).ok());
  EXPECT_EQ(k.revision(), first);
  ASSERT_TRUE(solver.compute(k).status.ok());
  const InstantCentres old = solver.result();

  // An edit of dimensions makes a new revision: the prepared solver refuses it, loudly.
  Mechanism m = f.m;
  m.point(f.P)->pos += Vec2(1, 0);
  ASSERT_TRUE(k.edit(m).ok());
  EXPECT_NE(k.revision(), first);
  const InstantCentres& stale = solver.compute(k);
  EXPECT_EQ(stale.status.code, StatusCode::BadModel);
  EXPECT_NE(stale.status.message.find("prepare() again"), std::string::npos);
  EXPECT_TRUE(stale.centres.empty());
  // So does a velocity chain handed the centres of the old revision.
  const VelocityChain ch = velocityChain(k, old, f.P);
  EXPECT_EQ(ch.status.code, StatusCode::BadModel) << ch.status.message;
  // Prepared again, it works.
  ASSERT_TRUE(solver.prepare(k).ok());
  ASSERT_TRUE(solver.compute(k).status.ok());
  EXPECT_TRUE(velocityChain(k, solver.result(), f.P).status.ok());

  // Another Kinematics holding an equal mechanism is another revision too.
  Kinematics twin;
  ASSERT_TRUE(twin.load(m).ok());
  EXPECT_NE(twin.revision(), k.revision());
  EXPECT_EQ(solver.compute(twin).status.code, StatusCode::BadModel);
}

TEST(Ids, NothingLoadedAnswersNaNAndBadModel) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  EXPECT_FALSE(k.valid());
  EXPECT_EQ(k.revision(), 0u);
  expectQueriesRefused(k, f.P, f.coupler, "nothing loaded");
  EXPECT_EQ(computeInstantCentres(k).status.code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage
