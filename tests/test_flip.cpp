// Branch flip (Kinematics::flipBranch): a dyad or core group put on its other assembly equals
// the mirror closed form (the other intersection of the four-bar's two circles, of the
// slider-crank's circle and line), the groups downstream keep their own branches, the design
// redrawn on the new branch loads to the same motion, and what has no mirror is refused.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "four_bar_reference.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

// Every point of m moves alike in a and b (a's accelerations against b's where both have them).
void expectSameMotion(Kinematics& a, Kinematics& b, const Mechanism& m,
                      std::initializer_list<double> angles, const char* what) {
  const double L = a.size(), w = a.omega();
  for (double deg : angles) {
    ASSERT_TRUE(a.moveTo(deg).ok()) << what << " at " << deg;
    ASSERT_TRUE(b.moveTo(deg).ok()) << what << " at " << deg;
    for (const Point& p : m.points) {
      const Kinematics::PointMotion x = a.motion(p.id), y = b.motion(p.id);
      EXPECT_LT((x.position - y.position).norm(), 1e-9 * L) << what << " " << m.pointLabel(p.id);
      EXPECT_LT((x.velocity - y.velocity).norm(), 1e-9 * L * w) << what << " at " << deg;
      EXPECT_LT((x.acceleration - y.acceleration).norm(), 1e-9 * L * w * w)
          << what << " at " << deg;
    }
  }
}

// The flipped kinematics and a fresh load of the redrawn design, by the closed form and by the
// general solve.
void expectRedrawnMovesAlike(Kinematics& flipped, const Mechanism& redrawn,
                             std::initializer_list<double> angles) {
  for (bool closedForm : {true, false}) {
    KinematicsOptions opt;
    opt.closedForm = closedForm;
    Kinematics loaded(opt);
    const Status s = loaded.load(redrawn);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_FALSE(loaded.assembly().moved);  // drawn closed
    expectSameMotion(flipped, loaded, redrawn, angles,
                     closedForm ? "redrawn, closed form" : "redrawn, general solve");
  }
}

TEST(Flip, FourBarGoesToTheOtherIntersectionOfItsCircles) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  for (double at : {0.0, 75.0, 200.0, 330.0}) {
    Kinematics k;
    ASSERT_TRUE(k.load(f.m).ok());
    ASSERT_TRUE(k.moveTo(at).ok());
    const PointId onCrank = *f.m.findPoint("crank.A");
    const Vec2 crankA = k.position(onCrank);
    Mechanism redrawn;
    const Status s = k.flipBranch(f.coupler, &redrawn);
    ASSERT_TRUE(s.ok()) << s.message;
    EXPECT_EQ(k.crankDeg(), at);
    EXPECT_EQ(k.position(onCrank), crankA);  // the crank does not move
    // The crossed closed form, here and along the motion.
    const auto crossed = test::fourBarReference(60, 20, 70, 50, 60, false, 35, 25, k.omega());
    const double L = k.size(), w = k.omega();
    for (double deg : {at, at + 50, at + 180, at - 90}) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const auto r = linkref::four_bar(crossed, deg * kDeg);
      EXPECT_LT((k.position(f.B) - Vec2(r.B.x, r.B.y)).norm(), 1e-9 * L) << at << " " << deg;
      EXPECT_LT((k.position(f.P) - Vec2(r.P.x, r.P.y)).norm(), 1e-9 * L) << at << " " << deg;
      EXPECT_LT((k.velocity(f.P) - Vec2(r.vP.x, r.vP.y)).norm(), 1e-9 * L * w) << deg;
      EXPECT_LT((k.acceleration(f.P) - Vec2(r.aP.x, r.aP.y)).norm(), 1e-9 * L * w * w) << deg;
      EXPECT_NEAR(k.bodyOmega(f.rocker), r.w4, 1e-9 * w);
    }
    // The redrawn design: the crank and the ground as drawn, to the bit; coupler and rocker
    // where the crossed branch has them at the drawing's crank angle.
    ASSERT_TRUE(k.moveTo(at).ok());
    for (const Point& p : redrawn.points) {
      const Point* before = f.m.point(p.id);
      ASSERT_NE(before, nullptr);
      if (p.body == f.ground || p.body == f.crank) EXPECT_EQ(p.pos, before->pos);
    }
    const auto drawn = linkref::four_bar(crossed, 0.0);
    EXPECT_LT((redrawn.point(f.B)->pos - Vec2(drawn.B.x, drawn.B.y)).norm(), 1e-12 * L);
    EXPECT_LT((redrawn.point(f.P)->pos - Vec2(drawn.P.x, drawn.P.y)).norm(), 1e-12 * L);
    EXPECT_EQ(mechanismDifference(redrawn, f.m).empty(), false);
    expectRedrawnMovesAlike(k, redrawn, {at, at + 120, at + 240});
  }
}

