// The canvas on one plane of a machine in space (issue 27, the editor; linkage/plane_view.h):
// everything in that plane's coordinates. A planar mechanism redrawn in a plane parallel to
// the drawing, shifted and turned (its class's frame is the drawing plane, so the solver's
// positions differ from the plane's), must be drawn on that plane exactly as the planar one is
// drawn, moved into the plane's coordinates: bodies, joints (the ground's pivots too: the
// ground is written in the world), slots, output marks, traces and instant centres. The
// independent truth is the planar machine's own drawing. On the overedge machine the ground's
// needle slot, projected along the rocker plane's normal, holds the needle arm's block; only
// the rocker plane's centres are drawn. The Properties give a machine in space's output points
// in world x, y, z, as `linkage-cli analyze` does, and so do the plots.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QDockWidget>
#include <QFile>
#include <QGraphicsPathItem>
#include <QHeaderView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <cmath>

#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "drawing.h"
#include "examples.h"
#include "export/motion_table_export.h"
#include "figures/units.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/plane_view.h"
#include "linkage/space.h"
#include "plots/curve_set.h"
#include "properties/inspector_panel.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

using test::showExample;

constexpr double kTol = 1e-9;

// The drawing's (x, y) in a plane parallel to it at z 20, its origin at (5, 3), turned 30 deg.
struct Turned {
  double a = 30 * M_PI / 180;
  Vec2 origin{5, 3};
  Vec2 operator()(const Vec2& v) const {
    const Vec2 d = v - origin;
    return Vec2(d.dot(Vec2(std::cos(a), std::sin(a))), d.dot(Vec2(-std::sin(a), std::cos(a))));
  }
  Vec2 direction(const Vec2& v) const { return (*this)(v + origin); }
  Plane plane() const {
    Plane p;
    p.name = "turned";
    p.origin = Vec3(origin.x(), origin.y(), 20);
    p.xAxis = Vec3(std::cos(a), std::sin(a), 0);
    p.yAxis = Vec3(-std::sin(a), std::cos(a), 0);
    return p;
  }
};

// The planar example with its moving bodies in the plane "turned" (their points rewritten in
// its coordinates); the ground stays where it is in the world.
Mechanism turnedCopy(const Mechanism& planar) {
  const Turned in;
  Mechanism m = planar;
  m.planes = std::vector<Plane>{in.plane()};
  for (Body& b : m.bodies)
    if (!b.ground) b.plane = "turned";
  for (Point& q : m.points)
    if (!m.body(q.body)->ground) q.pos = in(q.pos);
  for (Slot& sl : m.slots) {
    if (m.body(sl.body)->ground) continue;
    sl.p0 = in(sl.p0), sl.p1 = in(sl.p1);
    if (sl.mid) sl.mid = in(*sl.mid);
  }
  return m;
}

void expectNear(const Vec2& got, const Vec2& want, const std::string& what) {
  EXPECT_LT((got - want).norm(), kTol) << what << ": got (" << got.x() << ", " << got.y()
                                       << "), want (" << want.x() << ", " << want.y() << ")";
}

// Shows m at `deg` with the instant centres and traces, on plane `plane`.
void showAt(MainWindow& w, const Mechanism& m, double deg, const std::string& plane) {
  w.resize(1200, 800);
  w.document()->setContents(m, QString());
  w.show();
  ASSERT_TRUE(w.document()->solved()) << w.document()->solveStatus().message;
  w.view3d().choosePlane(plane);  // the plane chooser's own path
  ASSERT_EQ(w.scene()->shownPlane(), plane);
  w.scene()->setCentresVisible(true);
  w.scene()->setTracesVisible(true);
  ASSERT_TRUE(w.document()->setCrankDeg(deg).ok());
  QApplication::processEvents();
}

