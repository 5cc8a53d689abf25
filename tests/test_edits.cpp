// The editing operations the editor's tools make (linkage/edits.h), without Qt: links pinned
// where they are drawn, ground pivots, blocks and pins in slots, the driver, joint types, gears,
// arc slots, and an edit made at the current pose redrawn at the sketch's (editAtPose).
#include <gtest/gtest.h>

#include <cmath>

#include "examples.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/limits.h"
#include "linkage/space.h"
#include "mechanisms.h"

namespace linkage {
namespace {

TEST(Edits, LinksPinWhereTheyAreDrawnAndTakeTextbookNames) {
  Mechanism m;
  m.addBody("ground", true);
  const PointId g = addGroundPoint(m, Vec2(0, 0));
  const BodyId crank = addLink(m, {{Vec2(0, 0), g}, {Vec2(20, 0), {}}});
  ASSERT_TRUE(crank);
  EXPECT_EQ(m.body(crank)->name, "link2");
  ASSERT_EQ(m.joints.size(), 1u);
  EXPECT_EQ(jointLabel(m, m.joints[0].id), "joints[0] (pin ground.A - link2.A)");
  EXPECT_EQ(jointName(m, m.joints[0].id), "pin ground.A - link2.A");
  std::string why;
  EXPECT_FALSE(addLink(m, {{Vec2(0, 0), {}}}, &why));
  EXPECT_EQ(why, "a link needs two points at least");
  // The pin's points are one place: moving one moves the other with it.
  EXPECT_EQ(pinnedTogether(m, g).size(), 2u);
  // The driver is a pin, its ground side made `a`; a slider is refused.
  EXPECT_TRUE(setDriver(m, m.joints[0].id, &why));
  EXPECT_EQ(m.point(m.joints[0].a)->body, m.ground()->id);
  const SlotId slot = addBodySlot(m, m.ground()->id, Vec2(40, -20), Vec2(40, 20));
  const PointId tip = m.pointNamed(crank, "B")->id;
  const BodyId block = addBlock(m, tip, slot, Vec2(20, 0), &why);
  ASSERT_TRUE(block) << why;
  const JointId slider = m.joints.back().id;
  EXPECT_EQ(m.joint(slider)->type, JointType::Slider);
  EXPECT_FALSE(setDriver(m, slider, &why));
  EXPECT_EQ(why, "the driver is a pin joint: pick a pin");
  // A slider and a pin in a slot change into each other; a pin cannot become either.
  EXPECT_TRUE(changeJointType(m, slider, JointType::PinInSlot, &why));
  EXPECT_TRUE(changeJointType(m, slider, JointType::Slider, &why));
  EXPECT_FALSE(changeJointType(m, m.joints[0].id, JointType::Slider, &why));
  EXPECT_NE(why.find("a pin cannot become a slider"), std::string::npos) << why;
  // A point and a slot of one body cannot make a joint.
  EXPECT_FALSE(addPinInSlot(m, m.pointNamed(m.ground()->id, "A")->id, slot, &why));
  toggleOutput(m, tip);
  EXPECT_EQ(m.outputs, std::vector<PointId>{tip});
  toggleOutput(m, tip);
  EXPECT_TRUE(m.outputs.empty());
}

TEST(Edits, AnEditAtTheCurrentPoseIsRedrawnAtTheSketchs) {
  // A four-bar turned to crank 90: a point added to the coupler where it is now is drawn, in the
  // file, where the coupler is at crank 0; the bodies the edit did not move keep their numbers
  // to the last bit.
  const test::FourBar f = test::fourBar(60, 20, 70, 50, 0);
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(90).ok());
  const Vec2 now = k.position(f.B) + Vec2(0, 10);  // 10 mm above B, where it is now
  Mechanism next = f.m;
  const PointId q = addBodyPoint(next, f.coupler, k.toSketch(f.coupler, now));
  ASSERT_TRUE(q);
  // As the tools do: the new point in the coupler's drawing, from where it is now.
  const PoseEdit e = editAtPose(k, next);
  ASSERT_TRUE(e.solved);
  EXPECT_EQ(e.kinematics.crankDeg(), 90);
  EXPECT_LT((e.kinematics.position(q) - now).norm(), 1e-9);
  // The file's drawing is the sketch's pose: the crank back at 0 puts the point there.
  Kinematics atZero;
  ASSERT_TRUE(atZero.load(e.design).ok());
  EXPECT_LT((atZero.position(q) - e.design.point(q)->pos).norm(), 1e-9);
  for (const Point& p : f.m.points) EXPECT_EQ(e.design.point(p.id)->pos, p.pos);
  // An edit the solver refuses is handed back as given, unsolved.
  Mechanism broken = f.m;
  broken.point(f.O4)->pos = Vec2(500, 0);
  const PoseEdit refused = editAtPose(k, broken);
  EXPECT_FALSE(refused.solved);
  EXPECT_EQ(refused.design.point(f.O4)->pos, Vec2(500, 0));
}

TEST(Edits, AnEditWhoseSketchPoseIsOutOfReachBecomesTheDrawing) {
  // A crank-rocker turned to crank 90 (A = (0, 20)); its rocker pivot moved, where it is now, to
  // O4 = (-80, 70) with a rocker of 40: the loop closes here (|A O4| = 94.3 < 70 + 40) but not at
  // crank 0 (|A O4| = 122 > 110). The drawing becomes this pose, and crank angle 0 with it.
  // The crank's mass sits 10 mm off its line O2A: redrawn at crank 90, it stays there on it.
  test::FourBar f = test::fourBar(60, 20, 70, 50, 0);
  f.m.body(f.crank)->mass = Mass{.kg = 1, .com = Vec2(15, 10), .jKgMm2 = 1};
  f.m.body(f.crank)->mass->counterweights.push_back({0.5, Vec2(15, 10)});
  const auto onCrank = [&](const Mechanism& m, Vec2 at) -> Vec2 {
    const Vec2 o = m.point(f.O2)->pos, oa = m.pointNamed(f.crank, "A")->pos - o;
    return Vec2((at - o).dot(oa), cross(oa, at - o)) / oa.norm();
  };
  const Vec2 comOnCrank = onCrank(f.m, Vec2(15, 10));
  Kinematics k;
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(90).ok());
  const Vec2 A(0, 20), O4(-80, 70);
  ASSERT_LT((k.position(f.A) - A).norm(), 1e-12);
  // B: on the circles of 70 about A and 40 about O4.
  const Vec2 e = O4 - A;
  const double d = e.norm(), a = (70 * 70 - 40 * 40 + d * d) / (2 * d);
  const Vec2 B = A + a * e / d + std::sqrt(70 * 70 - a * a) * perp(e / d);
  Mechanism next = f.m;
  for (const Point& p : f.m.points) {
    const bool pivot = p.name == "O4", pin = p.name == "B";
    if (pivot || pin) next.point(p.id)->pos = k.toSketch(p.body, pivot ? O4 : B);
  }
  const PoseEdit edit = editAtPose(k, next);
  ASSERT_TRUE(edit.solved);
  ASSERT_TRUE(edit.design.driver);
  EXPECT_EQ(edit.design.driver->startDeg, 0);
  EXPECT_EQ(edit.kinematics.crankDeg(), 0);
  // Loaded, the file starts where the edit was made.
  Kinematics loaded;
  ASSERT_TRUE(loaded.load(edit.design).ok());
  for (const Point& p : edit.design.points)
    EXPECT_LT((loaded.position(p.id) - edit.kinematics.position(p.id)).norm(), 1e-9) << p.name;
  EXPECT_LT((loaded.position(f.O4) - O4).norm(), 1e-9);
  const Mass& mass = *edit.design.body(f.crank)->mass;
  EXPECT_LT((onCrank(edit.design, mass.com) - comOnCrank).norm(), 1e-9);
  EXPECT_LT((onCrank(edit.design, mass.counterweights[0].at) - comOnCrank).norm(), 1e-9);
}

