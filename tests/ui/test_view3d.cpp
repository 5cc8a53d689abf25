// The 3D view (issue 27): where a world point lands in the standard views (against their
// definitions, not the code's own arithmetic), zoom about the cursor, the turntable orbit;
// the dock on the RSSR crank-rocker: what it paints is where the projection says, a click on a
// plate selects its body and brings its plane to the canvas, the animation moves it; the plane
// chooser: the other planes faint or hidden and not picked, new links in the chosen plane as one
// undo step; a planar machine has no chooser and is drawn too.
#include <gtest/gtest.h>

#include "edge_on.h"
#include "ui_test.h"

#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <cmath>

#include "canvas/body_item.h"
#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/elements.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/space.h"
#include "tools/picker.h"
#include "tools/selection.h"
#include "view3d/add_plane_dialog.h"
#include "view3d/projection.h"
#include "view3d/view3d_widget.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

using test::Draw;
using test::showExample;

// A projection fitted to a box, so that the target, centre and scale are not trivial.
Projection fitted(Projection::View v) {
  Projection p;
  p.setRotation(Projection::rotationOf(v));
  p.fit({Vec3(-10, 5, 2), Vec3(30, 45, 70), Vec3(0, 0, 0)}, QSize(640, 480));
  return p;
}

void expectAt(const QPointF& got, double x, double y, const char* what) {
  EXPECT_NEAR(got.x(), x, 1e-9) << what;
  EXPECT_NEAR(got.y(), y, 1e-9) << what;
}

TEST(View3dProjection, StandardViewsPutAWorldPointWhereTheirDefinitionsSay) {
  const Vec3 w(12.5, -7, 31);
  for (auto v : {Projection::View::Front, Projection::View::Top, Projection::View::Side}) {
    const Projection p = fitted(v);
    const Vec3 d = w - p.target();
    const double s = p.scale(), cx = p.centre().x(), cy = p.centre().y();
    // Screen y grows downwards.
    if (v == Projection::View::Front)  // from +z: x right, y up
      expectAt(p.toScreen(w), cx + s * d.x(), cy - s * d.y(), "front");
    if (v == Projection::View::Top)  // from +y: x right, z down the screen
      expectAt(p.toScreen(w), cx + s * d.x(), cy + s * d.z(), "top");
    if (v == Projection::View::Side)  // from +x: z to the left, y up
      expectAt(p.toScreen(w), cx - s * d.z(), cy - s * d.y(), "side");
  }
  // Isometric: the line of sight is (1, 1, 1); every world axis foreshortened alike, y up.
  const Projection iso = fitted(Projection::View::Isometric);
  const QPointF o = iso.toScreen(Vec3::Zero());
  const QPointF along = iso.toScreen(Vec3(5, 5, 5)) - o;
  EXPECT_NEAR(along.x(), 0, 1e-9);
  EXPECT_NEAR(along.y(), 0, 1e-9);
  double len[3];
  for (int k = 0; k < 3; ++k) {
    const QPointF a = iso.toScreen(Vec3::Unit(k)) - o;
    len[k] = std::hypot(a.x(), a.y());
  }
  EXPECT_NEAR(len[0], len[1], 1e-9);
  EXPECT_NEAR(len[0], len[2], 1e-9);
  EXPECT_NEAR(len[0], iso.scale() * std::sqrt(2.0 / 3.0), 1e-9);
  EXPECT_LT((iso.toScreen(Vec3::UnitY()) - o).y(), 0);  // y up the screen
}

