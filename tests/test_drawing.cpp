// The paint list: shapes as a textbook draws them, every position at the solver's, and the
// Kennedy lines of each centre really passing through it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "linkage/drawing.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "mechanisms.h"

namespace linkage {
namespace {

Mechanism example(const char* name) {
  LoadResult r = loadMechanismFile(*resolveModel(name));
  EXPECT_TRUE(r.mechanism) << r.error;
  return *r.mechanism;
}

const Drawing::Body& bodyNamed(const Drawing& d, const std::string& name) {
  for (const Drawing::Body& b : d.bodies)
    if (b.name == name) return b;
  throw std::runtime_error("no body " + name);
}

std::vector<JointSymbol> symbols(const Drawing& d, JointType t) {
  std::vector<JointSymbol> out;
  for (const JointSymbol& s : d.joints)
    if (s.type == t) out.push_back(s);
  return out;
}

TEST(Drawing, WanzerShapesAreTheTextbooks) {
  Kinematics k;
  ASSERT_TRUE(k.load(example("wanzer-inversion-2")).ok());
  const Drawing d = describeDrawing(k);
  ASSERT_EQ(d.bodies.size(), 6u);
  EXPECT_EQ(d.bodies[0].shape, Drawing::Shape::Ground);
  EXPECT_EQ(d.bodies[0].number, 1);
  EXPECT_EQ(bodyNamed(d, "disk").shape, Drawing::Shape::Disc);  // its slots are chords
  EXPECT_NEAR(bodyNamed(d, "disk").radius, std::hypot(10.0, 31.0), 1e-9);
  EXPECT_EQ(bodyNamed(d, "triangle").shape, Drawing::Shape::Plate);
  EXPECT_EQ(bodyNamed(d, "triangle").outline.size(), 3u);
  for (const char* block : {"slider4", "slider5", "needlebar"})
    EXPECT_EQ(bodyNamed(d, block).shape, Drawing::Shape::Block) << block;
  EXPECT_EQ(symbols(d, JointType::Pin).size(), 4u);  // disk, and the triangle to each block
  EXPECT_EQ(symbols(d, JointType::Slider).size(), 3u);
  EXPECT_EQ(d.joints.size(), k.mechanism().joints.size());
  EXPECT_EQ(d.channels.size(), 3u);
  ASSERT_EQ(d.drivers.size(), 1u);
  EXPECT_FALSE(d.drivers[0].ccw);
  EXPECT_EQ(d.drivers[0].crank, k.mechanism().bodyNamed("disk")->id);
  ASSERT_EQ(d.outputs.size(), 1u);
  EXPECT_EQ(d.outputs[0].label, "needlebar.G");
}

TEST(Drawing, FourBarIsBarsWithTwoGroundPivots) {
  Kinematics k;
  ASSERT_TRUE(k.load(example("four-bar-crank-rocker")).ok());
  const Drawing d = describeDrawing(k);
  EXPECT_EQ(bodyNamed(d, "crank").shape, Drawing::Shape::Bar);
  EXPECT_EQ(bodyNamed(d, "rocker").shape, Drawing::Shape::Bar);
  int pivots = 0;
  for (const JointSymbol& p : symbols(d, JointType::Pin)) pivots += p.groundPivot;
  EXPECT_EQ(pivots, 2);
}

// At every pose: bodies placed by their transforms, pins, blocks and outputs where the solver
// has their points, slots where the solver has their ends.
TEST(Drawing, EveryPositionIsTheSolversAlongARevolution) {
  for (const char* name : {"wanzer-inversion-1", "wanzer-inversion-2", "four-bar-crank-rocker",
                           "slider-crank-22a-lambda-0.5"}) {
    Kinematics k;
    ASSERT_TRUE(k.load(example(name)).ok()) << name;
    const Mechanism& m = k.mechanism();
    Drawing d = describeDrawing(k);
    for (double deg = 0; deg <= 360; deg += 15) {
      ASSERT_TRUE(k.moveTo(deg).ok()) << name << " " << deg;
      ASSERT_TRUE(updateDrawing(d, k));
      for (const Point& p : m.points) {
        const Drawing::Body* b = nullptr;
        for (const Drawing::Body& x : d.bodies)
          if (x.id == p.body) b = &x;
        ASSERT_TRUE(b);
        EXPECT_LT((b->pose * p.pos - k.position(p.id)).norm(), 1e-9) << name << " " << deg;
      }
      for (const JointSymbol& p : d.joints) EXPECT_EQ(p.at, k.position(m.joint(p.joint)->a));
      for (const JointSymbol& b : symbols(d, JointType::Slider)) {
        EXPECT_EQ(b.at, k.position(m.joint(b.joint)->a));
        const Kinematics::Segment s = k.slotEnds(b.slot);
        EXPECT_LT(std::abs(cross(b.direction, s.p1 - s.p0)), 1e-12 * (s.p1 - s.p0).norm());
      }
      for (const Drawing::Output& o : d.outputs) EXPECT_EQ(o.at, k.position(o.point));
      ASSERT_EQ(d.drivers.size(), 1u);
      EXPECT_NEAR(d.drivers[0].crankDeg, deg, 1e-9);
    }
  }
}

TEST(Drawing, StaleDrawingIsRefused) {
  Kinematics k;
  ASSERT_TRUE(k.load(example("four-bar-crank-rocker")).ok());
  Drawing d = describeDrawing(k);
  Mechanism e = k.mechanism();
  e.point(*e.findPoint("ground.O4"))->pos.x() += 1;
  ASSERT_TRUE(k.edit(e).ok());
  EXPECT_FALSE(updateDrawing(d, k));
  EXPECT_TRUE(describeDrawing(Kinematics{}).bodies.empty());
}

// Each Kennedy centre lies on both lines it was found from (Kennedy's theorem, checked
// independently of how the solver intersected them), at several poses of the Wanzer.
TEST(Drawing, CentresLieOnTheirKennedyLines) {
  Kinematics k;
  ASSERT_TRUE(k.load(example("wanzer-inversion-2")).ok());
  InstantCentreSolver ics;
  ASSERT_TRUE(ics.prepare(k).ok());
  int kennedy = 0;
  for (double deg : {0.0, 37.0, 101.0, 250.0}) {
    ASSERT_TRUE(k.moveTo(deg).ok());
    const InstantCentres& c = ics.compute(k);
    const Drawing d = describeDrawing(k, &c);
    ASSERT_EQ(d.centres.size(), 15u);
    for (const Drawing::Centre& ce : d.centres) {
      const InstantCentre* ref = c.find(ce.i, ce.j);
      ASSERT_TRUE(ref);
      EXPECT_EQ(ce.determined, ref->determined);
      if (!ce.determined) continue;
      EXPECT_EQ(ce.atInfinity, ref->atInfinity());
      if (ce.status != CentreStatus::Kennedy) continue;
      ++kennedy;
      ASSERT_EQ(ce.lines.size(), 2u);
      const Eigen::Vector3d x = ce.atInfinity ? Eigen::Vector3d(ce.at.x(), ce.at.y(), 0)
                                              : Eigen::Vector3d(ce.at.x(), ce.at.y(), 1);
      for (const Drawing::KennedyLine& l : ce.lines) {
        Eigen::Vector3d a = l.through[0], b = l.through[1];
        const Eigen::Vector3d line = a.normalized().cross(b.normalized());
        ASSERT_GT(line.norm(), 1e-9);
        EXPECT_LT(std::abs(line.normalized().dot(x.normalized())), 1e-9)
            << ce.i << "," << ce.j << " via " << l.k << " at " << deg;
      }
    }
  }
  EXPECT_GT(kennedy, 20);
}

}  // namespace
}  // namespace linkage
