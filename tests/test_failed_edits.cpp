// A load or edit that fails keeps the last good state, readable and equal to what it was, and
// says why with ids: the joints that do not close and by how much (AssemblyFailed), the
// redundant joints that conflict (Conflicting).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace linkage {
namespace {

// Everything a caller can read of a Kinematics, to compare before and after a failure.
struct Reading {
  bool valid = false, derivatives = false, closedForm = false;
  std::uint64_t revision = 0;
  double crankDeg = 0, size = 0;
  std::string file;
  std::vector<Vec2> positions, velocities, accelerations;
  std::vector<double> angles, omegas;
  std::vector<Note> notes;
  StructureReport structure;
  Eigen::VectorXd q, dq;
};

Reading read(const Kinematics& k) {
  Reading r;
  r.valid = k.valid();
  r.derivatives = k.derivativesValid();
  r.closedForm = k.closedForm();
  r.revision = k.revision();
  r.crankDeg = k.crankDeg();
  r.size = k.size();
  r.file = serializeMechanism(k.mechanism());
  for (const Point& p : k.mechanism().points) {
    r.positions.push_back(k.position(p.id));
    r.velocities.push_back(k.velocity(p.id));
    r.accelerations.push_back(k.acceleration(p.id));
  }
  for (const Body& b : k.mechanism().bodies) {
    r.angles.push_back(k.bodyAngle(b.id));
    r.omegas.push_back(k.bodyOmega(b.id));
  }
  r.notes = k.notes();
  r.structure = k.structure();
  r.q = k.q();
  r.dq = k.dq();
  return r;
}

void expectEqual(const Reading& a, const Reading& b) {
  EXPECT_EQ(a.valid, b.valid);
  EXPECT_EQ(a.derivatives, b.derivatives);
  EXPECT_EQ(a.closedForm, b.closedForm);
  EXPECT_EQ(a.revision, b.revision);
  EXPECT_EQ(a.crankDeg, b.crankDeg);
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.file, b.file);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.velocities, b.velocities);
  EXPECT_EQ(a.accelerations, b.accelerations);
  EXPECT_EQ(a.angles, b.angles);
  EXPECT_EQ(a.omegas, b.omegas);
  EXPECT_EQ(a.notes, b.notes);
  EXPECT_EQ(a.structure.rank, b.structure.rank);
  EXPECT_EQ(a.structure.redundantJoints, b.structure.redundantJoints);
  EXPECT_EQ(a.structure.freeBodies, b.structure.freeBodies);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.dq, b.dq);
}

// The four-bar with its ground pivot O4 moved 500 mm away: the rocker cannot reach it.
Mechanism unreachablePivot(const test::FourBar& f) {
  Mechanism m = f.m;
  for (Point& p : m.points)
    if (p.body == f.ground && p.name == "O4") p.pos += Vec2(500, 0);
  return m;
}

void expectFailuresKeepTheState(const KinematicsOptions& opt) {
  auto f = test::fourBar(60, 20, 70, 50, 60, true, 35, 25);
  Kinematics k(opt);
  ASSERT_TRUE(k.load(f.m).ok());
  ASSERT_TRUE(k.moveTo(100).ok());
  const Reading before = read(k);

  // Dimensions only, but the loop cannot close.
  Status s = k.edit(unreachablePivot(f));
  EXPECT_EQ(s.code, StatusCode::AssemblyFailed) << s.message;
  expectEqual(read(k), before);

  // A new topology that does not compile: a joint with both points on one body.
  Mechanism broken = f.m;
  broken.addPin(f.A, f.P);
  s = k.edit(broken);
  EXPECT_EQ(s.code, StatusCode::BadModel) << s.message;
  expectEqual(read(k), before);

  // No ground at all, by load.
  Mechanism noGround = f.m;
  noGround.bodies[0].ground = false;
  s = k.load(noGround);
  EXPECT_EQ(s.code, StatusCode::BadModel) << s.message;
  expectEqual(read(k), before);

  // A structure: the driver cannot turn.
  Mechanism locked = f.m;
  locked.addPin(locked.addPoint(f.ground, "C", f.m.point(f.P)->pos),
                locked.addPoint(f.coupler, "C", f.m.point(f.P)->pos));
  s = k.edit(locked);
  EXPECT_NE(s.code, StatusCode::Ok);
  expectEqual(read(k), before);

  // And it goes on from there as if nothing had been tried.
  Kinematics fresh(opt);
  ASSERT_TRUE(fresh.load(f.m).ok());
  ASSERT_TRUE(fresh.moveTo(100).ok());
  ASSERT_TRUE(k.moveTo(250).ok());
  ASSERT_TRUE(fresh.moveTo(250).ok());
  for (const Point& p : f.m.points)
    EXPECT_LT((k.position(p.id) - fresh.position(p.id)).norm(), 1e-12);
}