TEST(View3dProjection, AlongAPlaneItsAxesAreTheScreensAndFitKeepsEverythingInSight) {
  Plane pl;  // the RSSR's rocker plane: inclined 23 degrees
  pl.origin = Vec3(0, 0, 80);
  pl.xAxis = Vec3(0, 0.9205048534524404, 0.39073112848927377);
  pl.yAxis = Vec3(0, -0.39073112848927377, 0.9205048534524404);
  Projection p;
  p.setRotation(Projection::along(pl));
  const std::vector<Vec3> pts = {pl.world(Vec2(-30, 10)), pl.world(Vec2(5, -20)), Vec3(0, 0, 0)};
  p.fit(pts, QSize(800, 600));
  const QPointF a = p.toScreen(pl.world(Vec2(1, 2))), b = p.toScreen(pl.world(Vec2(4, 6)));
  EXPECT_NEAR(b.x() - a.x(), 3 * p.scale(), 1e-9);
  EXPECT_NEAR(b.y() - a.y(), -4 * p.scale(), 1e-9);
  double xlo = 1e9, xhi = -1e9, ylo = 1e9, yhi = -1e9;
  for (const Vec3& w : pts) {
    const QPointF s = p.toScreen(w);
    xlo = std::min(xlo, s.x()), xhi = std::max(xhi, s.x());
    ylo = std::min(ylo, s.y()), yhi = std::max(yhi, s.y());
  }
  EXPECT_GE(xlo, 0);
  EXPECT_LE(xhi, 800);
  EXPECT_GE(ylo, 0);
  EXPECT_LE(yhi, 600);
  // 85 % of the width or of the height, centred.
  EXPECT_TRUE(std::abs(xhi - xlo - 680) < 1e-6 || std::abs(yhi - ylo - 510) < 1e-6);
  EXPECT_NEAR(xlo + xhi, 800, 1e-6);
  EXPECT_NEAR(ylo + yhi, 600, 1e-6);
}

TEST(View3dProjection, ZoomKeepsThePointUnderTheCursorAndOrbitKeepsYUp) {
  Projection p = fitted(Projection::View::Isometric);
  const Vec3 w(20, 10, 40);
  const QPointF at = p.toScreen(w);
  const double s = p.scale();
  p.zoomAbout(at, 1.7);
  EXPECT_NEAR(p.scale(), 1.7 * s, 1e-12);
  EXPECT_NEAR((p.toScreen(w) - at).manhattanLength(), 0, 1e-9);
  p.orbit(130, 0);
  // A turntable: the world's y still projects straight up, and the view stays a rotation.
  EXPECT_NEAR(p.rotation().row(0).dot(Vec3::UnitY()), 0, 1e-12);
  EXPECT_NEAR((p.rotation() * p.rotation().transpose() - Eigen::Matrix3d::Identity()).norm(), 0,
              1e-12);
  p.orbit(-40, 55);
  EXPECT_NEAR((p.rotation() * p.rotation().transpose() - Eigen::Matrix3d::Identity()).norm(), 0,
              1e-12);
}

// The RSSR in a window with its 3D dock shown, from the front.
struct Rssr {
  MainWindow w;
  View3dWidget* v = nullptr;
  Rssr() {
    if (!showExample(w, "rssr-crank-rocker")) return;
    w.view3d().show->trigger();
    QApplication::processEvents();
    v = w.view3d().view();
    v->showView(Projection::View::Front);
    QApplication::processEvents();
    v->repaint();
  }
  const Mechanism& m() const { return w.document()->design(); }
  BodyId body(const char* name) const { return m().bodyNamed(name)->id; }
  Vec3 world(const char* body, const char* point) const {
    const Point* p = m().pointNamed(m().bodyNamed(body)->id, point);
    return w.document()->kinematics().motionInSpace(p->id).position;
  }
  // Where a point of a body's plate is on the screen: between two of its points.
  QPoint between(const char* body, const char* p, const char* q, double t = 0.5) const {
    const QPointF a = v->projection().toScreen(world(body, p));
    const QPointF b = v->projection().toScreen(world(body, q));
    return (a + t * (b - a)).toPoint();
  }
};

