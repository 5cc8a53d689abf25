// What a canvas asks of the kinematics to draw the mechanism where it is: each body's rigid
// motion from the drawing (bodyTransform), world and sketch coordinates both ways, slot ends
// now; and the ids that notes and the structure report carry, for it to highlight.
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

constexpr double kDeg = M_PI / 180;

Vec2 rotated(const Vec2& p, double rad) {
  return Vec2(std::cos(rad) * p.x() - std::sin(rad) * p.y(),
              std::sin(rad) * p.x() + std::cos(rad) * p.y());
}

TEST(DrawingQueries, BodyTransformsMapTheDrawingToThePose) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const double L = k.size();
  for (double deg : {0.0, 37.0, 150.0, 299.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    // The crank turns about O2 = (0, 0) by the crank angle: the closed form.
    const Transform crank = k.bodyTransform(f.crank);
    EXPECT_NEAR(crank.R.angle(), std::remainder(deg * kDeg, 2 * M_PI), 1e-12);
    EXPECT_LT(crank.t.norm(), 1e-12 * L);
    // Every point of every body where the transform of its body puts its drawn position, and
    // back; the ground where it is drawn.
    EXPECT_EQ(k.bodyTransform(f.ground).R.c, 1);
    EXPECT_EQ(k.bodyTransform(f.ground).t, Vec2::Zero());
    for (const Point& p : f.m.points) {
      const Vec2 now = k.position(p.id);
      EXPECT_LT((k.toWorld(p.body, p.pos) - now).norm(), 1e-12 * L) << f.m.pointLabel(p.id);
      EXPECT_LT((k.toSketch(p.body, now) - p.pos).norm(), 1e-12 * L) << f.m.pointLabel(p.id);
      const Transform T = k.bodyTransform(p.body);
      EXPECT_NEAR(T.R.c * T.R.c + T.R.s * T.R.s, 1, 1e-15);
      EXPECT_NEAR(T.R.angle(), std::remainder(k.bodyAngle(p.body), 2 * M_PI), 1e-12);
    }
  }
}

TEST(DrawingQueries, SlotEndsWhereTheirBodyIs) {
  // The Wanzer's disk turns clockwise about the origin: its slots' ends are the drawn ones
  // turned by minus the crank angle; the ground's slot stays where it is drawn.
  const Mechanism m = test::example("wanzer-inversion-2");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  for (double deg : {0.0, 45.0, 200.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    for (const Slot& s : m.slots) {
      const Kinematics::Segment now = k.slotEnds(s.id);
      const bool ground = m.body(s.body)->ground;
      const double turn = ground ? 0 : -deg * kDeg;
      EXPECT_LT((now.p0 - rotated(s.p0, turn)).norm(), 1e-12 * k.size()) << m.slotLabel(s.id);
      EXPECT_LT((now.p1 - rotated(s.p1, turn)).norm(), 1e-12 * k.size()) << m.slotLabel(s.id);
      if (ground) EXPECT_EQ(now.p0, s.p0);
    }
  }
}

TEST(DrawingQueries, NotesAndTheStructureCarryIds) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  // A pin said twice (redundant), a flap hung from the ground by one pin (free, held), and the
  // rocker drawn 0.2 mm off its pivot (assembled, moved).
  const Vec2 B = f.m.point(f.B)->pos;
  const JointId dup = f.m.addPin(f.m.addPoint(f.coupler, "B2", B), f.m.addPoint(f.rocker, "B2", B));
  const BodyId flap = f.m.addBody("flap");
  f.m.addPin(f.m.addPoint(f.ground, "H", {-20, 0}), f.m.addPoint(flap, "H", {-20, 0}));
  f.m.addPoint(flap, "T", {-20, -10});
  f.m.point(*f.m.findPoint("ground.O4"))->pos += Vec2(0.2, 0);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  const StructureReport s = k.structure();
  EXPECT_EQ(s.redundantJoints, std::vector<JointId>{dup});
  EXPECT_EQ(s.freeBodies, std::vector<BodyId>{flap});
  bool redundant = false, held = false, moved = false;
  for (const Note& n : k.notes()) {
    switch (n.kind) {
      case Note::Kind::RedundantJoints:
        redundant = true;
        EXPECT_EQ(n.joints, std::vector<JointId>{dup});
        break;
      case Note::Kind::FreedomsHeld:
        held = true;
        EXPECT_EQ(n.bodies, std::vector<BodyId>{flap});
        break;
      case Note::Kind::AssemblyMoved:
        moved = true;
        ASSERT_EQ(n.bodies.size(), 1u);
        EXPECT_EQ(n.bodies[0], k.assembly().body);
        EXPECT_TRUE(k.contains(n.bodies[0]));
        break;
      case Note::Kind::CrankMoved:
        ADD_FAILURE() << n.text;
        break;
    }
  }
  EXPECT_TRUE(redundant && held && moved);
}

}  // namespace
}  // namespace linkage