TEST(FailedEdit, KeepsThePreviousStateOnTheClosedFormPath) {
  expectFailuresKeepTheState(KinematicsOptions{});
}

TEST(FailedEdit, KeepsThePreviousStateOnTheGeneralPath) {
  KinematicsOptions opt;
  opt.closedForm = false;
  expectFailuresKeepTheState(opt);
}

TEST(FailedEdit, AFailedFirstLoadLeavesNothingLoaded) {
  auto f = test::fourBar(60, 20, 70, 50, 60);
  Kinematics k;
  EXPECT_EQ(k.load(unreachablePivot(f)).code, StatusCode::AssemblyFailed);
  EXPECT_FALSE(k.valid());
  EXPECT_TRUE(std::isnan(k.crankDeg()));
  EXPECT_EQ(k.moveTo(10).code, StatusCode::BadModel);
}

TEST(Gaps, ALoopTooShortReportsEachJointsGapWithItsId) {
  // Crank 2 mm along the x axis, coupler and rocker drawn bent; the links add up to 3 mm less
  // than the 12 mm between the pivots. Closest to closing, the crank stays where the driver
  // holds it, coupler and rocker straighten along the axis and the four pins share the 3 mm
  // equally (the least sum of squares of four gaps that add up to 3).
  Mechanism m;
  const double coupler = 3, rocker = 4;
  const Vec2 B(2 + coupler * std::cos(0.5), coupler * std::sin(0.5));
  const Vec2 O4 = B + rocker * Vec2(std::cos(-0.3), std::sin(-0.3));
  const BodyId g = m.addBody("ground", true), c = m.addBody("crank"), k3 = m.addBody("coupler"),
               k4 = m.addBody("rocker");
  const JointId drive = m.addPin(m.addPoint(g, "O2", {0, 0}), m.addPoint(c, "O2", {0, 0}));
  const JointId a = m.addPin(m.addPoint(c, "A", {2, 0}), m.addPoint(k3, "A", {2, 0}));
  const JointId b = m.addPin(m.addPoint(k3, "B", B), m.addPoint(k4, "B", B));
  const JointId o4 = m.addPin(m.addPoint(k4, "O4", O4), m.addPoint(g, "O4", {12, 0}));
  m.driver = Driver{drive, 60, Direction::Ccw, 0, ""};
  Kinematics k;
  const Status s = k.load(m);
  ASSERT_EQ(s.code, StatusCode::AssemblyFailed) << s.message;
  ASSERT_EQ(s.gaps.size(), 4u) << s.message;
  std::vector<JointId> ids;
  for (const JointGap& gap : s.gaps) {
    ids.push_back(gap.joint);
    EXPECT_NEAR(gap.gap, 0.75, 1e-9) << jointLabel(m, gap.joint);
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<JointId>{drive, a, b, o4}));
  // The message names the worst (first) gap's joint; joints lists them all.
  EXPECT_EQ(s.joints.size(), 4u);
  EXPECT_EQ(s.joints[0], s.gaps[0].joint);
  EXPECT_NE(s.message.find(jointName(m, s.gaps[0].joint) + " stays"), std::string::npos)
      << s.message;
}

TEST(Gaps, AConflictingRedundantJointReportsItsGap) {
  // A parallelogram (crank 40 at 60 degrees, coupler 100, rocker 40) with a fifth link of 40
  // from O5 = (50, 0), parallel to the crank, pinned to the coupler 1 mm to the right of where it
  // should be. Of that pin's two rows the x row is independent (it fixes the fifth link's angle)
  // and the y row repeats the others (in the parallelogram the link's end and the coupler move
  // alike vertically). Assembled, the x row holds: the link's end M = O5 + 40 (cos t, sin t)
  // with 50 + 40 cos t = A.x + 51 = 71, so the y row stays open by 40 sin 60 - sqrt(40^2 - 21^2).
  auto f = test::fourBar(100, 40, 100, 40, 60);
  Mechanism& m = f.m;
  const BodyId link = m.addBody("link5");
  const Vec2 A = m.point(f.A)->pos;
  m.addPin(m.addPoint(f.ground, "O5", {50, 0}), m.addPoint(link, "O5", {50, 0}));
  const JointId extra =
      m.addPin(m.addPoint(link, "M", A + Vec2(50, 0)), m.addPoint(f.coupler, "M", A + Vec2(51, 0)));
  Kinematics k;
  const Status s = k.load(m);
  ASSERT_EQ(s.code, StatusCode::Conflicting) << s.message;
  ASSERT_EQ(s.gaps.size(), 1u);
  EXPECT_EQ(s.gaps[0].joint, extra);
  EXPECT_NEAR(s.gaps[0].gap, 40 * std::sin(M_PI / 3) - std::sqrt(40.0 * 40 - 21 * 21), 1e-9);
  ASSERT_EQ(s.joints.size(), 1u);
  EXPECT_EQ(s.joints[0], extra);
}

}  // namespace
}  // namespace linkage