TEST(PlaneView, APlaneShiftedAndTurnedIsDrawnAsThePlanarMachineInItsCoordinates) {
  const Mechanism planar = *loadMechanismFile(*resolveModel("wanzer-inversion-2")).mechanism;
  ASSERT_FALSE(planar.outputs.empty());
  const Mechanism turned = turnedCopy(planar);
  const Turned in;
  for (double deg : {0.0, 75.0}) {
    MainWindow flat, up;
    showAt(flat, planar, deg, "");
    showAt(up, turned, deg, "turned");
    const Drawing &a = flat.scene()->drawing(), &b = up.scene()->drawing();
    const std::string at = " at " + std::to_string(deg);
    // Bodies: the pose maps each sketch point (in the plane for the turned copy) where the
    // planar one is, in the plane's coordinates; every body of the plane is at full strength.
    ASSERT_EQ(a.bodies.size(), b.bodies.size());
    for (size_t i = 0; i < a.bodies.size(); ++i)
      for (const Point& p : planar.points)
        if (p.body == a.bodies[i].id) {
          // As the item draws it: a moving body's in its plane, the ground's seen in it.
          const Vec2 sketch = up.scene()->planeView().seen(turned).point(p.id)->pos;
          const Vec2 want = in(a.bodies[i].pose * p.pos);
          expectNear(b.bodies[i].pose * sketch, want, planar.pointLabel(p.id) + " pose" + at);
          expectNear(up.scene()->worldOf(p.id), want, planar.pointLabel(p.id) + at);
          const BodyItem* item = up.scene()->bodyItem(a.bodies[i].id);
          const QPointF drawn = item->sceneTransform().map(toQt(sketch));
          expectNear(Vec2(drawn.x(), drawn.y()), want, planar.pointLabel(p.id) + " item" + at);
          EXPECT_EQ(item->opacity(), 1.0);
        }
    // Joints (a ground pivot coincides with its body's point), slots, outputs.
    ASSERT_EQ(a.joints.size(), b.joints.size());
    for (size_t i = 0; i < a.joints.size(); ++i) {
      expectNear(b.joints[i].at, in(a.joints[i].at), "joint " + std::to_string(i) + at);
      EXPECT_NEAR(up.scene()->jointItems()[i]->opacity(), 1.0, 0) << i;
    }
    ASSERT_EQ(a.channels.size(), b.channels.size());
    for (size_t i = 0; i < a.channels.size(); ++i) {
      expectNear(b.channels[i].p0, in(a.channels[i].p0), "slot end 0" + at);
      expectNear(b.channels[i].p1, in(a.channels[i].p1), "slot end 1" + at);
    }
    ASSERT_EQ(a.outputs.size(), b.outputs.size());
    for (size_t i = 0; i < a.outputs.size(); ++i) {
      expectNear(b.outputs[i].at, in(a.outputs[i].at), "output" + at);
      const QPointF mark = up.scene()->outputItems()[i]->pos();
      expectNear(Vec2(mark.x(), mark.y()), in(a.outputs[i].at), "output mark" + at);
    }
    // Traces, sample by sample.
    ASSERT_EQ(flat.scene()->traceItems().size(), up.scene()->traceItems().size());
    for (size_t i = 0; i < flat.scene()->traceItems().size(); ++i) {
      const QPainterPath &pa = flat.scene()->traceItems()[i]->path(),
                         &pb = up.scene()->traceItems()[i]->path();
      ASSERT_EQ(pa.elementCount(), pb.elementCount());
      ASSERT_GT(pa.elementCount(), 10);
      for (int e = 0; e < pa.elementCount(); e += 7)
        expectNear(Vec2(pb.elementAt(e).x, pb.elementAt(e).y),
                   in(Vec2(pa.elementAt(e).x, pa.elementAt(e).y)), "trace" + at);
    }
    // Instant centres, and the Kennedy lines' points, in the plane's coordinates.
    ASSERT_EQ(a.centres.size(), b.centres.size());
    ASSERT_FALSE(a.centres.empty());
    for (size_t i = 0; i < a.centres.size(); ++i) {
      const Drawing::Centre &ca = a.centres[i], &cb = b.centres[i];
      ASSERT_EQ(ca.i, cb.i);
      ASSERT_EQ(ca.j, cb.j);
      ASSERT_EQ(ca.determined, cb.determined);
      if (!ca.determined) continue;
      const std::string name = std::to_string(ca.i) + "," + std::to_string(ca.j) + at;
      expectNear(cb.at, ca.atInfinity ? in.direction(ca.at) : in(ca.at), "centre " + name);
      // Each Kennedy line it was found from (the solver may pick other lines in space than in
      // the plane) goes through it as drawn.
      const Eigen::Vector3d x(cb.at.x(), cb.at.y(), cb.atInfinity ? 0.0 : 1.0);
      for (const Drawing::KennedyLine& l : cb.lines) {
        const Eigen::Vector3d line = l.through[0].cross(l.through[1]);
        if (line.head<2>().norm() == 0) continue;  // through two centres at infinity
        EXPECT_LT(std::abs(line.dot(x)) / line.head<2>().norm(), kTol)
            << "line " << l.k << " of " << name;
      }
    }
    if (deg == 75.0) shot(&up, "plane-view-turned-wanzer");
  }
}

