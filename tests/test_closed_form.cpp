// The closed-form group solve (closed_form.h) against the general Newton solve of the same
// equations, and which mechanisms it takes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

Kinematics make(const Mechanism& m, bool closedForm) {
  KinematicsOptions o;
  o.closedForm = closedForm;
  Kinematics k(o);
  EXPECT_TRUE(k.load(m).ok());
  return k;
}

// Every body's pose, angular rates and the listed points agree over the sweep.
void expectSameMotion(const Mechanism& m, const std::vector<PointId>& points, double toDeg,
                      const std::string& what) {
  Kinematics fast = make(m, true), slow = make(m, false);
  ASSERT_TRUE(fast.closedForm()) << what;
  ASSERT_FALSE(slow.closedForm());
  for (double a = 0; a <= toDeg; a += 3) {
    ASSERT_TRUE(fast.moveTo(a).ok()) << what << " at " << a;
    ASSERT_TRUE(slow.moveTo(a).ok()) << what << " at " << a;
    EXPECT_LT((fast.q() - slow.q()).cwiseAbs().maxCoeff(), 1e-10) << what << " at " << a;
    EXPECT_LT((fast.dq() - slow.dq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.dq().norm()))
        << what << " at " << a;
    EXPECT_LT((fast.ddq() - slow.ddq()).cwiseAbs().maxCoeff(), 1e-9 * (1 + slow.ddq().norm()))
        << what << " at " << a;
    for (PointId p : points) {
      EXPECT_LT((fast.position(p) - slow.position(p)).norm(), 1e-10) << what;
      EXPECT_LT((fast.acceleration(p) - slow.acceleration(p)).norm(),
                1e-9 * (1 + slow.acceleration(p).norm()))
          << what;
    }
  }
}

TEST(ClosedForm, RandomGrashofFourBarsMatchTheGeneralSolve) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> len(10, 100), ang(0, 360), off(-40, 40);
  int tested = 0;
  while (tested < 25) {
    double r[4] = {len(rng), len(rng), len(rng), len(rng)};
    // Grashof with the crank shortest: the crank turns fully.
    std::sort(r, r + 4);
    if (r[0] + r[3] >= r[1] + r[2] - 1) continue;
    const double crank = r[0];
    std::shuffle(r + 1, r + 4, rng);
    const double d = r[1], coupler = r[2], rocker = r[3];
    const bool open = rng() % 2;
    const Direction dir = rng() % 2 ? Direction::Cw : Direction::Ccw;
    auto f = test::fourBar(d, crank, coupler, rocker, ang(rng), open, off(rng), off(rng), dir);
    expectSameMotion(f.m, {f.P, f.B}, 720, "four-bar #" + std::to_string(tested));
    ++tested;
  }
}

// A drag link (ground shortest): crank, coupler and rocker all turn fully, so every body's
// angle crosses the -x axis many times. The closed-form path keeps rotations and counts whole
// turns by signs only; its angles must equal the general solve's continued angles, forwards
// and backwards, and grow by exactly one turn per crank turn.
TEST(ClosedForm, DragLinkCountsWholeTurnsOfEveryBody) {
  auto f = test::fourBar(20, 50, 60, 55, 30, true, 10, 5);
  expectSameMotion(f.m, {f.P}, 1080, "drag link");
  Kinematics fast = make(f.m, true), slow = make(f.m, false);
  for (double a : {0.0, 200.0, 721.0, 1500.0, -10.0, -800.0, 5.0}) {
    ASSERT_TRUE(fast.moveTo(a).ok()) << a;
    ASSERT_TRUE(slow.moveTo(a).ok()) << a;
    for (BodyId b : {f.crank, f.coupler, f.rocker})
      EXPECT_NEAR(fast.bodyAngle(b), slow.bodyAngle(b), 1e-10) << a;
  }
  Kinematics k = make(f.m, true);
  ASSERT_TRUE(k.moveTo(17).ok());
  const double rocker = k.bodyAngle(f.rocker), coupler = k.bodyAngle(f.coupler);
  ASSERT_TRUE(k.moveTo(17 + 3 * 360).ok());
  EXPECT_NEAR(k.bodyAngle(f.rocker) - rocker, 6 * M_PI, 1e-9);
  EXPECT_NEAR(k.bodyAngle(f.coupler) - coupler, 6 * M_PI, 1e-9);
}

TEST(ClosedFormCoverage, SliderCranksBothKinds) {
  for (bool pinInSlot : {false, true}) {
    auto sc = test::sliderCrank(12, 41, 5, 70, Direction::Cw, 1500, pinInSlot);
    expectSameMotion(sc.m, {sc.B}, 720, pinInSlot ? "pin-in-slot" : "slider block");
  }
}