TEST(View3dDock, PaintsThePlatesWhereTheProjectionPutsThemAndPicksThem) {
  Rssr r;
  ASSERT_TRUE(r.v);
  ASSERT_TRUE(r.w.view3d().dock->isVisible());
  shot(r.v, "view3d-rssr-front");
  const QImage img = r.v->grab().toImage();
  const QColor paper = img.pixelColor(3, 3);
  // The rocker's bar, seen from the front (its plane is edge-on: the bar spans its y).
  const QPoint mid = r.between("rocker", "H", "C", 0.6);
  ASSERT_TRUE(r.v->rect().contains(mid));
  EXPECT_NE(img.pixelColor(mid), paper);
  EXPECT_EQ(r.v->pickAt(mid).body, r.body("rocker"));
  EXPECT_EQ(r.v->pickAt(r.v->projection().toScreen(r.world("rocker", "C"))).point,
            r.m().pointNamed(r.body("rocker"), "C")->id);
  EXPECT_TRUE(r.v->pickAt(QPointF(2, 2)).empty());
  // A click selects the body, as the canvas does, and the canvas shows its plane.
  Selection* sel = r.w.tools().selection();
  QTest::mouseClick(r.v, Qt::LeftButton, {}, mid);
  ASSERT_EQ(sel->bodies.size(), 1u);
  EXPECT_EQ(sel->bodies[0], r.body("rocker"));
  EXPECT_EQ(r.w.scene()->shownPlane(), "rocker");
  EXPECT_EQ(r.w.view3d().planeChooser->currentText(), "rocker");
  // The crank (the drawing plane) picked from the top, where its plane is edge-on: half-way
  // from O to the foot of its stud A (A is 5 mm out of the plane, along z).
  r.v->showView(Projection::View::Top);
  r.v->repaint();
  const Vec3 foot = r.world("crank", "A") - 5 * Vec3::UnitZ();
  QTest::mouseClick(r.v, Qt::LeftButton, {},
                    r.v->projection().toScreen(0.5 * (r.world("crank", "O") + foot)).toPoint());
  ASSERT_EQ(sel->bodies.size(), 1u);
  EXPECT_EQ(sel->bodies[0], r.body("crank"));
  EXPECT_EQ(r.w.scene()->shownPlane(), "");
  // A click on nothing clears the selection.
  QTest::mouseClick(r.v, Qt::LeftButton, {}, QPoint(2, 2));
  EXPECT_TRUE(sel->empty());
}

TEST(View3dDock, FollowsTheCrankAndADragOrbits) {
  Rssr r;
  ASSERT_TRUE(r.v);
  const QImage before = r.v->grab().toImage();
  ASSERT_TRUE(r.w.document()->setCrankDeg(90).ok());
  QApplication::processEvents();
  // The scene is the solver's pose now, in the world.
  const Scene3d s = r.v->scene();
  const PointId c = r.m().pointNamed(r.body("rocker"), "C")->id;
  bool found = false;
  for (const Scene3d::Mark& m : s.points)
    if (m.point == c) {
      found = true;
      EXPECT_LT((m.at - r.w.document()->kinematics().motionInSpace(c).position).norm(), 1e-12);
    }
  EXPECT_TRUE(found);
  const QImage turned = r.v->grab().toImage();
  EXPECT_NE(before, turned);
  const Eigen::Matrix3d rot = r.v->projection().rotation();
  const QPoint from(r.v->width() / 2, r.v->height() / 2);
  QTest::mousePress(r.v, Qt::LeftButton, {}, from);
  for (int i = 1; i <= 10; ++i) {
    QMouseEvent e(QEvent::MouseMove, QPointF(from + QPoint(8 * i, 3 * i)),
                  r.v->mapToGlobal(QPointF(from + QPoint(8 * i, 3 * i))), Qt::NoButton,
                  Qt::LeftButton, {});
    QApplication::sendEvent(r.v, &e);
  }
  QTest::mouseRelease(r.v, Qt::LeftButton, {}, from + QPoint(80, 30));
  EXPECT_GT((r.v->projection().rotation() - rot).norm(), 0.1);
  EXPECT_NE(r.v->grab().toImage(), turned);
  EXPECT_TRUE(r.w.tools().selection()->empty());  // a drag is no click
}