// A plate by its side lengths (the homework's triangle EF 16, FG 56, EG 62), a bar by its
// length, a point by its distance and angle from another: exact, on the side it was drawn.
TEST(Edits, TypedDimensionsPlaceThePointsExactly) {
  Mechanism m;
  m.addBody("ground", true);
  const PointId g = addGroundPoint(m, Vec2(0, 0));
  const BodyId plate = addLink(m, {{Vec2(0, 0), g}, {Vec2(10, 0), {}}, {Vec2(5, -8), {}}});
  ASSERT_TRUE(plate);
  const BodyId rod = addLink(m, {{Vec2(10, 0), m.pointNamed(plate, "B")->id}, {Vec2(20, 5), {}}});
  ASSERT_TRUE(rod);
  const Vec2 e = m.pointNamed(plate, "A")->pos;
  std::string why;
  ASSERT_TRUE(setSideLengths(m, plate, {16, 56, 62}, &why)) << why;
  const std::vector<double> sides = sideLengths(m, plate);
  ASSERT_EQ(sides.size(), 3u);
  EXPECT_EQ(sides[0], 16);
  EXPECT_NEAR(sides[1], 56, 1e-12);
  EXPECT_NEAR(sides[2], 62, 1e-12);
  EXPECT_EQ(m.pointNamed(plate, "A")->pos, e);            // the first point stays
  EXPECT_EQ(m.pointNamed(plate, "B")->pos, Vec2(16, 0));  // the second on its direction
  EXPECT_LT(m.pointNamed(plate, "C")->pos.y(), 0);        // the third on its side
  EXPECT_EQ(m.pointNamed(rod, "B")->pos, Vec2(16, 0));    // a pinned point goes along
  // No triangle: refused, nothing moved.
  const Mechanism before = m;
  EXPECT_FALSE(setSideLengths(m, plate, {16, 20, 62}, &why));
  EXPECT_EQ(why, "these sides make no triangle: each must be shorter than the other two");
  EXPECT_FALSE(setSideLengths(m, plate, {16, 0, 62}, &why));
  EXPECT_EQ(why, "a length must be positive");
  EXPECT_FALSE(setSideLengths(m, plate, {16}, &why));
  EXPECT_EQ(m.pointNamed(plate, "C")->pos, before.pointNamed(plate, "C")->pos);
  // A bar: its length along its direction.
  ASSERT_TRUE(setSideLengths(m, rod, {25}, &why)) << why;
  EXPECT_NEAR((m.pointNamed(rod, "D")->pos - m.pointNamed(rod, "B")->pos).norm(), 25, 1e-12);
  // A point from another: exact at quarter turns.
  ASSERT_TRUE(setPolar(m, m.pointNamed(rod, "D")->id, m.pointNamed(rod, "B")->id, 30, 90, &why));
  EXPECT_EQ(m.pointNamed(rod, "D")->pos, Vec2(16, 30));
  ASSERT_TRUE(setPolar(m, m.pointNamed(rod, "D")->id, m.pointNamed(rod, "B")->id, 10, 30, &why));
  EXPECT_NEAR(m.pointNamed(rod, "D")->pos.x(), 16 + 10 * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_FALSE(setPolar(m, g, g, 1, 0, &why));
  EXPECT_FALSE(setPolar(m, m.pointNamed(rod, "D")->id, g, -1, 0, &why));
}

// A machine in space is drawn one plane at a time (issue 27): a link drawn in a plane is of that
// plane, its points in its coordinates; a ground point drawn in it is where that plane puts it in
// the world; a block runs in its slot's plane; the drawing plane is written as no plane.
TEST(Edits, PartsDrawnInAPlaneAreOfThatPlane) {
  Mechanism m = linkage::test::example("rssr-crank-rocker");
  const Plane* rocker = planeNamed(m, "rocker");
  ASSERT_TRUE(rocker);
  std::string why;
  const BodyId b = addLink(m, {{Vec2(-40, -20), {}}, {Vec2(-20, -30), {}}}, &why, "rocker");
  ASSERT_TRUE(b) << why;
  EXPECT_EQ(m.body(b)->plane, "rocker");
  const BodyId d = addLink(m, {{Vec2(1, 2), {}}, {Vec2(3, 4), {}}}, &why, "drawing");
  ASSERT_TRUE(d);
  EXPECT_EQ(m.body(d)->plane, "");
  EXPECT_FALSE(addLink(m, {{Vec2(1, 2), {}}, {Vec2(3, 4), {}}}, &why, "nowhere"));
  EXPECT_NE(why.find("nowhere"), std::string::npos) << why;
  // The ground point at (10, 20) of the rocker's plane: origin + 10 x + 20 y, in the world.
  const PointId g = addGroundPoint(m, Vec2(10, 20), {}, "rocker");
  ASSERT_TRUE(g);
  const Vec3 expected = Vec3(0, 0, 80) + 10 * rocker->xAxis + 20 * rocker->yAxis;
  EXPECT_LT((worldOf(m, *m.point(g)) - expected).norm(), 1e-12);
  EXPECT_FALSE(addGroundPoint(m, Vec2(10, 20), {}, "nowhere"));
  // A block in a slot of the new rocker-plane link is in that plane.
  const SlotId s = addBodySlot(m, b, Vec2(-40, -20), Vec2(-20, -30));
  ASSERT_TRUE(s);
  const PointId onCrank = m.pointNamed(m.bodyNamed("crank")->id, "A")->id;
  const BodyId block = addBlock(m, onCrank, s, Vec2(-30, -25), &why);
  ASSERT_TRUE(block) << why;
  EXPECT_EQ(m.body(block)->plane, "rocker");
}

// Planes added as the file takes them: checked the same way, with the place named, and made by
// the two constructions a designer names (inclined by rho about x; square to a shaft at a
// distance along it).
TEST(Edits, PlanesAreAddedCheckedAndConstructed) {
  Mechanism m = linkage::test::example("rssr-crank-rocker");
  std::string why;
  const Plane inclined = planeInclinedAboutX(newPlaneName(m), Vec3(111, 134.5, 53.5), 23);
  EXPECT_EQ(inclined.name, "plane2");
  // rho = 23 degrees: y (0, cos 23, sin 23), the spec's example's normal up to sign.
  EXPECT_LT((inclined.yAxis - Vec3(0, 0.9205048534524404, 0.39073112848927377)).norm(), 1e-15);
  ASSERT_TRUE(addPlane(m, inclined, &why)) << why;
  ASSERT_TRUE(planeNamed(m, "plane2"));
  EXPECT_EQ(newPlaneName(m), "plane3");
  EXPECT_FALSE(addPlane(m, inclined, &why));
  EXPECT_NE(why.find("already"), std::string::npos) << why;
  Plane bad = inclined;
  bad.name = "skew";
  bad.yAxis = Vec3(0, 1, 0.1);
  const Mechanism before = m;
  EXPECT_FALSE(addPlane(m, bad, &why));
  EXPECT_NE(why.find("planes.skew.y_axis"), std::string::npos) << why;
  EXPECT_EQ(m.planes->size(), before.planes->size());
  bad = inclined;
  bad.name = "drawing";
  EXPECT_FALSE(addPlane(m, bad, &why));
  // The crank's shaft at O, along z: a plane 12 mm along it, the drawing's axes.
  const PointId o = m.pointNamed(m.ground()->id, "O")->id;
  const PointId h = m.pointNamed(m.ground()->id, "H")->id;
  ASSERT_EQ(shafts(m), (std::vector<PointId>{o, h}));
  const std::optional<Plane> onShaft = planeOnShaft(m, "cam", o, 12);
  ASSERT_TRUE(onShaft);
  EXPECT_LT((onShaft->origin - Vec3(0, 0, 12)).norm(), 1e-15);
  EXPECT_EQ(onShaft->xAxis, Vec3::UnitX());
  EXPECT_EQ(onShaft->yAxis, Vec3::UnitY());
  // The rocker's shaft at H (0, 0, 80), along the rocker plane's normal, x.
  const std::optional<Plane> onRocker = planeOnShaft(m, "arm", h, -5);
  ASSERT_TRUE(onRocker);
  EXPECT_LT((onRocker->origin - Vec3(-5, 0, 80)).norm(), 1e-12);
  EXPECT_TRUE(parallel(*onRocker, *planeNamed(m, "rocker")));
  EXPECT_FALSE(planeOnShaft(m, "x", m.pointNamed(m.bodyNamed("crank")->id, "A")->id, 0));
}

// A ball rod between two planes' points, as the 3D view's picks make it; the refusals the file
// format names (one body, both on the ground, no length).
TEST(Edits, ABallRodJoinsPointsOfAnyPlanes) {
  Mechanism m = linkage::test::example("rssr-crank-rocker");
  const Body* crank = m.bodyNamed("crank");
  const Body* rocker = m.bodyNamed("rocker");
  const PointId o = m.pointNamed(crank->id, "O")->id, a = m.pointNamed(crank->id, "A")->id;
  const PointId h = m.pointNamed(rocker->id, "H")->id, c = m.pointNamed(rocker->id, "C")->id;
  const PointId g = m.pointNamed(m.ground()->id, "O")->id,
                gh = m.pointNamed(m.ground()->id, "H")->id;
  std::string why;
  const size_t joints = m.joints.size();
  const JointId rod = addBallRod(m, a, h, &why);
  ASSERT_TRUE(rod) << why;
  EXPECT_EQ(m.joints.size(), joints + 1);
  EXPECT_EQ(toString(m.joint(rod)->type), std::string("ball-rod"));
  EXPECT_EQ(m.joint(rod)->a, a);
  EXPECT_EQ(m.joint(rod)->b, h);
  EXPECT_EQ(checkJoints(m), "");
  EXPECT_FALSE(addBallRod(m, o, a, &why));
  EXPECT_NE(why.find("one body"), std::string::npos) << why;
  EXPECT_FALSE(addBallRod(m, g, gh, &why));  // both on the ground: one body
  EXPECT_NE(why.find("one body"), std::string::npos) << why;
  EXPECT_FALSE(addBallRod(m, g, o, &why));  // crank.O is drawn on ground.O
  EXPECT_NE(why.find("no length"), std::string::npos) << why;
  EXPECT_FALSE(addBallRod(m, c, c, &why));
  EXPECT_EQ(m.joints.size(), joints + 1);
}

}  // namespace
}  // namespace linkage

