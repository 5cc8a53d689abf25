// Structure analysis and assembly: degrees of freedom, redundant and conflicting joints, a
// driver that cannot turn, freedoms the driver leaves, drawings that do not close.
#include <gtest/gtest.h>

#include <cmath>

#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

using test::fourBar;
using test::sliderCrank;

TEST(Structure, FourBarHasOneFreedomAndFullRank) {
  auto f = fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const StructureReport s = k.structure();
  EXPECT_EQ(s.coordinates, 9);
  EXPECT_EQ(s.jointEquations, 8);
  EXPECT_EQ(s.gruebler, 1);
  EXPECT_EQ(s.rank, 8);
  EXPECT_EQ(s.mobility, 1);
  EXPECT_TRUE(s.redundantJoints.empty());
  EXPECT_TRUE(s.driverMoves);
  EXPECT_EQ(s.freeAfterDriver, 0);
  EXPECT_FALSE(k.assembly().moved);
}

TEST(Structure, DuplicatedPinIsNamedRedundantAndMotionUnchanged) {
  auto plain = fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto f = fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const Vec2 B = f.m.point(f.B)->pos;
  const PointId b2 = f.m.addPoint(f.coupler, "B2", B);
  const PointId r2 = f.m.addPoint(f.rocker, "B2", B);
  const JointId dup = f.m.addPin(b2, r2);
  Kinematics k, ref;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(ref.load(plain.m).ok());
  const StructureReport s = k.structure();
  EXPECT_EQ(s.gruebler, -1);
  EXPECT_EQ(s.mobility, 1);
  ASSERT_EQ(s.redundantJoints.size(), 1u);
  EXPECT_EQ(s.redundantJoints[0], dup);
  ASSERT_FALSE(k.notes().empty());
  // Named as the user sees it (issue 26: "joints[4]" named nothing on the canvas).
  EXPECT_NE(k.notes()[0].text.find("pin coupler.B2 - rocker.B2"), std::string::npos)
      << k.notes()[0].text;
  EXPECT_EQ(jointName(f.m, dup), "pin coupler.B2 - rocker.B2");
  EXPECT_EQ(k.notes()[0].text.find("joints["), std::string::npos) << k.notes()[0].text;
  for (double a : {37.0, 123.0, 290.0}) {
    ASSERT_TRUE(k.moveTo(a).ok());
    ASSERT_TRUE(ref.moveTo(a).ok());
    // Equal to the solver's tolerance (the accuracy target is 1e-9 mm).
    EXPECT_LT((k.position(f.P) - ref.position(plain.P)).norm(), 1e-10);
    EXPECT_LT((k.velocity(f.P) - ref.velocity(plain.P)).norm(), 1e-9);
  }
}

// The classic over-constrained parallelogram: a fifth link parallel to crank and rocker.
struct Parallelogram {
  Mechanism m;
  PointId M;  // coupler point the extra link holds
  JointId extra;
};

Parallelogram parallelogram(double extraOffsetMm) {
  auto f = fourBar(100, 40, 100, 40, 60);
  Parallelogram p;
  p.m = f.m;
  const BodyId link = p.m.addBody("link5");
  const Vec2 A = p.m.point(f.A)->pos;
  const PointId g = p.m.addPoint(p.m.ground()->id, "O5", Vec2(50, 0));
  const PointId l0 = p.m.addPoint(link, "O5", Vec2(50, 0));
  const PointId l1 = p.m.addPoint(link, "M", A + Vec2(50, 0));
  p.M = p.m.addPoint(f.coupler, "M", A + Vec2(50 + extraOffsetMm, 0));
  p.m.addPin(g, l0);
  p.extra = p.m.addPin(l1, p.M);
  return p;
}