TEST(View3dDock, StandardViewsAreActionsWithShortcutsAndStatusTips) {
  Rssr r;
  ASSERT_TRUE(r.v);
  const auto& f = r.w.view3d();
  for (QAction* a : {f.front, f.top, f.side, f.isometric, f.alongPlane, f.fit, f.show}) {
    EXPECT_FALSE(a->shortcut().isEmpty()) << a->objectName();
    EXPECT_FALSE(a->statusTip().isEmpty()) << a->objectName();
  }
  f.top->trigger();
  EXPECT_NEAR((r.v->projection().rotation() - Projection::rotationOf(Projection::View::Top)).norm(),
              0, 1e-12);
  r.w.view3d().choosePlane("rocker");
  f.alongPlane->trigger();
  const Plane* rocker = planeNamed(r.m(), "rocker");
  EXPECT_NEAR((r.v->projection().rotation() - Projection::along(*rocker)).norm(), 0, 1e-12);
}

TEST(PlaneChooser, TheCanvasDrawsOnePlaneTheOthersFaintOrHiddenAndNotPicked) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "rssr-crank-rocker"));
  View3dFeature& f = w.view3d();
  EXPECT_TRUE(f.planeChooserAction->isVisible());
  ASSERT_EQ(f.planeChooser->count(), 2);
  EXPECT_EQ(f.planeChooser->itemText(1), "rocker");
  const Mechanism& m = w.document()->design();
  const BodyId crank = m.bodyNamed("crank")->id, rocker = m.bodyNamed("rocker")->id;
  CanvasScene* s = w.scene();
  EXPECT_EQ(s->bodyItem(crank)->opacity(), 1.0);
  EXPECT_LT(s->bodyItem(rocker)->opacity(), 0.5);
  f.planeChooser->setCurrentIndex(1);
  EXPECT_EQ(s->shownPlane(), "rocker");
  EXPECT_EQ(f.view()->plane(), "rocker");
  EXPECT_LT(s->bodyItem(crank)->opacity(), 0.5);
  EXPECT_EQ(s->bodyItem(rocker)->opacity(), 1.0);
  // The crank's point A is not picked where it is drawn; the rocker's C is.
  const Point* a = m.pointNamed(crank, "A");
  const Point* c = m.pointNamed(rocker, "C");
  const double px = 0.05;
  EXPECT_NE(pickAt(*s, s->worldOf(a->id), px).point, a->id);
  EXPECT_EQ(pickAt(*s, s->worldOf(c->id), px).point, c->id);
  f.hideOtherPlanes->setChecked(true);
  EXPECT_FALSE(s->bodyItem(crank)->isVisible());
  EXPECT_TRUE(s->bodyItem(rocker)->isVisible());
  f.hideOtherPlanes->setChecked(false);
  EXPECT_TRUE(s->bodyItem(crank)->isVisible());
  shot(&w, "plane-chooser-rocker");
}

TEST(PlaneChooser, ALinkDrawnGoesIntoTheChosenPlaneAsOneUndoStep) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "rssr-crank-rocker"));
  w.view3d().choosePlane("rocker");
  const size_t bodies = w.document()->design().bodies.size();
  const int steps = w.document()->undoStack()->count();
  Draw{w}.link({{-40, -20}, {-20, -30}});
  const Mechanism& m = w.document()->design();
  ASSERT_EQ(m.bodies.size(), bodies + 1);
  EXPECT_EQ(m.bodies.back().plane, "rocker");
  EXPECT_EQ(w.document()->undoStack()->count(), steps + 1);
  w.document()->undoStack()->undo();
  EXPECT_EQ(w.document()->design().bodies.size(), bodies);
}