TEST(Flip, RedrawnAtTheDrawingsDriverAngleWhateverTheStartOffset) {
  // Crank angle 0 is the drawing turned by start_deg: the redrawn design is drawn at the
  // drawing's driver angle (crank angle -start_deg), keeps the offset, and moves alike. Here by
  // a clockwise driver.
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25, Direction::Cw);
  f.m.driver->startDeg = 25;
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(40).ok());
  Mechanism redrawn;
  const Status s = k.flipBranch(f.rocker, &redrawn);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(redrawn.driver->startDeg, 25);
  // The crossed closed form at the drawn crank (60 degrees): the redrawn B.
  const auto crossed = test::fourBarReference(60, 20, 70, 50, 60, false, 35, 25);
  const auto drawn = linkref::four_bar(crossed, 0.0);
  EXPECT_LT((redrawn.point(f.B)->pos - Vec2(drawn.B.x, drawn.B.y)).norm(), 1e-12 * k.size());
  expectRedrawnMovesAlike(k, redrawn, {40, -25, 100, 250});
}

TEST(Flip, ByAnyBodyOrJointOfTheDyadAndBackAgain) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k, byRocker, byJoint, twice;
  for (Kinematics* x : {&k, &byRocker, &byJoint, &twice}) {
    ASSERT_TRUE(x->load(f.m).ok());
    ASSERT_TRUE(x->moveTo(123).ok());
  }
  EXPECT_EQ(k.flippableBodies(), (std::vector<BodyId>{f.coupler, f.rocker}));
  const std::uint64_t revision = k.revision();
  ASSERT_TRUE(k.flipBranch(f.coupler).ok());
  ASSERT_TRUE(byRocker.flipBranch(f.rocker).ok());
  ASSERT_TRUE(byJoint.flipBranch(f.pinB).ok());  // the joint between the dyad's two links
  for (const Point& p : f.m.points) {
    EXPECT_EQ(byRocker.position(p.id), k.position(p.id));
    EXPECT_EQ(byJoint.position(p.id), k.position(p.id));
  }
  ASSERT_TRUE(twice.flipBranch(f.coupler).ok());
  ASSERT_TRUE(twice.flipBranch(f.pinO4).ok());
  Kinematics plain;
  ASSERT_TRUE(plain.load(f.m).ok());
  expectSameMotion(twice, plain, f.m, {123, 200, 10}, "flipped twice");
  // The revision stays: the mechanism has not changed, derived objects remain valid.
  EXPECT_EQ(k.revision(), revision);
  // No mirror: the crank, the driver's joint, the ground.
  EXPECT_EQ(k.flipBranch(f.crank).code, StatusCode::BadModel);
  EXPECT_EQ(k.flipBranch(f.drive).code, StatusCode::BadModel);
  EXPECT_EQ(k.flipBranch(f.ground).code, StatusCode::BadModel);
}

TEST(Flip, EditsAndDragsKeepTheFlippedBranch) {
  // An edit starts from the pose, so it stays on the flipped branch: of dimensions (re-solved
  // in place) and of topology (a point added: solved whole from the pose).
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto crossedAt = [&](const Kinematics& k) {
    const Vec2 A = k.position(f.A), B = k.position(f.B), O4 = k.position(f.O4);
    return cross(O4 - A, B - A) < 0;
  };
  Mechanism longer = f.m;  // the design as drawn (open), with a longer rocker
  for (Point& p : longer.points)
    if (p.name == "O4") p.pos += Vec2(2, 0);
  Mechanism more = f.m;
  more.addPoint(f.coupler, "Q", Vec2(10, 10));
  for (const Mechanism* edited : {&longer, &more}) {
    Kinematics k;
    ASSERT_TRUE(k.load(f.m).ok());
    ASSERT_TRUE(k.moveTo(40).ok());
    ASSERT_TRUE(k.flipBranch(f.coupler).ok());
    ASSERT_TRUE(crossedAt(k));
    ASSERT_TRUE(k.edit(*edited).ok());
    EXPECT_EQ(k.lastEditGroups() >= 0, edited == &longer);
    EXPECT_TRUE(crossedAt(k));
    for (double deg : {100.0, 250.0}) {
      ASSERT_TRUE(k.dragTo(f.P, k.position(f.P) + Vec2(3, -2)).status.ok());
      ASSERT_TRUE(k.moveTo(deg).ok());
      EXPECT_TRUE(crossedAt(k)) << deg;
    }
  }
}