// A six-bar: a four-bar whose rocker carries a slot, in which a block slides, pinned to a rod
// driven by the coupler. The block's pin and its point on the slot line differ (offset block),
// and the slot turns with the rocker: the RRP group with a moving slot.
TEST(ClosedForm, SixBarWithABlockInASlotOfAMovingRocker) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Mechanism& m = f.m;
  const Vec2 P = m.point(f.P)->pos, O4 = m.point(f.O4)->pos, B = m.point(f.B)->pos;
  const Vec2 along = (B - O4).normalized(), across(-along.y(), along.x());
  // The slot on the rocker, along it; the block rides it 4 mm off its pin.
  const SlotId slot = m.addSlot(f.rocker, "slot", O4, O4 + 80 * along);
  const Vec2 blockOnLine = O4 + 30 * along;
  const Vec2 blockPin = blockOnLine + 4 * across;
  const BodyId rod = m.addBody("rod"), block = m.addBody("block");
  const PointId cP = *m.findPoint("coupler.P");
  const PointId rodP = m.addPoint(rod, "P", P), rodC = m.addPoint(rod, "C", blockPin);
  const PointId blC = m.addPoint(block, "C", blockPin), blQ = m.addPoint(block, "Q", blockOnLine);
  m.addPin(cP, rodP);
  m.addPin(rodC, blC);
  m.addSlider(blQ, slot);
  m.outputs = {blC, blQ};
  expectSameMotion(m, {blC, blQ, f.P}, 720, "six-bar");
}

// The Wanzer triangle held by three slider blocks: a core group (core_group.h), 3 unknowns.
TEST(ClosedForm, WanzerTriadAsACoreGroupMatchesTheGeneralSolve) {
  for (const char* name : {"wanzer-inversion-1", "wanzer-inversion-2"}) {
    LoadResult r =
        loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
    ASSERT_TRUE(r.mechanism) << r.error;
    std::vector<PointId> points;
    for (const Point& p : r.mechanism->points) points.push_back(p.id);
    expectSameMotion(*r.mechanism, points, 1080, name);
  }
}

// A swinging slotted link (PR: pinned to a known body, a known point in its slot): the
// lockstitch machine's feed bar on the feed shaft's lift eccentric, and an inverted slider-crank
// (the crank's pin in a slot of a rocker pinned to the ground, either way round it turns).
TEST(ClosedForm, SlottedLinkMatchesTheGeneralSolve) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/lockstitch-machine.linkage.json");
  ASSERT_TRUE(r.mechanism) << r.error;
  std::vector<PointId> points;
  for (const Point& p : r.mechanism->points) points.push_back(p.id);
  expectSameMotion(*r.mechanism, points, 720, "lockstitch machine");
  for (Direction dir : {Direction::Ccw, Direction::Cw}) {
    Mechanism m;
    const BodyId g = m.addBody("ground", true), crank = m.addBody("crank"),
                 rocker = m.addBody("rocker");
    const JointId drive =
        m.addPin(m.addPoint(g, "O", Vec2(0, 0)), m.addPoint(crank, "O", Vec2(0, 0)));
    const PointId a = m.addPoint(crank, "A", Vec2(20, 0));
    m.addPin(m.addPoint(g, "Q", Vec2(50, 10)), m.addPoint(rocker, "Q", Vec2(50, 10)));
    // The slot through Q and A, as drawn, offset 3 mm from Q's line so that k is not 0.
    const Vec2 d = (Vec2(20, 0) - Vec2(50, 10)).normalized(), off = 3 * perp(d);
    m.addPinInSlot(a, m.addSlot(rocker, "slot", Vec2(50, 10) + off + 10 * d,
                                Vec2(50, 10) + off + 70 * d));
    m.point(a)->pos += off;  // on the slot
    m.driver = Driver{drive, 60, dir, 0, ""};
    expectSameMotion(m, {a}, 720, "inverted slider-crank");
  }
}

TEST(ClosedForm, ChainOfTenFourBarsMatchesTheGeneralSolve) {
  const Mechanism m = test::fourBarChain(10);  // 21 bodies, 63 coordinates
  expectSameMotion(m, {m.outputs[0]}, 720, "chain of 10 four-bars");
}

TEST(ClosedFormCoverage, TakenOnlyWhereTheMechanismDecomposes) {
  // Wanzer-like triads, redundant joints and mechanisms with free freedoms use the general solve.
  auto f = test::fourBar(60, 20, 70, 50, 60);
  const Vec2 B = f.m.point(f.B)->pos;
  Mechanism dup = f.m;
  dup.addPin(dup.addPoint(f.coupler, "B2", B), dup.addPoint(f.rocker, "B2", B));
  EXPECT_FALSE(make(dup, true).closedForm());
  EXPECT_TRUE(make(f.m, true).closedForm());
  Mechanism noDriver = f.m;
  noDriver.driver.reset();
  EXPECT_FALSE(make(noDriver, true).closedForm());
}