TEST(PlaneChooser, APlanarMachineHasNoChooserAndIsDrawnIn3d) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "four-bar-crank-rocker"));
  EXPECT_FALSE(w.view3d().planeChooserAction->isVisible());
  EXPECT_FALSE(w.view3d().hideOtherPlanes->isEnabled());
  for (const Body& b : w.document()->design().bodies)
    if (BodyItem* item = w.scene()->bodyItem(b.id)) EXPECT_EQ(item->opacity(), 1.0);
  w.view3d().show->trigger();
  QApplication::processEvents();
  View3dWidget* v = w.view3d().view();
  const Scene3d s = v->scene();
  EXPECT_EQ(s.plates.size(), w.document()->design().bodies.size() - 1);
  for (const Scene3d::Mark& m : s.points) EXPECT_EQ(m.at.z(), 0);
  // From the front, a planar machine is its drawing: x right, y up, at its solver positions.
  v->showView(Projection::View::Front);
  v->repaint();
  const Kinematics& k = w.document()->kinematics();
  const Mechanism& m = w.document()->design();
  const QPointF a = v->projection().toScreen(k.motionInSpace(m.points[0].id).position);
  const QPointF b = v->projection().toScreen(k.motionInSpace(m.points[1].id).position);
  const Vec2 d = k.position(m.points[1].id) - k.position(m.points[0].id);
  EXPECT_NEAR(b.x() - a.x(), v->projection().scale() * d.x(), 1e-9);
  EXPECT_NEAR(b.y() - a.y(), -v->projection().scale() * d.y(), 1e-9);
  shot(v, "view3d-four-bar");
}

// Edit > Add Plane on a planar machine: a refusal is said in the dialog, which stays open; the
// plane inclined 23 degrees about x is added as one undo step, listed by the chooser (now shown)
// and shown on the canvas; undone, the machine is planar again.
TEST(AddPlane, TheDialogAddsAPlaneAsOneUndoStepAndTheCanvasShowsIt) {
  MainWindow w;
  ASSERT_TRUE(showExample(w, "four-bar-crank-rocker"));
  View3dFeature& f = w.view3d();
  EXPECT_EQ(f.addPlane->shortcut(), QKeySequence("Shift+P"));
  const int steps = w.document()->undoStack()->count();
  QString refusal;
  bool stayedOpen = false;
  QTimer::singleShot(0, [&] {
    auto* d = qobject_cast<AddPlaneDialog*>(QApplication::activeModalWidget());
    ASSERT_TRUE(d);
    d->how->setCurrentIndex(2);
    d->name->setText("rocker");
    d->inclinedOrigin->setText("0, 0, 80");
    d->rho->setText("twenty");
    d->accept();
    refusal = d->problem->text();
    stayedOpen = d->isVisible();
    shot(d, "add-plane-dialog");
    d->rho->setText("23");
    d->accept();
  });
  f.addPlane->trigger();
  EXPECT_TRUE(stayedOpen);
  EXPECT_TRUE(refusal.contains("rho")) << refusal;
  const Mechanism& m = w.document()->design();
  const Plane* p = planeNamed(m, "rocker");
  ASSERT_TRUE(p);
  EXPECT_LT((p->yAxis - Vec3(0, std::cos(23 * M_PI / 180), std::sin(23 * M_PI / 180))).norm(),
            1e-15);
  EXPECT_EQ(w.document()->undoStack()->count(), steps + 1);
  EXPECT_TRUE(f.planeChooserAction->isVisible());
  EXPECT_EQ(f.planeChooser->currentText(), "rocker");
  EXPECT_EQ(w.scene()->shownPlane(), "rocker");
  w.document()->undoStack()->undo();
  EXPECT_FALSE(planeNamed(w.document()->design(), "rocker"));
  EXPECT_FALSE(f.planeChooserAction->isVisible());
  EXPECT_EQ(w.scene()->shownPlane(), "");
}