TEST(Flip, SliderCrankBlockGoesToTheOtherSideOfTheCrank) {
  // RRP (block in a ground slot) and RP (the rod's end in the slot): B on the line x = e at
  // A.y - sqrt(l^2 - (e - A.x)^2) instead of + (the other intersection of circle and line).
  const double r = 20, l = 60, e = 5, drawn = 30;
  for (bool pinInSlot : {false, true}) {
    auto s = test::sliderCrank(r, l, e, drawn, Direction::Ccw, 60, pinInSlot);
    Kinematics k;
    ASSERT_TRUE(k.load(s.m).ok());
    ASSERT_TRUE(k.moveTo(100).ok());
    EXPECT_EQ(k.flippableBodies().size(), pinInSlot ? 1u : 2u);
    Mechanism redrawn;
    const Status st = k.flipBranch(s.rod, &redrawn);
    ASSERT_TRUE(st.ok()) << st.message;
    const double w = k.omega(), L = k.size();
    for (double deg : {100.0, 170.0, 260.0, 20.0}) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
      const double t = (drawn + deg) * kDeg;
      const Vec2 A = r * Vec2(std::cos(t), std::sin(t)), dA = r * Vec2(-std::sin(t), std::cos(t));
      const double root = std::sqrt(l * l - (e - A.x()) * (e - A.x()));
      const Vec2 B(e, A.y() - root);
      const double vy = dA.y() - (e - A.x()) * dA.x() / root;
      EXPECT_LT((k.position(s.B) - B).norm(), 1e-9 * L) << pinInSlot << " " << deg;
      EXPECT_LT((k.velocity(s.B) - Vec2(0, w * vy)).norm(), 1e-9 * L * w) << deg;
    }
    expectRedrawnMovesAlike(k, redrawn, {100, 200, 300});
  }
}

TEST(Flip, DownstreamLoopsKeepTheirOwnBranches) {
  // A chain of four-bars: flipping loop 2 crosses it; loops 0 and 1 do not move at all, loops 3
  // and 4 are re-solved on their own (open) branches from the crossed loop's new output.
  const Mechanism m = test::fourBarChain(5);
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.moveTo(70).ok());
  std::vector<Vec2> before;
  for (const Point& p : m.points) before.push_back(k.position(p.id));
  Mechanism redrawn;
  const Status s = k.flipBranch(m.bodyNamed("rocker2")->id, &redrawn);
  ASSERT_TRUE(s.ok()) << s.message;
  auto open = [&](int loop) {  // B to the left of A -> O4
    const std::string n = std::to_string(loop);
    const Vec2 A = k.position(*m.findPoint("coupler" + n + ".A"));
    const Vec2 B = k.position(*m.findPoint("coupler" + n + ".B"));
    const Vec2 O4 = k.position(*m.findPoint("rocker" + n + ".O4"));
    return cross(O4 - A, B - A) > 0;
  };
  for (size_t i = 0; i < m.points.size(); ++i) {
    const std::string body = m.body(m.points[i].body)->name;
    if (body == "ground" || body == "crank" || body.back() == '0' || body.back() == '1')
      EXPECT_EQ(k.position(m.points[i].id), before[i]) << m.pointLabel(m.points[i].id);
  }
  for (double deg : {70.0, 160.0, 290.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    EXPECT_TRUE(open(0) && open(1) && open(3) && open(4)) << deg;
    EXPECT_FALSE(open(2)) << deg;
  }
  // Only the bodies that moved are redrawn; the others keep their coordinates to the bit.
  for (const Point& p : redrawn.points) {
    const std::string body = redrawn.body(p.body)->name;
    const bool upstream = body == "crank" || body == "ground" || body == "coupler0" ||
                          body == "rocker0" || body == "coupler1" || body == "rocker1";
    if (upstream) EXPECT_EQ(p.pos, m.point(p.id)->pos) << redrawn.pointLabel(p.id);
    if (body == "coupler2") EXPECT_NE(p.pos, m.point(p.id)->pos) << redrawn.pointLabel(p.id);
  }
  expectRedrawnMovesAlike(k, redrawn, {70, 150, 300});
}