TEST(ClosedForm, UnreachableAngleIsExplainedByTheGeneralSolve) {
  auto f = test::fourBar(100, 60, 40, 70, 30);  // non-Grashof: locks 52.819 degrees on
  Kinematics k = make(f.m, true);
  ASSERT_TRUE(k.closedForm());
  Status s = k.moveTo(60);
  EXPECT_EQ(s.code, StatusCode::Unreachable) << s.message;
  EXPECT_NEAR(s.lastReachedDeg.value_or(0), 52.8192, 1e-3);
  // And it still turns back in closed form.
  ASSERT_TRUE(k.moveTo(10).ok());
  Kinematics g = make(f.m, false);
  ASSERT_TRUE(g.moveTo(10).ok());
  EXPECT_LT((k.q() - g.q()).cwiseAbs().maxCoeff(), 1e-10);
}

// Regressions found by review of the state-per-body step; each failed before its fix.

// The plan is checked against a fresh solve, not against what the scratch state held before
// (a stale check dropped the closed-form path, or read past the end of a smaller state).
TEST(Regression, AnEditOrALoadAfterStepsKeepsTheClosedFormPath) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Mechanism more = f.m;
  more.addPoint(f.coupler, "Q", Vec2(10, 10));
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(1).ok());
  ASSERT_TRUE(k.edit(more).ok());
  EXPECT_TRUE(k.closedForm());
  ASSERT_TRUE(k.moveTo(2).ok());
  ASSERT_TRUE(k.load(test::fourBarChain(3)).ok());
  EXPECT_TRUE(k.closedForm());
}

// Whole turns are counted step to step, which needs steps under half a turn whatever
// maxStepDeg says.
TEST(Regression, LargeMaxStepKeepsTheCrankAngle) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  for (double maxStep : {90.0, 181.0, 360.0}) {
    KinematicsOptions fo, so;
    fo.maxStepDeg = so.maxStepDeg = maxStep;
    so.closedForm = false;
    Kinematics fast(fo), slow(so);
    ASSERT_TRUE(fast.load(f.m).ok());
    ASSERT_TRUE(slow.load(f.m).ok());
    for (double deg : {270.0, 500.0, 100.0}) {
      ASSERT_TRUE(fast.moveTo(deg).ok()) << maxStep << " " << deg;
      ASSERT_TRUE(slow.moveTo(deg).ok()) << maxStep << " " << deg;
      for (BodyId b : {f.crank, f.coupler, f.rocker})
        EXPECT_NEAR(fast.bodyAngle(b), slow.bodyAngle(b), 1e-8) << maxStep << " " << deg;
    }
  }
}

// 1e12 degrees is 2.8e9 turns: more than an int counts.
TEST(Regression, HugeAnglesCountTheirTurns) {
  auto f = test::fourBar(20, 50, 60, 55, 30, true, 10, 5);  // a drag link: every body turns
  Kinematics k = make(f.m, true);
  const double deg = 1e12;
  ASSERT_TRUE(k.moveTo(deg).ok());
  EXPECT_NEAR(k.bodyAngle(f.crank) / (deg * M_PI / 180), 1, 1e-12);
}

// A parallelogram first loop crossed from many start angles: the tracker must stop at the change
// point every time, never carry on along the other branch. Next to it the computed
// accelerations grow without bound and could excuse a jump made in tiny steps; positions that
// close to singular are no longer bases (Kinematics::tryStep).
TEST(Regression, AChangePointIsNeverCrossedSilentlyWhateverTheStart) {
  for (int loops : {3, 4}) {
    const Mechanism m = test::fourBarChain(loops, 25, 60, 25);
    const BodyId coupler0 = m.bodyNamed("coupler0")->id;
    for (double start = -50; start > -57.25; start -= 0.137) {
      for (bool closedForm : {true, false}) {
        Kinematics k = make(m, closedForm);
        ASSERT_TRUE(k.moveTo(start).ok());
        const Status s = k.moveTo(-70);
        EXPECT_EQ(s.code, StatusCode::Singular)
            << loops << " loops from " << start << (closedForm ? ", closed form" : "");
        EXPECT_NEAR(k.bodyAngle(coupler0), 0, 1e-6)
            << loops << " loops from " << start << (closedForm ? ", closed form" : "");
      }
    }
  }
}

}  // namespace
}  // namespace linkage