// A ball rod from the 3D view's picks: a click on a point of one plane, Ctrl+click on a point of
// another, Edit > Join with a Ball Rod: one undo step joining those two points.
TEST(AddBallRod, TwoPointsPickedIn3dAreJoinedAsOneUndoStep) {
  Rssr r;
  ASSERT_TRUE(r.v);
  QAction* join = r.w.view3d().addBallRod;
  EXPECT_EQ(join->shortcut(), QKeySequence("Shift+R"));
  EXPECT_FALSE(join->isEnabled());
  const PointId a = r.m().pointNamed(r.body("crank"), "A")->id;
  const PointId c = r.m().pointNamed(r.body("rocker"), "C")->id;
  QTest::mouseClick(r.v, Qt::LeftButton, {},
                    r.v->projection().toScreen(r.world("crank", "A")).toPoint());
  QTest::mouseClick(r.v, Qt::LeftButton, Qt::ControlModifier,
                    r.v->projection().toScreen(r.world("rocker", "C")).toPoint());
  Selection* sel = r.w.tools().selection();
  ASSERT_EQ(sel->points, (std::vector<PointId>{a, c}));
  EXPECT_TRUE(join->isEnabled());
  const size_t joints = r.m().joints.size();
  const int steps = r.w.document()->undoStack()->count();
  join->trigger();
  ASSERT_EQ(r.m().joints.size(), joints + 1);
  const Joint& rod = r.m().joints.back();
  EXPECT_EQ(toString(rod.type), std::string("ball-rod"));
  EXPECT_EQ(rod.a, a);
  EXPECT_EQ(rod.b, c);
  EXPECT_EQ(r.w.document()->undoStack()->count(), steps + 1);
  r.w.document()->undoStack()->undo();
  EXPECT_EQ(r.m().joints.size(), joints);
}

// A body in a plane parallel to the drawing but shifted and turned in it moves in the drawing
// plane's class frame: the 3D view lifts its points and slot ends through that frame. The
// Wanzer (a slotted disk) redrawn in such a plane, 20 mm out, is the same machine 20 mm along z:
// every plate corner (slot ends among them) where the planar one's is, plus (0, 0, 20).
TEST(View3dScene, APlaneParallelToTheDrawingIsLiftedThroughItsClassFrame) {
  const Mechanism planar = *loadMechanismFile(*resolveModel("wanzer-inversion-2")).mechanism;
  Mechanism lifted = planar;
  Plane p;
  p.name = "lifted";
  const double a = 30 * M_PI / 180;
  p.origin = Vec3(5, 3, 20);
  p.xAxis = Vec3(std::cos(a), std::sin(a), 0);
  p.yAxis = Vec3(-std::sin(a), std::cos(a), 0);
  lifted.planes = std::vector<Plane>{p};
  // The drawing's (x, y) in the plane's coordinates.
  auto inPlane = [&](const Vec2& v) {
    const Vec2 d = v - Vec2(5, 3);
    return Vec2(d.dot(Vec2(std::cos(a), std::sin(a))), d.dot(Vec2(-std::sin(a), std::cos(a))));
  };
  for (Body& b : lifted.bodies)
    if (!b.ground) b.plane = "lifted";
  for (Point& q : lifted.points)
    if (!lifted.body(q.body)->ground) q.pos = inPlane(q.pos);
  for (Slot& sl : lifted.slots) {
    if (lifted.body(sl.body)->ground) continue;
    sl.p0 = inPlane(sl.p0), sl.p1 = inPlane(sl.p1);
    if (sl.mid) sl.mid = inPlane(*sl.mid);
  }
  auto sceneOf = [](const Mechanism& m, double deg) {
    Document d;
    d.setContents(m, "");
    EXPECT_TRUE(d.solved()) << d.solveStatus().message;
    EXPECT_TRUE(d.setCrankDeg(deg).ok());
    View3dWidget v;
    v.setDocument(&d);
    return v.scene();
  };
  for (double deg : {0.0, 75.0}) {
    const Scene3d flat = sceneOf(planar, deg), up = sceneOf(lifted, deg);
    ASSERT_EQ(flat.plates.size(), up.plates.size());
    for (size_t i = 0; i < flat.plates.size(); ++i) {
      ASSERT_EQ(flat.plates[i].outline.size(), up.plates[i].outline.size()) << i;
      for (const Vec3& v : flat.plates[i].outline) {
        double nearest = INFINITY;
        for (const Vec3& u : up.plates[i].outline)
          nearest = std::min(nearest, (u - v - Vec3(0, 0, 20)).norm());
        EXPECT_LT(nearest, 1e-9) << "plate " << i << " at " << deg;
      }
    }
  }
}

