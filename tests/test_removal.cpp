// Removal and its undo (Mechanism::remove, restore): what a removal takes along, and that the
// undo gives back the same mechanism (the same file, the same ids in the same places) and the
// same motion.
#include <gtest/gtest.h>

#include <algorithm>

#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

// Every entity with its id in its place, and the file they make.
void expectIdentical(const Mechanism& a, const Mechanism& b) {
  EXPECT_EQ(serializeMechanism(a), serializeMechanism(b));
  EXPECT_EQ(mechanismDifference(a, b), "");
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (size_t i = 0; i < a.bodies.size(); ++i) EXPECT_EQ(a.bodies[i].id, b.bodies[i].id) << i;
  ASSERT_EQ(a.points.size(), b.points.size());
  for (size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].id, b.points[i].id) << i;
    EXPECT_EQ(a.points[i].body, b.points[i].body) << i;
  }
  ASSERT_EQ(a.slots.size(), b.slots.size());
  for (size_t i = 0; i < a.slots.size(); ++i) EXPECT_EQ(a.slots[i].id, b.slots[i].id) << i;
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (size_t i = 0; i < a.joints.size(); ++i) {
    EXPECT_EQ(a.joints[i].id, b.joints[i].id) << i;
    EXPECT_EQ(a.joints[i].a, b.joints[i].a) << i;
    EXPECT_EQ(a.joints[i].b, b.joints[i].b) << i;
    EXPECT_EQ(a.joints[i].slot, b.joints[i].slot) << i;
  }
  EXPECT_EQ(a.outputs, b.outputs);
  ASSERT_EQ(a.driver.has_value(), b.driver.has_value());
  if (a.driver) EXPECT_EQ(a.driver->joint, b.driver->joint);
}

// The same positions, velocities and accelerations of every point at each angle: the same
// computation on the same input, so equal to the last bit.
void expectSameMotion(const Mechanism& a, const Mechanism& b) {
  Kinematics ka, kb;
  ASSERT_TRUE(ka.load(a).ok());
  ASSERT_TRUE(kb.load(b).ok());
  for (double deg : {0.0, 47.0, 180.0, 333.0}) {
    ASSERT_TRUE(ka.moveTo(deg).ok());
    ASSERT_TRUE(kb.moveTo(deg).ok());
    for (const Point& p : a.points) {
      const Kinematics::PointMotion x = ka.motion(p.id), y = kb.motion(p.id);
      EXPECT_EQ(x.position, y.position) << a.pointLabel(p.id) << " at " << deg;
      EXPECT_EQ(x.velocity, y.velocity) << a.pointLabel(p.id) << " at " << deg;
      EXPECT_EQ(x.acceleration, y.acceleration) << a.pointLabel(p.id) << " at " << deg;
    }
  }
}

TEST(Removal, ABodyTakesItsPointsTheirJointsAndItsPlaceAmongTheOutputs) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const Mechanism before = f.m;
  Mechanism m = f.m;
  const Removal r = m.remove(f.coupler);
  ASSERT_EQ(r.bodies.size(), 1u);
  EXPECT_EQ(r.bodies[0].value.id, f.coupler);
  EXPECT_EQ(r.bodies[0].index, 2u);
  EXPECT_EQ(r.points.size(), 3u);  // A, B, P
  ASSERT_EQ(r.joints.size(), 2u);  // the pins at A and B
  EXPECT_EQ(r.joints[0].value.id, f.pinA);
  EXPECT_EQ(r.joints[1].value.id, f.pinB);
  ASSERT_EQ(r.outputs.size(), 1u);
  EXPECT_EQ(r.outputs[0].value, f.P);
  EXPECT_FALSE(r.driver);
  EXPECT_FALSE(m.contains(f.coupler));
  EXPECT_FALSE(m.contains(f.P));
  EXPECT_FALSE(m.contains(f.pinA));
  EXPECT_TRUE(m.contains(f.drive));
  EXPECT_TRUE(m.outputs.empty());
  for (const Point& p : m.points) EXPECT_NE(p.body, f.coupler);

  m.restore(r);
  expectIdentical(m, before);
  expectSameMotion(m, before);
}

TEST(Removal, TheDriversJointTakesTheDriver) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  const Mechanism before = f.m;
  Mechanism m = f.m;
  const Removal r = m.remove(f.drive);
  ASSERT_EQ(r.joints.size(), 1u);
  ASSERT_TRUE(r.driver);
  EXPECT_FALSE(m.driver);
  EXPECT_TRUE(r.points.empty());  // a joint takes nothing but itself (and the driver)
  m.restore(r);
  expectIdentical(m, before);
  expectSameMotion(m, before);
}