TEST(Flip, TheWanzerTriangleGoesToTheOtherRootOfItsCoreGroup) {
  // The triangle is held by three blocks (one core group): its pose is where a line in
  // (x, y, cos, sin) meets the unit circle, twice. The other root: every joint still holds (the
  // blocks on their slots, the needle on its line), the needle elsewhere, and the redrawn design
  // moves alike by the general solve.
  const Mechanism m = test::example("wanzer-inversion-2");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.closedForm());
  const BodyId triangle = m.bodyNamed("triangle")->id;
  EXPECT_EQ(k.flippableBodies().size(), 4u);  // the triangle and its three blocks
  const PointId G = *m.findPoint("needlebar.G");
  const Vec2 before = k.position(G);
  Mechanism redrawn;
  const Status s = k.flipBranch(triangle, &redrawn);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT((k.position(G) - before).norm(), 1.0);
  const double L = k.size();
  for (double deg : {0.0, 90.0, 200.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    for (const Joint& j : m.joints) {
      if (j.type == JointType::Pin) {
        EXPECT_LT((k.position(j.a) - k.position(j.b)).norm(), 1e-10 * L) << jointLabel(m, j.id);
      } else {
        const Kinematics::Segment slot = k.slotEnds(j.slot);
        const Vec2 d = (slot.p1 - slot.p0).normalized();
        EXPECT_LT(std::abs(cross(d, k.position(j.a) - slot.p0)), 1e-10 * L) << jointLabel(m, j.id);
        const BodyId block = m.point(j.a)->body, slotBody = m.slot(j.slot)->body;
        EXPECT_NEAR(k.bodyAngle(block), k.bodyAngle(slotBody), 1e-12) << jointLabel(m, j.id);
      }
    }
  }
  expectRedrawnMovesAlike(k, redrawn, {0, 90, 200, 300});
}

// The lockstitch machine's feed bar (a swinging slotted link, PR): flipped, its slot's normal is
// the other root of N . D = k: the bar is mirrored about the line from its pin to the lift
// eccentric, its pin and the eccentric in its fork still hold, and the redrawn design moves
// alike by the general solve.
TEST(Flip, TheFeedBarGoesToTheOtherRootOfItsSlot) {
  const Mechanism m = test::example("lockstitch-machine");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  ASSERT_TRUE(k.closedForm());
  const PointId T = *m.findPoint("feedbar.T");
  const Vec2 before = k.position(T);
  Mechanism redrawn;
  const Status s = k.flipBranch(m.bodyNamed("feedbar")->id, &redrawn);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT((k.position(T) - before).norm(), 1.0);
  const double L = k.size();
  for (double deg : {0.0, 120.0, 250.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok()) << deg;
    for (const Joint& j : m.joints)
      if (j.type == JointType::Pin)
        EXPECT_LT((k.position(j.a) - k.position(j.b)).norm(), 1e-10 * L) << jointLabel(m, j.id);
    const Joint& fork = m.joints[15];
    const Kinematics::Segment slot = k.slotEnds(fork.slot);
    const Vec2 d = (slot.p1 - slot.p0).normalized();
    EXPECT_LT(std::abs(cross(d, k.position(fork.a) - slot.p0)), 1e-10 * L);
  }
  expectRedrawnMovesAlike(k, redrawn, {0, 90, 200, 300});
}

TEST(Flip, RefusedWhereThereIsNoMirrorAndNothingChanges) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  // The general solve knows no mirror assembly.
  KinematicsOptions general;
  general.closedForm = false;
  Kinematics g(general);
  ASSERT_TRUE(g.load(f.m).ok());
  EXPECT_TRUE(g.flippableBodies().empty());
  Status s = g.flipBranch(f.coupler);
  EXPECT_EQ(s.code, StatusCode::BadModel);
  EXPECT_NE(s.message.find("general solve"), std::string::npos) << s.message;
  // Nor a chain of triads, which does not decompose.
  Kinematics t;
  const Mechanism triads = test::triadChain(2);
  ASSERT_TRUE(t.load(triads).ok());
  EXPECT_FALSE(t.closedForm());
  EXPECT_TRUE(t.flippableBodies().empty());
  EXPECT_EQ(t.flipBranch(triads.bodyNamed("triangle0")->id).code, StatusCode::BadModel);

  // At a parallelogram's change point the two assemblies meet: nothing to flip to.
  auto p = test::fourBar(60, 25, 60, 25, 30);
  Kinematics k;
  ASSERT_TRUE(k.load(p.m).ok());
  ASSERT_TRUE(k.moveTo(-29).ok());
  ASSERT_EQ(k.moveTo(-30).code, StatusCode::Singular);
  const Vec2 B = k.position(p.B);
  Mechanism redrawn = p.m;
  s = k.flipBranch(p.coupler, &redrawn);
  EXPECT_EQ(s.code, StatusCode::Singular) << s.message;
  EXPECT_EQ(k.position(p.B), B);
  EXPECT_EQ(serializeMechanism(redrawn), serializeMechanism(p.m));
  Kinematics none;
  EXPECT_EQ(none.flipBranch(p.coupler).code, StatusCode::BadModel);
}

}  // namespace
}  // namespace linkage