// Slots in 3D: a ground arc written in the world in a plane square to the drawing, and a ground
// slot along z, drawn where the file puts them (the arc's path on the circle through its three
// points, from its first through its middle to its last); the Wanzer's slotted disk's slots on
// the disk where the solver has it. Looked at: view3d-ground-arc.png.
TEST(View3dScene, SlotsAreDrawnWhereTheFileAndTheSolverPutThem) {
  const std::string text = edgeOnText();
  const LoadResult loaded = parseMechanism(text);
  ASSERT_TRUE(loaded.mechanism) << loaded.error;
  Document d;
  d.setContents(*loaded.mechanism, "");
  ASSERT_TRUE(d.solved()) << d.solveStatus().message;
  View3dWidget v;
  v.resize(640, 480);
  v.setDocument(&d);
  const Scene3d s = v.scene();
  ASSERT_EQ(s.grooves.size(), 3u);
  // The arc through (0, -20, 0), (0, -35, 5), (0, -50, 0): centre (0, -35, -20), radius 25.
  const Scene3d::Groove& arc = s.grooves[0];
  EXPECT_TRUE(arc.ground);
  const Vec3 c(0, -35, -20);
  ASSERT_GE(arc.path.size(), 3u);
  EXPECT_LT((arc.path.front() - Vec3(0, -20, 0)).norm(), 1e-9);
  EXPECT_LT((arc.path.back() - Vec3(0, -50, 0)).norm(), 1e-9);
  double nearMid = INFINITY;
  for (size_t i = 0; i < arc.path.size(); ++i) {
    EXPECT_NEAR((arc.path[i] - c).norm(), 25.0, 1e-9) << i;
    EXPECT_NEAR(arc.path[i].x(), 0, 1e-12) << i;
    if (i > 0) EXPECT_LE((arc.path[i] - arc.path[i - 1]).norm(), 25.0 * 5 * M_PI / 180 + 1e-9);
    nearMid = std::min(nearMid, (arc.path[i] - Vec3(0, -35, 5)).norm());
  }
  EXPECT_LT(nearMid, 25.0 * 2.5 * M_PI / 180);
  const Scene3d::Groove& along = s.grooves[1];
  ASSERT_EQ(along.path.size(), 2u);
  EXPECT_LT((along.path[0] - Vec3(0, -60, 0)).norm(), 1e-12);
  EXPECT_LT((along.path[1] - Vec3(0, -60, 9)).norm(), 1e-12);
  // Three quarters of a turn about (10, -80, 0), radius 10, in the plane x = 10: from its first
  // point the long way round through its middle (not the quarter between its ends), every 5
  // degrees or less.
  const Scene3d::Groove& wide = s.grooves[2];
  const Vec3 cw(10, -80, 0);
  EXPECT_GE(wide.path.size(), 55u);
  EXPECT_LT((wide.path.front() - Vec3(10, -70, 0)).norm(), 1e-9);
  EXPECT_LT((wide.path.back() - Vec3(10, -80, -10)).norm(), 1e-9);
  double opposite = INFINITY;
  for (const Vec3& q : wide.path) {
    EXPECT_NEAR((q - cw).norm(), 10, 1e-9);
    opposite = std::min(opposite, (q - Vec3(10, -90, 0)).norm());
  }
  EXPECT_LT(opposite, 10 * 2.5 * M_PI / 180);
  v.showView(Projection::View::Isometric);
  shot(&v, "view3d-ground-arc");
  // A moving body's slots: their ends where the solver has them now.
  Document wanzer;
  wanzer.setContents(*loadMechanismFile(*resolveModel("wanzer-inversion-2")).mechanism, "");
  ASSERT_TRUE(wanzer.setCrankDeg(40).ok());
  View3dWidget w3;
  w3.setDocument(&wanzer);
  const Scene3d ws = w3.scene();
  const Mechanism& m = wanzer.design();
  ASSERT_EQ(ws.grooves.size(), m.slots.size());
  for (size_t i = 0; i < m.slots.size(); ++i) {
    const Slot& sl = m.slots[i];
    if (m.body(sl.body)->ground) continue;
    const Vec2 a = wanzer.kinematics().toWorld(sl.body, sl.p0),
               b = wanzer.kinematics().toWorld(sl.body, sl.p1);
    EXPECT_LT((ws.grooves[i].path.front() - Vec3(a.x(), a.y(), 0)).norm(), 1e-9) << sl.name;
    EXPECT_LT((ws.grooves[i].path.back() - Vec3(b.x(), b.y(), 0)).norm(), 1e-9) << sl.name;
  }
}