TEST(PlaneView, TheGroundsNeedleSlotSeenFromTheRockerPlaneHoldsTheNeedleArmsBlock) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "overedge-machine"));
  w.view3d().choosePlane("rocker");
  w.scene()->setCentresVisible(true);
  ASSERT_TRUE(w.document()->setCrankDeg(30).ok());
  QApplication::processEvents();
  const Mechanism& m = w.document()->kinematics().mechanism();
  const Plane& rocker = *planeNamed(m, "rocker");
  // Every slider of a moving body of the rocker plane in a ground slot: its point on the
  // slot's line as drawn (the line through the slot's ends in the world, seen along the
  // plane's normal: the ends' coordinates in the plane).
  int checked = 0;
  const Drawing& d = w.scene()->drawing();
  for (const Slot& s : m.slots) {
    if (!m.body(s.body)->ground) continue;
    auto inPlane = [&](const Vec2& xy, double z) {
      const Vec3 r = Vec3(xy.x(), xy.y(), z) - rocker.origin;
      return Vec2(r.dot(rocker.xAxis), r.dot(rocker.yAxis));
    };
    const Vec2 e0 = inPlane(s.p0, s.z.empty() ? 0.0 : s.z.front());
    const Vec2 e1 = inPlane(s.p1, s.z.empty() ? 0.0 : s.z.back());
    for (const Drawing::Channel& c : d.channels)
      if (c.slot == s.id) {
        expectNear(c.p0, e0, "the slot's first end");
        expectNear(c.p1, e1, "the slot's second end");
      }
    for (const Joint& j : m.joints)
      if (j.slot == s.id && m.body(m.point(j.a)->body)->plane == "rocker") {
        const Vec2 p = w.scene()->worldOf(j.a), u = (e1 - e0).normalized();
        const Vec2 off = (p - e0) - (p - e0).dot(u) * u;
        EXPECT_LT(off.norm(), kTol) << m.pointLabel(j.a) << " is off its slot";
        ++checked;
      }
  }
  EXPECT_GT(checked, 0);
  // Only the rocker plane's class's centres, none across planes.
  const int cls = planeClasses(m).of("rocker").cls;
  ASSERT_FALSE(d.centres.empty());
  for (const Drawing::Centre& c : d.centres) {
    EXPECT_FALSE(c.across);
    EXPECT_EQ(c.planeClass, cls);
  }
  // A ground pivot of a rocker body (centre 1,k of a body turning on it) is where the body's
  // point is drawn, and where the world point is seen in the plane.
  for (const Joint& j : m.joints) {
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b || kindOf(j).role != Role::Revolute || !m.body(a->body)->ground ||
        m.body(b->body)->plane != "rocker")
      continue;
    const Vec3 world = worldOf(m, *a);
    const Vec3 r = world - rocker.origin;
    const Vec2 seen(r.dot(rocker.xAxis), r.dot(rocker.yAxis));
    expectNear(w.scene()->worldOf(a->id), seen, m.pointLabel(a->id));
    expectNear(w.scene()->worldOf(b->id), seen, m.pointLabel(b->id));
    ++checked;
  }
  EXPECT_GT(checked, 1);
  shot(&w, "plane-view-overedge-rocker");
}