namespace linkage {
namespace {

// A body redrawn rigidly where the solve put it (what editAtPose does after an edit the solve
// had to close: the slider-crank's crank made 2 mm longer, its rod moved up to meet it) is
// solved again, not left where its old displacement from the drawing puts it: the rod's pin
// closed and the motion a fresh load's. (The in-place edit kept the rod's old displacement from
// its drawing, 2 mm too high, and its group unsolved as its shape had not changed: the stroke
// read 36 mm where it is 34.)
TEST(Edits, ABodyRedrawnRigidlyIsSolvedWhereItsJointsHoldIt) {
  // Example 22-A: crank O-A 15 drawn up the y axis, rod A-B 50, the needle bar's block B in the
  // slot x = 0: the stroke is 2 r.
  const Mechanism m = test::example("slider-crank-22a-lambda-0.3");
  Kinematics k;
  ASSERT_TRUE(k.load(m).ok());
  Mechanism next = m;
  next.point(*next.findPoint("crank.A"))->pos = Vec2(0, 17);  // the rod's A stays at (0, 15)
  const PoseEdit e = editAtPose(k, next);
  ASSERT_TRUE(e.solved);
  const PointId rodA = *m.findPoint("rod.A"), B = *m.findPoint("needlebar.B");
  EXPECT_LT((e.kinematics.position(rodA) - Vec2(0, 17)).norm(), 1e-12);  // the rod's pin
  EXPECT_LT((e.design.point(rodA)->pos - Vec2(0, 17)).norm(), 1e-12);    // redrawn there
  Kinematics fresh;
  ASSERT_TRUE(fresh.load(e.design).ok());
  for (const Point& p : e.design.points)
    EXPECT_LT((e.kinematics.position(p.id) - fresh.position(p.id)).norm(), 1e-12) << p.name;
  const LimitMeasure stroke = LimitMeasure::along(B, Vec2(0, 1));
  EXPECT_NEAR(findLimits(e.kinematics, stroke).stroke, 34, 1e-9);
  EXPECT_NEAR(findLimits(fresh, stroke).stroke, 34, 1e-9);
}

}  // namespace
}  // namespace linkage