// On the drawing plane the ground arcs square to it are the segments they cover (their curves
// seen along its normal): g from y -50 to -20 at x 0, and w from -90 to -70 at x 10 (its ends
// are at -70 and -80; it turns through -90 on the way); the slot along z, seen end on, is not
// drawn. Looked at: edge-on-arcs.png.
TEST(PlaneChooser, AGroundArcSeenEdgeOnIsTheSegmentItCovers) {
  QTemporaryDir dir;
  const QString path = writeEdgeOn(dir);
  ASSERT_FALSE(path.isEmpty());
  MainWindow w;
  w.resize(1200, 800);
  ASSERT_TRUE(w.document()->open(path, nullptr));
  w.show();
  QApplication::processEvents();
  const Mechanism& m = w.document()->design();
  const BodyItem* ground = w.scene()->bodyItem(m.ground()->id);
  ASSERT_TRUE(ground);
  const BodyGeometry& g = ground->geometry();
  auto guide = [&](const char* name) -> const Guide* {
    for (size_t i = 0; i < g.slotIds.size(); ++i)
      if (m.slot(g.slotIds[i])->name == name) return &g.slots[i];
    return nullptr;
  };
  auto expectSpan = [](const Guide* s, double x, double lo, double hi, const char* name) {
    ASSERT_TRUE(s) << name;
    EXPECT_FALSE(s->arc) << name;
    EXPECT_NEAR(s->p0.x(), x, 1e-9) << name;
    EXPECT_NEAR(s->p1.x(), x, 1e-9) << name;
    EXPECT_NEAR(std::min(s->p0.y(), s->p1.y()), lo, 1e-9) << name;
    EXPECT_NEAR(std::max(s->p0.y(), s->p1.y()), hi, 1e-9) << name;
  };
  expectSpan(guide("g"), 0, -50, -20, "g");
  expectSpan(guide("w"), 10, -90, -70, "w");
  EXPECT_EQ(guide("z"), nullptr);
  w.canvas()->setZoom(5);
  w.canvas()->centerOn(5, -55);
  shot(&w, "edge-on-arcs");
  // Picked where it is drawn (for its Properties), but no point snaps onto it: its points are
  // off the plane shown.
  const double px = 0.2;  // mm a pixel
  const Pick onArc = pickAt(*w.scene(), Vec2(0.3, -40), px);
  ASSERT_TRUE(onArc.slot);
  EXPECT_EQ(m.slot(onArc.slot)->name, "g");
  EXPECT_NE(snapAt(*w.scene(), onArc, Vec2(0.3, -40), px, 0).kind, Snap::Kind::Slot);
  EXPECT_FALSE(pickAt(*w.scene(), Vec2(0.3, -10), px).slot);  // past its end
}

}  // namespace
}  // namespace linkage::ui