TEST(PlaneView, OutputPointsOfAMachineInSpaceAreInTheWorld) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "overedge-machine"));
  w.properties().dock->show();
  w.properties().dock->raise();
  ASSERT_TRUE(w.document()->setCrankDeg(30).ok());
  QApplication::processEvents();
  InspectorPanel* panel = w.properties().inspector();
  panel->refreshMotion();
  QTableWidget* t = panel->motionTable();
  EXPECT_TRUE(t->horizontalHeaderItem(1)->text().contains("world x, y, z"));
  EXPECT_TRUE(t->horizontalHeaderItem(2)->text().contains("world vx, vy, vz"));
  const Kinematics& k = w.document()->kinematics();
  const Mechanism& m = k.mechanism();
  ASSERT_EQ(t->rowCount(), static_cast<int>(m.outputs.size()));
  for (int r = 0; r < t->rowCount(); ++r) {
    const Kinematics::PointMotion3 pm = k.motionInSpace(m.outputs[r]);
    const Vec3* v[3] = {&pm.position, &pm.velocity, &pm.acceleration};
    for (int c = 0; c < 3; ++c) {
      const QStringList parts = t->item(r, c + 1)->text().split(", ");
      ASSERT_EQ(parts.size(), 3) << t->item(r, c + 1)->text();
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(parts[i].toDouble(), (*v[c])[i], 1e-3 * std::max(1.0, std::abs((*v[c])[i])))
            << r << " " << c << " " << i;
    }
  }
  // The editor's motion table: the nine world columns of `linkage-cli analyze`.
  QTemporaryDir dir;
  const QString path = dir.filePath("motion.csv");
  QString error;
  ASSERT_TRUE(exportMotionTable(*w.document(), path, 36, 1, &error)) << error;
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QString text = QString::fromUtf8(f.readAll());
  EXPECT_TRUE(text.contains("z_mm")) << text.left(400);
  EXPECT_TRUE(text.contains("az_mm_s2")) << text.left(400);
}

// A ground slot drawn with the Slot tool on the rocker plane: written in the world where the
// clicks are on that plane (every end on it), drawn where it was clicked; one undo step.
TEST(PlaneView, AGroundSlotDrawnOnAPlaneIsWrittenWhereThePlaneIs) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "rssr-crank-rocker"));
  w.view3d().choosePlane("rocker");
  w.canvas()->setZoom(3);
  w.canvas()->centerOn(-40, 40);
  QApplication::processEvents();
  const size_t slots = w.document()->design().slots.size();
  const int steps = w.document()->undoStack()->count();
  test::Draw d{w};
  d.key("T");
  d.click(-60, 50);
  d.click(-20, 50);
  const Mechanism& m = w.document()->design();
  ASSERT_EQ(m.slots.size(), slots + 1);
  const Slot& s = m.slots.back();
  ASSERT_TRUE(m.body(s.body)->ground);
  ASSERT_EQ(s.z.size(), 2u);
  const Plane& rocker = *planeNamed(m, "rocker");
  const Vec2 clicked[2] = {w.scene()->drawing().channels.back().p0,
                           w.scene()->drawing().channels.back().p1};
  const Vec3 ends[2] = {Vec3(s.p0.x(), s.p0.y(), s.z[0]), Vec3(s.p1.x(), s.p1.y(), s.z[1])};
  for (int e = 0; e < 2; ++e) {
    const Vec3 r = ends[e] - rocker.origin;
    EXPECT_NEAR(r.dot(rocker.normal()), 0, kTol) << "end " << e << " off the plane";
    expectNear(Vec2(r.dot(rocker.xAxis), r.dot(rocker.yAxis)), clicked[e], "end in the plane");
  }
  EXPECT_NEAR(clicked[0].y(), clicked[1].y(), kTol);
  EXPECT_NEAR(clicked[1].x() - clicked[0].x(), 40, 1);  // where it was clicked (snapping aside)
  EXPECT_EQ(w.document()->undoStack()->count(), steps + 1);
  w.document()->undoStack()->undo();
  EXPECT_EQ(w.document()->design().slots.size(), slots);
}

