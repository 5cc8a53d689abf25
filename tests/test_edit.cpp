// Edits of dimensions on the closed-form path re-solve only the groups they touch
// (Kinematics::edit, ClosedFormPlan::resolveEdited); the answer must equal loading the edited
// drawing afresh and turning the crank to the same angle.
#include <gtest/gtest.h>

#include "examples.h"
#include "kinematics/kinematics_state.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

// Every point's position, velocity and acceleration equal a fresh load turned to `deg`.
void expectSameAsFresh(const Kinematics& k, const Mechanism& m, double deg, const char* what) {
  Kinematics fresh;
  ASSERT_TRUE(fresh.load(m).ok()) << what;
  ASSERT_TRUE(fresh.moveTo(deg).ok()) << what;
  const double L = fresh.size(), w = fresh.omega();
  for (const Point& p : m.points) {
    EXPECT_LT((k.position(p.id) - fresh.position(p.id)).norm(), 1e-10 * L) << what;
    EXPECT_LT((k.velocity(p.id) - fresh.velocity(p.id)).norm(), 1e-9 * L * w) << what;
    EXPECT_LT((k.acceleration(p.id) - fresh.acceleration(p.id)).norm(), 1e-9 * L * w * w) << what;
  }
}

Point& named(Mechanism& m, const std::string& body, const std::string& point) {
  const Body* b = m.bodyNamed(body);
  return *m.point(m.pointNamed(b->id, point)->id);
}

// The four-bar's rocker pivot O4 moved dx to the right, on the ground and on the rocker: a
// raised rocker, the drawing still closed.
Mechanism withRockerPivotMoved(const Mechanism& m, double dx) {
  Mechanism e = m;
  for (Point& p : e.points)
    if (p.name == "O4") p.pos += Vec2(dx, 0);
  return e;
}

TEST(Edit, ChangedLinkIsResolvedFromTheCurrentPose) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(100).ok());
  // Lengthen the rocker by moving its ground pivot 2 mm right, in the drawing.
  const Mechanism edited = withRockerPivotMoved(f.m, 2);
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_NEAR(k.crankDeg(), 100, 1e-12);
  // Same answer as loading the edited drawing and turning the crank.
  Kinematics fresh;
  ASSERT_TRUE(fresh.load(edited).ok());
  ASSERT_TRUE(fresh.moveTo(100).ok());
  EXPECT_LT((k.position(f.P) - fresh.position(f.P)).norm(), 1e-11);
  EXPECT_LT((k.acceleration(f.P) - fresh.acceleration(f.P)).norm(), 1e-7);
  // An edit that breaks the mechanism leaves a clear status: only the ground pivot moves far
  // away, the rocker keeps its length and cannot reach it.
  Mechanism broken = edited;
  for (Point& p : broken.points)
    if (p.name == "O4" && p.body == f.ground) p.pos += Vec2(500, 0);
  Status s = k.edit(broken);
  EXPECT_EQ(s.code, StatusCode::AssemblyFailed) << s.message;
}

TEST(Edit, ChainReSolvesOnlyTheGroupsDownstreamOfTheChange) {
  const int loops = 20;
  const Mechanism m = test::fourBarChain(loops);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(40).ok());
  const int groups = loops + 1;  // the crank, then one RRR dyad per loop

  // The last rocker's output arm: only the last loop's dyad.
  Mechanism last = m;
  named(last, "rocker19", "A").pos += Vec2(1.5, -0.5);
  ASSERT_TRUE(k.edit(last).ok());
  EXPECT_EQ(k.lastEditGroups(), 1);
  expectSameAsFresh(k, last, 40, "last rocker");

  // A ground pivot in the middle: its loop and every loop it drives.
  Mechanism middle = last;
  named(middle, "ground", "O4_10").pos += Vec2(0.8, 0.3);
  named(middle, "rocker10", "O4").pos += Vec2(0.8, 0.3);
  ASSERT_TRUE(k.edit(middle).ok());
  EXPECT_EQ(k.lastEditGroups(), loops - 10);
  expectSameAsFresh(k, middle, 40, "middle pivot");

  // The crank: everything.
  Mechanism crank = middle;
  named(crank, "crank", "A").pos *= 1.02;
  named(crank, "coupler0", "A").pos *= 1.02;
  ASSERT_TRUE(k.edit(crank).ok());
  EXPECT_EQ(k.lastEditGroups(), groups);
  expectSameAsFresh(k, crank, 40, "crank");

  // A speed change moves nothing: no group is solved, rates scale.
  Mechanism faster = crank;
  faster.driver->rpm = 600;
  ASSERT_TRUE(k.edit(faster).ok());
  EXPECT_EQ(k.lastEditGroups(), 0);
  expectSameAsFresh(k, faster, 40, "rpm");

  // The motion goes on from the edited state as from a fresh load.
  ASSERT_TRUE(k.moveTo(250).ok());
  expectSameAsFresh(k, faster, 250, "after the edits");
}

TEST(Edit, InPlaceEqualsTheWholeReSolveOfTheGeneralPath) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  KinematicsOptions general;
  general.closedForm = false;
  Kinematics fast, slow(general);
  ASSERT_TRUE(fast.load(f.m).ok());
  ASSERT_TRUE(slow.load(f.m).ok());
  ASSERT_TRUE(fast.moveTo(123).ok());
  ASSERT_TRUE(slow.moveTo(123).ok());
  Mechanism edited = f.m;
  for (Point& p : edited.points)
    if (p.body == f.coupler && p.name == "B") p.pos += Vec2(0.5, 0.25);
  ASSERT_TRUE(fast.edit(edited).ok());
  ASSERT_TRUE(slow.edit(edited).ok());
  EXPECT_GE(fast.lastEditGroups(), 1);
  EXPECT_EQ(slow.lastEditGroups(), fast.lastEditGroups());
  for (const Point& p : edited.points) {
    EXPECT_LT((fast.position(p.id) - slow.position(p.id)).norm(), 1e-10);
    EXPECT_LT((fast.acceleration(p.id) - slow.acceleration(p.id)).norm(),
              1e-9 * (1 + slow.acceleration(p.id).norm()));
  }
}