TEST(Structure, ParallelogramWithFifthLinkHasMobilityOneWhereGrueblerSaysZero) {
  Parallelogram p = parallelogram(0);
  Kinematics k;
  Status s = k.load(p.m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(k.structure().gruebler, 0);
  EXPECT_EQ(k.structure().mobility, 1);
  ASSERT_EQ(k.structure().redundantJoints.size(), 1u);
  EXPECT_EQ(k.structure().redundantJoints[0], p.extra);
  // It moves, and the redundant link keeps up: its pin holds to rounding all the way.
  for (double a : {10.0, 45.0, 90.0}) {
    ASSERT_TRUE(k.moveTo(a).ok());
    const PointId linkM = *p.m.findPoint("link5.M");
    EXPECT_LT((k.position(linkM) - k.position(p.M)).norm(), 1e-10);
  }
}

TEST(Structure, RedundantJointThatCannotHoldIsConflicting) {
  Parallelogram p = parallelogram(1.0);  // the fifth link is 1 mm off its coupler point
  Kinematics k;
  Status s = k.load(p.m);
  EXPECT_EQ(s.code, StatusCode::Conflicting) << s.message;
  EXPECT_EQ(s.message.find(jointName(p.m, p.extra) + " conflicts"), 0u) << s.message;
  ASSERT_FALSE(s.joints.empty());
  EXPECT_EQ(s.joints[0], p.extra);
  EXPECT_FALSE(k.valid());
}

// A four-bar drawn with every pivot on the x axis: crank O2 A = 20, coupler A B = 30, rocker
// B O4 drawn `rocker` long, frame 100, the rocker's B drawn away from the coupler's. In line the
// rows of the last pin look dependent on the others; they are not anywhere else.
Mechanism inLineFourBar(double rocker) {
  Mechanism m;
  const BodyId g = m.addBody("ground", true), c = m.addBody("crank"), k = m.addBody("coupler"),
               r = m.addBody("rocker");
  const JointId d = m.addPin(m.addPoint(g, "O2", {0, 0}), m.addPoint(c, "O2", {0, 0}));
  m.addPin(m.addPoint(c, "A", {20, 0}), m.addPoint(k, "A", {20, 0}));
  m.addPin(m.addPoint(k, "B", {50, 0}), m.addPoint(r, "B", {100 - rocker, 0}));
  m.addPin(m.addPoint(r, "O4", {100, 0}), m.addPoint(g, "O4", {100, 0}));
  m.driver = Driver{d, 60, Direction::Ccw, 0, ""};
  return m;
}

TEST(Structure, InLineDrawingThatCanCloseAssemblesOffTheLine) {
  const Mechanism m = inLineFourBar(55);
  Kinematics k;
  const Status s = k.load(m);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(k.structure().mobility, 1);
  EXPECT_EQ(k.structure().rank, 8);
  EXPECT_TRUE(k.structure().redundantJoints.empty());
  EXPECT_TRUE(k.assembly().moved);
  // B where the circles |B - A| = 30 about A = (20, 0) and |B - O4| = 55 about O4 = (100, 0)
  // cross: 2 x - 120 = (900 - 3025) / 80.
  const Vec2 B = k.position(*m.findPoint("coupler.B"));
  const double x = (120 + (900.0 - 3025.0) / 80) / 2;
  EXPECT_NEAR(B.x(), x, 1e-9 * x);
  EXPECT_NEAR(std::abs(B.y()), std::sqrt(900 - (x - 20) * (x - 20)), 1e-9 * 14);
  EXPECT_NEAR((k.position(*m.findPoint("rocker.B")) - B).norm(), 0, 1e-9);
  EXPECT_NEAR(k.position(*m.findPoint("crank.A")).y(), 0, 1e-12);  // the crank stays at 0
  // It moves on from there as the four-bar it is, up to its limit.
  ASSERT_TRUE(k.moveTo(30).ok());
  EXPECT_NEAR((k.position(*m.findPoint("rocker.B")) - k.position(*m.findPoint("ground.O4"))).norm(),
              55, 1e-9);
}

TEST(Structure, InLineDrawingTooShortToCloseIsAnAssemblyFailureNotAConflict) {
  Kinematics k;
  const Status s = k.load(inLineFourBar(45));  // 20 + 30 + 45 < 100
  EXPECT_EQ(s.code, StatusCode::AssemblyFailed) << s.message;
  EXPECT_NE(s.message.find("cannot assemble"), std::string::npos) << s.message;
  EXPECT_EQ(s.message.find("conflicts"), std::string::npos) << s.message;
  EXPECT_FALSE(s.joints.empty());
  EXPECT_FALSE(k.valid());
}

TEST(Structure, TriangleCannotBeDriven) {
  // Three binary links pinned in a triangle to the ground: a structure.
  Mechanism m;
  const BodyId g = m.addBody("ground", true), a = m.addBody("a"), b = m.addBody("b");
  const PointId g0 = m.addPoint(g, "O", {0, 0}), g1 = m.addPoint(g, "Q", {50, 0});
  const PointId a0 = m.addPoint(a, "O", {0, 0}), a1 = m.addPoint(a, "C", {20, 30});
  const PointId b0 = m.addPoint(b, "Q", {50, 0}), b1 = m.addPoint(b, "C", {20, 30});
  const JointId d = m.addPin(g0, a0);
  m.addPin(a1, b1);
  m.addPin(b0, g1);
  m.driver = Driver{d, 60, Direction::Ccw, 0, ""};
  Kinematics k;
  Status s = k.load(m);
  EXPECT_EQ(s.code, StatusCode::Locked);
  EXPECT_NE(s.message.find("the driver at pin ground.O - a.O cannot turn"), std::string::npos)
      << s.message;
  EXPECT_NE(s.message.find("no degree of freedom"), std::string::npos) << s.message;
  EXPECT_EQ(k.structure().mobility, 0);
}

TEST(Structure, FiveBarWithOneDriverLeavesAFreedomAndNamesTheBodies) {
  // Ground, crank, two links, a rocker: five bars, two freedoms, one driver.
  Mechanism m;
  const BodyId g = m.addBody("ground", true), c = m.addBody("crank"), l1 = m.addBody("l1"),
               l2 = m.addBody("l2"), r = m.addBody("rocker");
  const Vec2 O(0, 0), A(15, 0), C(40, 40), D(80, 20), Q(90, 0);
  const PointId gO = m.addPoint(g, "O", O), gQ = m.addPoint(g, "Q", Q);
  const PointId cO = m.addPoint(c, "O", O), cA = m.addPoint(c, "A", A);
  const PointId l1A = m.addPoint(l1, "A", A), l1C = m.addPoint(l1, "C", C);
  const PointId l2C = m.addPoint(l2, "C", C), l2D = m.addPoint(l2, "D", D);
  const PointId rD = m.addPoint(r, "D", D), rQ = m.addPoint(r, "Q", Q);
  const JointId drive = m.addPin(gO, cO);
  m.addPin(cA, l1A);
  m.addPin(l1C, l2C);
  m.addPin(l2D, rD);
  m.addPin(rQ, gQ);
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  EXPECT_EQ(k.structure().mobility, 2);
  EXPECT_EQ(k.structure().freeAfterDriver, 1);
  Status s = k.checkDetermined({l1C});
  EXPECT_EQ(s.code, StatusCode::Underconstrained);
  EXPECT_NE(s.message.find("l1.C"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("'l2'"), std::string::npos) << s.message;
  // The crank's own point is determined all the same.
  EXPECT_TRUE(k.checkDetermined({cA}).ok());
}

TEST(Structure, IdleSpinIsHeldAndDoesNotDisturbTheRest) {
  // A roller pinned to the slider block of a slider-crank spins freely: an idle freedom.
  auto sc = sliderCrank(15, 45, 0, 90);
  auto ref = sliderCrank(15, 45, 0, 90);
  const BodyId roller = sc.m.addBody("roller");
  const Vec2 B = sc.m.point(sc.B)->pos;
  const PointId rc = sc.m.addPoint(roller, "C", B);
  const PointId rim = sc.m.addPoint(roller, "rim", B + Vec2(5, 0));
  const PointId sB = sc.m.addPoint(sc.slider, "axle", B);
  sc.m.addPin(sB, rc);
  Kinematics k, kr;
  ASSERT_TRUE(k.load(sc.m).ok());
  ASSERT_TRUE(kr.load(ref.m).ok());
  EXPECT_EQ(k.structure().freeAfterDriver, 1);
  ASSERT_FALSE(k.notes().empty());
  EXPECT_NE(k.notes().back().text.find("'roller'"), std::string::npos) << k.notes().back().text;
  EXPECT_TRUE(k.checkDetermined({rc}).ok());
  EXPECT_EQ(k.checkDetermined({rim}).code, StatusCode::Underconstrained);
  for (double a : {30.0, 200.0}) {
    ASSERT_TRUE(k.moveTo(a).ok());
    ASSERT_TRUE(kr.moveTo(a).ok());
    EXPECT_LT((k.position(rc) - kr.position(ref.B)).norm(), 1e-12);
    EXPECT_LT((k.acceleration(rc) - kr.acceleration(ref.B)).norm(), 1e-9);
  }
}

TEST(Assembly, HandDrawnSketchIsClosedMovingLittleAndKeepingShapes) {
  auto f = fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto exact = f;
  // Draw the rocker's pin 0.3 mm off, as a hand would: the coupler and rocker no longer meet.
  const BodyId rocker = f.rocker;
  for (Point& p : f.m.points)
    if (p.body == rocker && p.name == "B") p.pos += Vec2(0.3, -0.2);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  EXPECT_TRUE(k.assembly().moved);
  EXPECT_GT(k.assembly().maxMove, 0.01);
  EXPECT_LT(k.assembly().maxMove, 1.0);
  ASSERT_FALSE(k.notes().empty());
  EXPECT_NE(k.notes()[0].text.find("does not close"), std::string::npos) << k.notes()[0].text;
  // Joints hold, the crank stays where drawn, and every body keeps its drawn shape.
  const PointId rB = *f.m.findPoint("rocker.B");
  EXPECT_LT((k.position(rB) - k.position(f.B)).norm(), 1e-11);
  const PointId cA = *f.m.findPoint("crank.A");
  EXPECT_LT((k.position(cA) - f.m.point(cA)->pos).norm(), 1e-11);
  const double rockerDrawn = (f.m.point(rB)->pos - f.m.point(f.O4)->pos).norm();
  EXPECT_NEAR((k.position(rB) - k.position(f.O4)).norm(), rockerDrawn, 1e-11);
  // The drawn (open) branch is kept: B stays above the ground line.
  EXPECT_GT(k.position(f.B).y(), 0);
  (void)exact;
}

TEST(Assembly, LinkTooShortToCloseIsReportedWithTheJoint) {
  auto f = fourBar(60, 20, 70, 50, 60);
  for (Point& p : f.m.points)
    if (p.body == f.rocker && p.name == "B") p.pos = Vec2(60, 5);  // rocker now 5 mm long
  Kinematics k;
  Status s = k.load(f.m);
  EXPECT_EQ(s.code, StatusCode::AssemblyFailed);
  EXPECT_NE(s.message.find("cannot assemble"), std::string::npos) << s.message;
  // The joint as the user sees it (issue 26), not its place in the file.
  EXPECT_NE(s.message.find(": pin "), std::string::npos) << s.message;
  EXPECT_EQ(s.message.find("joints["), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("mm open"), std::string::npos) << s.message;
  EXPECT_FALSE(k.valid());
}

TEST(Compile, JointOnOneBodyAndMissingGroundAreBadModels) {
  auto f = fourBar(60, 20, 70, 50, 60);
  Mechanism m = f.m;
  m.joints[1].b = *m.findPoint("crank.O2");
  Kinematics k;
  Status s = k.load(m);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("joints[1]"), std::string::npos) << s.message;
  Mechanism n = f.m;
  n.bodies[0].ground = false;
  EXPECT_EQ(k.load(n).code, StatusCode::BadModel);
}

TEST(Compile, AbsurdSizesAreRefusedWithAReason) {
  auto f = fourBar(60, 20, 70, 50, 60);
  Mechanism huge = f.m, tiny = f.m;
  for (Point& p : huge.points) p.pos *= 1e11;
  for (Point& p : tiny.points) p.pos *= 1e-12;
  Kinematics k;
  Status s = k.load(huge);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("too large"), std::string::npos) << s.message;
  s = k.load(tiny);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("rounding"), std::string::npos) << s.message;
  // 1e4 times larger and 1e-3 times smaller are fine (tests/test_stress.cpp checks accuracy).
  Mechanism big = f.m, small = f.m;
  for (Point& p : big.points) p.pos *= 1e4;
  for (Point& p : small.points) p.pos *= 1e-3;
  EXPECT_TRUE(k.load(big).ok());
  EXPECT_TRUE(k.load(small).ok());
}

// Issue 26: the first ground pivot of a new drawing was refused as "the drawing's extent is
// below 1e-9 of its size": one point has no extent, but nothing moves to be swamped by rounding.
// The ground alone loads; a link whose points all coincide is still refused.
TEST(Compile, TheGroundAloneIsADrawingEvenAsOnePoint) {
  for (const Vec2 at : {Vec2(0, 0), Vec2(25, -40), Vec2(2e11, 0)}) {
    Mechanism m;
    const BodyId g = m.addBody("ground", true);
    m.addPoint(g, "A", at);
    Kinematics k;
    const Status s = k.load(m);
    EXPECT_TRUE(s.ok()) << at.transpose() << ": " << s.message;
    m.addPoint(g, "B", at);  // a second pivot on the first
    EXPECT_TRUE(k.load(m).ok()) << at.transpose();
  }
  Mechanism m;
  const BodyId g = m.addBody("ground", true), l = m.addBody("link");
  m.addPin(m.addPoint(g, "A", Vec2(5, 5)), m.addPoint(l, "A", Vec2(5, 5)));
  m.addPoint(l, "B", Vec2(5, 5));
  Kinematics k;
  const Status s = k.load(m);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("all its points coincide"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace linkage
