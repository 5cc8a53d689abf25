// The structure as a designer reads it: Assur groups from the ground outwards, and Grashof's
// class of every four-bar loop against the independent reference (tests/reference/four_bar.h).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "examples.h"
#include "linkage/grashof.h"
#include "linkage/groups.h"
#include "linkage/io/model_file.h"
#include "mechanisms.h"
#include "reference/four_bar.h"

namespace linkage {
namespace {

using test::example;

std::string names(const Mechanism& m, const std::vector<BodyId>& bodies) {
  std::string s;
  for (BodyId b : bodies) s += (s.empty() ? "" : ",") + m.body(b)->name;
  return s;
}

GrashofClass expected(linkref::Grashof g) {
  switch (g) {
    case linkref::Grashof::kCrankRocker:
      return GrashofClass::CrankRocker;
    case linkref::Grashof::kDoubleCrank:
      return GrashofClass::DoubleCrank;
    case linkref::Grashof::kDoubleRocker:
      return GrashofClass::GrashofDoubleRocker;
    case linkref::Grashof::kRockerCrank:
      return GrashofClass::RockerCrank;
    case linkref::Grashof::kChangePoint:
      return GrashofClass::ChangePoint;
    case linkref::Grashof::kTripleRocker:
      return GrashofClass::NonGrashofDoubleRocker;
  }
  return GrashofClass::ChangePoint;
}

TEST(AssurGroups, TheNeedleMechanismIsTheGroupsOfThePaper) {
  // Seed 001: crank 1, then groups 2-3 and 4-5 (RRR) and 6-7 (a rod driving a slider block).
  const Mechanism m = example("needle-876-alpha-0");
  const AssurDecomposition d = decomposeAssur(m);
  ASSERT_EQ(d.groups.size(), 4u);
  EXPECT_TRUE(d.unresolved.empty());
  EXPECT_EQ(d.groups[0].kind, AssurGroup::Kind::Crank);
  EXPECT_EQ(names(m, d.groups[0].bodies), "crank");
  EXPECT_EQ(d.groups[1].kind, AssurGroup::Kind::RRR);
  EXPECT_EQ(names(m, d.groups[1].bodies), "coupler,lever");
  // Outer pin of the coupler (A), middle pin (B), outer pin of the lever (C).
  EXPECT_EQ(d.groups[1].joints,
            (std::vector<JointId>{m.joints[1].id, m.joints[2].id, m.joints[3].id}));
  EXPECT_EQ(d.groups[2].kind, AssurGroup::Kind::RRR);
  EXPECT_EQ(names(m, d.groups[2].bodies), "link,rocker");
  EXPECT_EQ(d.groups[2].joints,
            (std::vector<JointId>{m.joints[4].id, m.joints[5].id, m.joints[6].id}));
  EXPECT_EQ(d.groups[3].kind, AssurGroup::Kind::RRP);
  EXPECT_EQ(names(m, d.groups[3].bodies), "rod,needlebar");
  EXPECT_EQ(d.groups[3].joints,
            (std::vector<JointId>{m.joints[7].id, m.joints[8].id, m.joints[9].id}));
  EXPECT_EQ(d.groupOf(m.ground()->id), -1);
  EXPECT_EQ(d.groupOf(m.bodies[7].id), 3);
}

TEST(AssurGroups, TriadsSlotsAndUnreachedBodies) {
  // Wanzer: the triangle and its three blocks are one class-III group of four bodies, the
  // triangle (its core) first.
  Mechanism w = example("wanzer-inversion-2");
  AssurDecomposition d = decomposeAssur(w);
  ASSERT_EQ(d.groups.size(), 2u);
  EXPECT_EQ(d.groups[1].kind, AssurGroup::Kind::Triad);
  ASSERT_EQ(d.groups[1].bodies.size(), 4u);
  EXPECT_EQ(d.groups[1].bodies[0], w.bodyNamed("triangle")->id);
  EXPECT_TRUE(d.unresolved.empty());
  // A rod whose end runs in a ground slot: RP.
  test::SliderCrank s = test::sliderCrank(15, 50, 5, 30, Direction::Ccw, 60, true);
  d = decomposeAssur(s.m);
  ASSERT_EQ(d.groups.size(), 2u);
  EXPECT_EQ(d.groups[1].kind, AssurGroup::Kind::RP);
  // A body hung on one pin is reached by nothing: unresolved, not guessed.
  const BodyId loose = w.addBody("loose");
  w.addPin(w.addPoint(loose, "P", Vec2(50, 50)), w.addPoint(w.ground()->id, "P", Vec2(50, 50)));
  d = decomposeAssur(w);
  EXPECT_EQ(d.unresolved, std::vector<BodyId>{loose});
  EXPECT_EQ(d.groupOf(loose), 2);
}

TEST(Grashof, ClassesMatchTheReferenceForRandomLengths) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> len(1, 100);
  for (int i = 0; i < 20000; ++i) {
    const double r1 = len(rng), r2 = len(rng), r3 = len(rng), r4 = len(rng);
    ASSERT_EQ(grashofClass(r1, r2, r3, r4), expected(linkref::grashof_class(r1, r2, r3, r4)))
        << r1 << " " << r2 << " " << r3 << " " << r4;
  }
  // Change points, exactly and within the tolerance of a drawing's rounding.
  EXPECT_EQ(grashofClass(60, 20, 60, 20), GrashofClass::ChangePoint);
  EXPECT_EQ(grashofClass(60, 20, 60, 20 * (1 + 1e-12)), GrashofClass::ChangePoint);
  // Just off it: 20 + 60 < 20.001 + 60, and 20 + 60.001 > 20 + 60.
  EXPECT_EQ(grashofClass(60, 20, 60, 20.001), GrashofClass::CrankRocker);
  EXPECT_EQ(grashofClass(60, 20, 60.001, 20), GrashofClass::NonGrashofDoubleRocker);
}

TEST(Grashof, LoopsAreFoundWithFrameAndInputFromTheStructure) {
  struct Case {
    double d, r2, r3, r4;
    GrashofClass kind;
  };
  for (const Case& c : {Case{60, 20, 70, 50, GrashofClass::CrankRocker},
                        Case{20, 60, 70, 50, GrashofClass::DoubleCrank},
                        Case{60, 50, 20, 55, GrashofClass::GrashofDoubleRocker},
                        Case{60, 50, 70, 20, GrashofClass::RockerCrank},
                        Case{60, 40, 50, 45, GrashofClass::NonGrashofDoubleRocker},
                        Case{60, 20, 60, 20, GrashofClass::ChangePoint}}) {
    test::FourBar f = test::fourBar(c.d, c.r2, c.r3, c.r4, 70);
    const std::vector<FourBarLoop> loops = fourBarLoops(f.m);
    ASSERT_EQ(loops.size(), 1u) << c.d << " " << c.r2 << " " << c.r3 << " " << c.r4;
    const FourBarLoop& l = loops[0];
    EXPECT_EQ(l.bodies, (std::array<BodyId, 4>{f.ground, f.crank, f.coupler, f.rocker}));
    EXPECT_EQ(l.joints, (std::array<JointId, 4>{f.drive, f.pinA, f.pinB, f.pinO4}));
    EXPECT_NEAR(l.lengths[0], c.d, 1e-12);
    EXPECT_NEAR(l.lengths[1], c.r2, 1e-12);
    EXPECT_NEAR(l.lengths[2], c.r3, 1e-12);
    EXPECT_NEAR(l.lengths[3], c.r4, 1e-12);
    EXPECT_EQ(l.kind, c.kind);
  }
  // Watt II: the second loop's frame is the ground and its input the first loop's rocker.
  test::WattSixBar w = test::wattSixBar();
  const std::vector<FourBarLoop> loops = fourBarLoops(w.m);
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(loops[0].bodies[1], w.crank);
  EXPECT_EQ(w.m.body(loops[1].bodies[1])->name, "rocker");
  EXPECT_EQ(loops[1].bodies[3], w.output);
  // Sliders make no four-bar loop.
  EXPECT_TRUE(fourBarLoops(example("wanzer-inversion-2")).empty());
  EXPECT_TRUE(fourBarLoops(test::sliderCrank(15, 50, 0, 30).m).empty());
}

TEST(Grashof, TheNeedleMechanismsLoops) {
  for (int alpha : {0, 35}) {
    const Mechanism m = example("needle-876-alpha-" + std::to_string(alpha));
    const std::vector<FourBarLoop> loops = fourBarLoops(m);
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(names(m, {loops[0].bodies.begin(), loops[0].bodies.end()}),
              "ground,crank,coupler,lever");
    EXPECT_EQ(loops[0].kind, GrashofClass::CrankRocker);
    EXPECT_NEAR(loops[0].lengths[0], std::hypot(18.0, 175.0), 1e-12);
    EXPECT_EQ(names(m, {loops[1].bodies.begin(), loops[1].bodies.end()}),
              "ground,lever,link,rocker");
    // CF 37.9446 at alpha = 0: 17 + 37.9446 < 30 + 25 by 0.055 mm, close to a change point.
    EXPECT_EQ(loops[1].kind, GrashofClass::CrankRocker);
    if (alpha == 0) EXPECT_NEAR(loops[1].margin, 55 - 17 - 37.944600683558, 1e-9);
  }
}

}  // namespace
}  // namespace linkage