TEST(Edit, KeepsTheCrossedBranch) {
  // Drawn crossed; after the edit (a raised rocker) it must still be crossed, as a fresh load of
  // the edited drawing assembles it.
  auto f = test::fourBar(60, 20, 70, 50, 60, false);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(30).ok());
  const Mechanism edited = withRockerPivotMoved(f.m, 3);
  ASSERT_TRUE(k.edit(edited).ok());
  EXPECT_GE(k.lastEditGroups(), 1);
  expectSameAsFresh(k, edited, 30, "crossed");
}

TEST(Edit, TopologyChangesAreSolvedWhole) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  Mechanism more = f.m;
  more.addPoint(f.coupler, "Q", Vec2(10, 10));
  ASSERT_TRUE(k.edit(more).ok());
  EXPECT_EQ(k.lastEditGroups(), -1);
  Mechanism reversed = f.m;
  reversed.driver->direction = Direction::Cw;
  ASSERT_TRUE(k.edit(reversed).ok());
  EXPECT_EQ(k.lastEditGroups(), -1);
}

using EditPath = KinematicsState::EditPath;

EditPath lastEdit(const Kinematics& k) {
  return internal::state(k).lastEdit;
}

// A design point moved by the mouse (Ctrl+drag): many small edits of one point in a row, each
// solved from the last pose; after each, the same motion as a fresh load of that design.
void expectMouseEditsLikeFreshLoads(const Mechanism& m, const std::string& point, double deg,
                                    bool closedForm, EditPath expected) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.moveTo(deg).ok());
  Mechanism edited = m;
  Point& p = *edited.point(*edited.findPoint(point));
  const Vec2 start = p.pos;
  for (int move = 1; move <= 12; ++move) {
    p.pos = start + 0.05 * move * Vec2(1, -0.5);
    const Status s = k.edit(edited);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(lastEdit(k), expected) << point << " move " << move;
    EXPECT_NEAR(k.crankDeg(), deg, 1e-12);
    if (move % 4 == 0) expectSameAsFresh(k, edited, deg, point.c_str());
  }
}

TEST(Edit, MouseMovesOfOnePointKeepTheAnalysisOnEveryPath) {
  const Mechanism chain = test::fourBarChain(25);  // 51 moving bodies
  const Mechanism wanzer = test::example("wanzer-inversion-2");
  // The closed-form groups re-solve in place; the general solve re-solves the groups the edit
  // touches by Newton on their bodies, or, where those are as many as the sparse solve's (loops
  // 12 to 24 of the chain: 26 bodies), keeps its analysis and its solver and re-assembles the
  // whole from the pose.
  expectMouseEditsLikeFreshLoads(chain, "coupler12.B", 30, true, EditPath::InPlace);
  expectMouseEditsLikeFreshLoads(chain, "coupler12.B", 30, false, EditPath::KeptAnalysis);
  expectMouseEditsLikeFreshLoads(wanzer, "triangle.G", 30, true, EditPath::InPlace);
  expectMouseEditsLikeFreshLoads(wanzer, "triangle.G", 30, false, EditPath::Blocks);
  // Triads do not decompose: the general solve, whatever the option says (units 1 and 2).
  expectMouseEditsLikeFreshLoads(test::triadChain(3), "triangle1.S", 30, true, EditPath::Blocks);
}

TEST(Edit, AnEditThatChangesTheRankIsAnalysedAgain) {
  // A parallelogram with a fifth link parallel to the crank: redundant, it moves. Edited so that
  // the fifth link's ground pivot is 0.5 mm higher, the circle its end draws crosses the one the
  // coupler's point draws instead of being the same: no raised redundant, the rank grows and the
  // mechanism is a structure. The edit of dimensions cannot keep the analysis (the redundant row
  // does not hold): analysed whole, it is refused as locked, and the state stays as it was.
  auto f = test::fourBar(100, 40, 100, 40, 60);
  Mechanism m = f.m;
  const BodyId link = m.addBody("link5");
  const Vec2 A = m.point(f.A)->pos;
  m.addPin(m.addPoint(f.ground, "O5", {50, 0}), m.addPoint(link, "O5", {50, 0}));
  m.addPin(m.addPoint(link, "M", A + Vec2(50, 0)), m.addPoint(f.coupler, "M", A + Vec2(50, 0)));
  KinematicsOptions opt;
  opt.closedForm = false;
  Kinematics k(opt);
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_EQ(k.structure().redundantJoints.size(), 1u);
  ASSERT_TRUE(k.moveTo(20).ok());
  const Vec2 before = k.position(f.P);
  Mechanism raised = m;
  raised.point(*raised.findPoint("ground.O5"))->pos += Vec2(0, 0.5);
  raised.point(*raised.findPoint("link5.O5"))->pos += Vec2(0, 0.5);
  const Status s = k.edit(raised);
  EXPECT_EQ(s.code, StatusCode::Locked) << s.message;
  EXPECT_EQ(k.structure().redundantJoints.size(), 1u);
  EXPECT_EQ(k.position(f.P), before);
  // The same design loaded afresh says the same.
  Kinematics fresh(opt);
  EXPECT_EQ(fresh.load(raised).code, StatusCode::Locked);
}

}  // namespace
}  // namespace linkage