TEST(Removal, ASlotTakesItsJointsAndAPointItsOwn) {
  auto s = test::sliderCrank(20, 60, 5, 30);
  const Mechanism before = s.m;
  Mechanism m = s.m;
  const SlotId guide = m.slots[0].id;
  const Removal r = m.remove(guide);
  ASSERT_EQ(r.slots.size(), 1u);
  ASSERT_EQ(r.joints.size(), 1u);
  EXPECT_EQ(r.joints[0].value.type, JointType::Slider);
  EXPECT_EQ(m.joints.size(), before.joints.size() - 1);
  m.restore(r);
  expectIdentical(m, before);

  // A point in the middle of the points vector: its two joints go, the others keep their order.
  const Removal rp = m.remove(s.A);
  EXPECT_EQ(rp.points.size(), 1u);
  ASSERT_EQ(rp.joints.size(), 1u);
  m.restore(rp);
  expectIdentical(m, before);
  expectSameMotion(m, before);
}

TEST(Removal, SeveralAtOnceWithOverlapsAndForeignIdsIgnored) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  auto other = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  const Mechanism before = f.m;
  Mechanism m = f.m;
  // Another mechanism's ids have the same values but another owner: nothing of m goes.
  EXPECT_TRUE(m.remove(other.coupler).empty());
  EXPECT_TRUE(m.remove({other.rocker}, {other.P}, {}, {other.drive}).empty());
  expectIdentical(m, before);
  // The coupler, one of its own points named again, the rocker's pivot pin and the driver's pin.
  const Removal r = m.remove({f.coupler, f.rocker}, {f.P}, {}, {f.drive, f.pinO4});
  EXPECT_EQ(r.bodies.size(), 2u);
  EXPECT_EQ(r.points.size(), 5u);  // coupler A, B, P; rocker B, O4
  EXPECT_EQ(r.joints.size(), 4u);  // every joint
  EXPECT_TRUE(r.driver);
  EXPECT_TRUE(m.joints.empty());
  EXPECT_EQ(m.bodies.size(), 2u);
  m.restore(r);
  expectIdentical(m, before);
  expectSameMotion(m, before);
}

TEST(Removal, AFileWithUnknownFieldsComesBackByteForByte) {
  LoadResult loaded = loadMechanismFile(std::string(LINKAGE_TEST_DATA_DIR) + "/io_extras.json");
  ASSERT_TRUE(loaded.mechanism) << loaded.error;
  const Mechanism before = *loaded.mechanism;
  Mechanism m = before;
  for (const Body& b : before.bodies) {
    if (b.ground) continue;
    const Removal r = m.remove(b.id);
    EXPECT_FALSE(r.empty()) << b.name;
    EXPECT_NE(serializeMechanism(m), serializeMechanism(before)) << b.name;
    m.restore(r);
    expectIdentical(m, before);
  }
  expectSameMotion(m, before);
}

TEST(Removal, UndoneInTheKinematicsGivesTheMotionBack) {
  // What an editor does: remove, re-solve what is left, undo, re-solve; the motion afterwards is
  // the motion before, from the crank angle it was at.
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k, ref;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(ref.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(100).ok());
  ASSERT_TRUE(ref.moveTo(100).ok());
  Mechanism m = f.m;
  const Removal r = m.remove(f.coupler);
  // Crank and rocker are left: the rocker is free, held where it is (a note, not a failure).
  ASSERT_TRUE(k.edit(m).ok());
  EXPECT_EQ(k.structure().freeAfterDriver, 1);
  EXPECT_TRUE(std::isnan(k.position(f.P).x()));  // gone with the coupler
  m.restore(r);
  ASSERT_TRUE(k.edit(m).ok());
  EXPECT_NEAR(k.crankDeg(), 100, 1e-12);
  for (double deg : {100.0, 170.0, 300.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    ASSERT_TRUE(ref.moveTo(deg).ok());
    for (const Point& p : f.m.points) {
      EXPECT_LT((k.position(p.id) - ref.position(p.id)).norm(), 1e-10) << f.m.pointLabel(p.id);
      EXPECT_LT((k.velocity(p.id) - ref.velocity(p.id)).norm(), 1e-9) << f.m.pointLabel(p.id);
    }
  }
}

}  // namespace
}  // namespace linkage