// The ground's slots that only another plane's bodies run in are faint, as those bodies are:
// the needle arm's guide in the overedge machine, seen from the main shaft's plane or from the
// rocker plane that holds the arm.
TEST(PlaneView, TheGroundsSlotsOfOtherPlanesAreFaint) {
  MainWindow w;
  const Mechanism m = linkage::test::example("overedge-machine");
  const BodyId ground = m.ground()->id;
  SlotId guide;
  for (const Joint& j : m.joints)
    if (j.slot && m.slot(j.slot)->body == ground &&
        m.point(j.a)->body == m.bodyNamed("needlearm")->id)
      guide = j.slot;
  ASSERT_TRUE(guide);
  showAt(w, m, 30, "main");
  EXPECT_TRUE(w.scene()->bodyItem(ground)->slotFaint(guide));
  showAt(w, m, 30, "rocker");
  EXPECT_FALSE(w.scene()->bodyItem(ground)->slotFaint(guide));
}

// The plots of a point of a machine in space: x, y and z in the world, position and velocity,
// each sample the solver's world motion there (motionInSpace at that crank angle, on another
// copy of the solver), and between samples too; the frame says "world".
TEST(PlaneView, PlotsOfAMachineInSpaceAreTheWorldsXYZ) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "overedge-machine"));
  const Kinematics& k = w.document()->kinematics();
  const Mechanism& m = k.mechanism();
  ASSERT_FALSE(m.outputs.empty());
  for (PointId out : m.outputs) {
    for (auto [c, axis] :
         {std::pair{Quantity::Component::X, 0}, std::pair{Quantity::Component::Y, 1},
          std::pair{Quantity::Component::Z, 2}}) {
      CurveRequest r;
      r.target = QString::fromStdString(m.pointLabel(out));
      r.component = c;
      r.steps = 36;
      CurveSet set(k, r, "t");
      ASSERT_TRUE(set.status().ok()) << set.status().message;
      EXPECT_EQ(set.frame(), "world");
      const Curve &pos = set.curve(Order::Position), &vel = set.curve(Order::Velocity);
      ASSERT_EQ(pos.values.size(), 37u);
      Kinematics at = k;
      for (size_t i = 0; i < pos.values.size(); i += 5) {
        ASSERT_TRUE(at.moveTo(pos.crankDeg[i]).ok());
        const Kinematics::PointMotion3 want = at.motionInSpace(out);
        EXPECT_NEAR(pos.values[i], want.position[axis], 1e-9 * at.size()) << r.target << " " << i;
        EXPECT_NEAR(vel.values[i], want.velocity[axis], 1e-9 * at.size() * at.omega())
            << r.target << " " << i;
      }
      ASSERT_TRUE(at.moveTo(47.5).ok());
      EXPECT_NEAR(set.valuesAt(47.5)[0], at.motionInSpace(out).position[axis], 1e-9 * at.size());
    }
  }
  // The labels say which component and that it is the world's.
  EXPECT_EQ(componentLabel({Quantity::Component::Z}, Order::Velocity), "vz");
}

}  // namespace
}  // namespace linkage::ui
