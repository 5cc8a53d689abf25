// The canvas draws what the solver says: every item where the solver has its point, at every
// frame of a revolution of every example; the overlay's centres are the solver's; the view is in
// millimetres with y up, zooms at the cursor and fits the mechanism.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QGraphicsPathItem>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>

#include <QDockWidget>
#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "centres/centres_panel.h"
#include "document/document.h"
#include "draw/style.h"
#include "drawing.h"
#include "linkage/guide.h"
#include "linkage/io/model_lookup.h"
#include "mechanisms.h"
#include "tools/selection.h"
#include "tools/tool_overlay.h"
#include "window/features.h"
#include "window/message_strip.h"
#include "window/offscreen_window.h"

namespace linkage::ui {
namespace {

Vec2 fromQt(const QPointF& p) {
  return Vec2(p.x(), p.y());
}

// Every body item maps each of its sketch points to the solver's position; pins, blocks and
// outputs sit where the solver has their points.
void expectDrawnAtSolver(const CanvasScene& s, const Kinematics& k, const std::string& where) {
  const Mechanism& m = k.mechanism();
  for (const Point& p : m.points) {
    const BodyItem* b = s.bodyItem(p.body);
    ASSERT_TRUE(b) << where;
    const Vec2 drawn = fromQt(b->sceneTransform().map(QPointF(p.pos.x(), p.pos.y())));
    EXPECT_LT((drawn - k.position(p.id)).norm(), 1e-9) << where << " " << m.pointLabel(p.id);
  }
  for (const PinItem* pin : s.pinItems())
    EXPECT_LT((fromQt(pin->pos()) - k.position(m.joint(pin->joint())->a)).norm(), 1e-9) << where;
  for (const BlockItem* b : s.blockItems()) {
    const Joint* j = m.joint(b->joint());
    EXPECT_LT((fromQt(b->pos()) - k.position(j->a)).norm(), 1e-9) << where;
    // Along the slot where the block is: its line, or an arc's tangent there.
    const Slot* sl = m.slot(j->slot);
    const Transform T = k.bodyTransform(sl->body);
    const Vec2 along = T.R * guideOf(*sl)->tangentAt(T.inverse(k.position(j->a)));
    const double a = b->rotation() * M_PI / 180;
    EXPECT_LT(std::abs(cross(Vec2(std::cos(a), std::sin(a)), along)), 1e-9) << where;
  }
  ASSERT_EQ(s.outputItems().size(), m.outputs.size());
  for (const OutputItem* o : s.outputItems())
    EXPECT_LT((fromQt(o->pos()) - k.position(o->point())).norm(), 1e-9) << where;
}

TEST(Canvas, EveryExampleIsDrawnAtTheSolversPositionsThroughARevolution) {
  const std::vector<std::string> names = listExamples();
  ASSERT_GE(names.size(), 5u);
  for (const std::string& name : names) {
    MainWindow w;
    w.resize(1000, 700);
    QString why;
    ASSERT_TRUE(w.openExample(QString::fromStdString(name), &why)) << why.toStdString();
    Document* d = w.document();
    ASSERT_TRUE(d->solved()) << name << ": " << d->solveStatus().message;
    w.centres().show->setChecked(true);
    for (int f = 0; f <= 72; ++f) {
      const Status st = d->setCrankDeg(5.0 * f);
      ASSERT_TRUE(st.ok()) << name << " " << st.message;
      expectDrawnAtSolver(*w.scene(), d->kinematics(), name + " at " + std::to_string(5 * f));
    }
  }
}

TEST(Canvas, OverlayShowsTheSolversCentres) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  Document* d = w.document();
  CanvasScene* s = w.scene();
  EXPECT_TRUE(s->centresItem()->centres().empty());  // hidden: nothing computed
  w.centres().show->setChecked(true);
  for (double deg : {0.0, 33.0, 190.0}) {
    ASSERT_TRUE(d->setCrankDeg(deg).ok());
    const InstantCentres ref = computeInstantCentres(d->kinematics());
    const auto& shown = s->centresItem()->centres();
    ASSERT_EQ(shown.size(), ref.centres.size());
    ASSERT_EQ(shown.size(), 15u);
    for (size_t i = 0; i < shown.size(); ++i) {
      const InstantCentre& c = ref.centres[i];
      EXPECT_EQ(shown[i].i, c.i);
      EXPECT_EQ(shown[i].j, c.j);
      EXPECT_EQ(shown[i].determined, c.determined);
      EXPECT_EQ(shown[i].atInfinity, c.atInfinity());
      EXPECT_EQ(shown[i].status, c.status);
      if (c.determined) EXPECT_LT((shown[i].at - Vec2(c.h.x(), c.h.y())).norm(), 1e-12);
    }
  }
  w.centres().show->setChecked(false);
  EXPECT_FALSE(s->centresItem()->isVisible());
}

TEST(Canvas, ViewIsMillimetresWithYUpAndZoomsAtTheCursor) {
  MainWindow w;
  w.resize(1000, 700);
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.show();
  CanvasView* v = w.canvas();
  v->fitToMechanism();
  // y up: a point higher in millimetres is higher on screen.
  const QPoint low = v->mapFromScene(QPointF(0, 0)), high = v->mapFromScene(QPointF(0, 10));
  EXPECT_LT(high.y(), low.y());
  EXPECT_EQ(high.x(), low.x());
  // The whole mechanism is in view after a fit.
  const QRectF r = w.scene()->mechanismRect();
  const QRect vr = v->viewport()->rect();
  for (const QPointF& c : {r.topLeft(), r.bottomRight()})
    EXPECT_TRUE(vr.contains(v->mapFromScene(c))) << c.x() << "," << c.y();
  // Wheel zoom keeps the point under the cursor where it is.
  const QPoint at(300, 250);
  const QPointF before = v->mapToScene(at);
  const double z = v->zoom();
  QWheelEvent wheel(QPointF(at), v->viewport()->mapToGlobal(QPointF(at)), QPoint(), QPoint(0, 120),
                    Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(v->viewport(), &wheel);
  EXPECT_NEAR(v->zoom(), z * 1.2, 1e-9 * z);
  EXPECT_LT((fromQt(v->mapToScene(at)) - fromQt(before)).norm(), 1.5 / v->zoom());
  // Symbols keep their size on screen: the scene knows millimetres per pixel.
  EXPECT_NEAR(w.scene()->pixelSize(), 1 / v->zoom(), 1e-12);
}

TEST(Canvas, SpaceTappedPlaysAndSpaceDragPans) {
  MainWindow w;
  w.resize(1000, 700);
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.show();
  CanvasView* v = w.canvas();
  v->setFocus();
  QSignalSpy taps(v, &CanvasView::spaceTapped);
  QTest::keyClick(v, Qt::Key_Space);
  EXPECT_EQ(taps.count(), 1);
  EXPECT_TRUE(w.animator()->playing());
  QTest::keyClick(v, Qt::Key_Space);
  EXPECT_FALSE(w.animator()->playing());
  // Held Space with a drag pans, and is no tap.
  const QPointF centre = v->mapToScene(v->viewport()->rect().center());
  QTest::keyPress(v, Qt::Key_Space);
  QTest::mousePress(v->viewport(), Qt::LeftButton, {}, QPoint(200, 200));
  QMouseEvent move(QEvent::MouseMove, QPointF(260, 230),
                   v->viewport()->mapToGlobal(QPointF(260, 230)), Qt::NoButton, Qt::LeftButton,
                   Qt::NoModifier);
  QApplication::sendEvent(v->viewport(), &move);
  QTest::mouseRelease(v->viewport(), Qt::LeftButton, {}, QPoint(260, 230));
  QTest::keyRelease(v, Qt::Key_Space);
  EXPECT_EQ(taps.count(), 2);
  EXPECT_FALSE(w.animator()->playing());
  const QPointF moved = v->mapToScene(v->viewport()->rect().center());
  EXPECT_NEAR(moved.x() - centre.x(), -60 / v->zoom(), 1.5 / v->zoom());
  EXPECT_NEAR(moved.y() - centre.y(), 30 / v->zoom(), 1.5 / v->zoom());  // y up
}

TEST(Canvas, TracedPathsFollowTheOutputPoints) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.view().showTraces->setChecked(true);
  const auto& traces = w.scene()->traceItems();
  ASSERT_EQ(traces.size(), 1u);
  const QPainterPath& path = traces[0]->path();
  ASSERT_GE(path.elementCount(), 360);
  // Every sampled point of the path is where the coupler point is at that angle.
  Kinematics k = w.document()->kinematics();
  for (int i = 0; i <= 360; i += 40) {
    ASSERT_TRUE(k.moveTo(i).ok());
    const QPointF e = path.elementAt(i);
    EXPECT_LT((fromQt(e) - k.position(k.mechanism().outputs[0])).norm(), 1e-9) << i;
  }
  w.view().showTraces->setChecked(false);
  EXPECT_TRUE(w.scene()->traceItems().empty());
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

// The homework's check, on the canvas: the chain of centres for the needle at the drawn
// position (inversion 2) goes through IC(2,6), and its distances are drawn as dimensions.
TEST(Canvas, VelocityChainIsWrittenOutAndItsDistancesDrawn) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  w.show();
  w.centres().dock->raise();  // its tab in front: the panel works only while seen
  QApplication::processEvents();
  CentresPanel* panel = w.centres().panel();
  ASSERT_TRUE(panel->isVisible());
  ASSERT_TRUE(panel->chain());  // the first output point is chosen
  const VelocityChain& ch = *panel->chain();
  ASSERT_TRUE(ch.status.ok()) << ch.status.message;
  ASSERT_EQ(ch.steps.size(), 1u);
  EXPECT_EQ(ch.steps[0].from, 2);
  EXPECT_EQ(ch.steps[0].to, 6);
  // By the chain as by the solver (the solver's velocity is exact).
  const Vec2 exact = w.document()->kinematics().velocity(ch.point);
  EXPECT_LT((ch.velocity - exact).norm(), 1e-9 * exact.norm());
  EXPECT_NE(panel->chainText().indexOf("IC(2,6)"), -1);
  // Drawn with the instant centres: |IC(1,2) P| with its length; IC(1,6) is at infinity, so
  // that is the only distance.
  EXPECT_TRUE(w.scene()->chainItem()->dimensions().empty());
  w.centres().show->setChecked(true);
  const auto& dims = w.scene()->chainItem()->dimensions();
  ASSERT_EQ(dims.size(), 1u);
  EXPECT_LT((dims[0].b - ch.steps[0].centre).norm(), 1e-12);
  EXPECT_NEAR((dims[0].b - dims[0].a).norm(), ch.steps[0].fromArm, 1e-12);
  // It follows the animation.
  ASSERT_TRUE(w.document()->setCrankDeg(40).ok());
  QApplication::processEvents();
  ASSERT_TRUE(panel->chain());
  const Vec2 v40 = w.document()->kinematics().velocity(panel->chain()->point);
  EXPECT_LT((panel->chain()->velocity - v40).norm(), 1e-9 * v40.norm());
}

// A machine in space: the centres panel gives each centre's plane, and says there is none
// between the crank and the rocker (planes not parallel) instead of a number; the chain to the
// rocker's point says why there is none.
TEST(Canvas, CentresOfAMachineInSpaceNameTheirPlaneAndNoneAcross) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("rssr-crank-rocker"));
  w.show();
  w.centres().dock->raise();
  ASSERT_TRUE(w.document()->setCrankDeg(40).ok());
  QApplication::processEvents();
  QTableWidget* t = w.centres().panel()->table();
  ASSERT_EQ(t->rowCount(), 3);
  EXPECT_EQ(t->item(0, 5)->text(), QStringLiteral("primary, in plane drawing"));
  EXPECT_EQ(t->item(1, 5)->text(), QStringLiteral("primary, in plane rocker"));
  EXPECT_EQ(t->item(2, 0)->text(), QStringLiteral("2,3"));
  EXPECT_EQ(t->item(2, 2)->text(), QStringLiteral("\u2013"));
  EXPECT_EQ(t->item(2, 5)->text(), QStringLiteral("none: their planes are not parallel"));
  EXPECT_NE(w.centres().panel()->chainText().indexOf("IC(2,3) does not exist"), -1)
      << w.centres().panel()->chainText().toStdString();
}

// No two labels of a paint overlap, nor the velocity chain's dimension (painted first): the
// Wanzer's centres all labelled beside it; a machine of 31 bodies (465 centres) labels what
// has room and draws the rest unlabelled, in the same frame time order as its mechanism.
TEST(Canvas, CentreLabelsNeverOverlapEachOtherOrTheChain) {
  auto disjoint = [](const std::vector<QRectF>& r) {
    for (size_t i = 0; i < r.size(); ++i)
      for (size_t j = i + 1; j < r.size(); ++j)
        if (r[i].intersects(r[j])) return false;
    return true;
  };
  MainWindow w;
  w.resize(1400, 950);
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  w.show();
  w.centres().dock->raise();
  w.centres().show->setChecked(true);
  ASSERT_TRUE(w.document()->setCrankDeg(30).ok());
  QApplication::processEvents();
  w.canvas()->viewport()->grab();
  const LabelBoard& board = w.scene()->context()->labels;
  ASSERT_EQ(w.scene()->chainItem()->dimensions().size(), 1u);
  // The chain's label, the output point's name and the 15 centres (those off the view with
  // their arrows); none of them is left out at this size.
  EXPECT_GE(board.size(), 1 + 1 + 15);
  EXPECT_TRUE(disjoint(board.rects()));
  Document* d = w.document();
  d->setContents(linkage::test::shaftMachine(14), QString(), "machine");
  QApplication::processEvents();
  w.canvas()->fitToMechanism();
  w.canvas()->viewport()->grab();
  EXPECT_GT(board.size(), 100);
  EXPECT_LT(board.size(), 465);  // not every one has room
  EXPECT_TRUE(disjoint(board.rects()));
}

// `linkage --screenshot --angle 30 --ics`: the chain of centres, whose text is laid out at
// most ten times a second, is that of 30 degrees when the picture is taken, as the rest is.
TEST(Canvas, AScreenshotIsOfOnePose) {
  MainWindow w;
  OffscreenOptions o;
  o.model = "wanzer-inversion-2";
  o.ics = true;
  o.angleDeg = 30;
  ASSERT_EQ(setUpOffscreen(w, o), 0);
  EXPECT_NE(w.centres().panel()->stepsText().indexOf("at crank 30.000"), -1)
      << w.centres().panel()->stepsText();
  EXPECT_NE(w.centres().panel()->stepsText().indexOf("741.070 mm/s"), -1);
}

// Hovering a centre draws its Kennedy lines; leaving it draws the chosen row's again.
TEST(Canvas, HoveredCentreShowsItsKennedyLines) {
  MainWindow w;
  w.resize(1100, 750);
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  w.show();
  w.centres().show->setChecked(true);
  QApplication::processEvents();
  CanvasView* v = w.canvas();
  const auto& cs = w.scene()->centresItem()->centres();
  const Drawing::Centre* kennedy = nullptr;
  for (const Drawing::Centre& c : cs)
    if (c.status == CentreStatus::Kennedy && !c.atInfinity &&
        v->viewport()->rect().contains(v->mapFromScene(toQt(c.at))))
      kennedy = &c;
  ASSERT_TRUE(kennedy);
  QTest::mouseMove(v->viewport(), v->mapFromScene(toQt(kennedy->at)));
  EXPECT_EQ(w.scene()->centresItem()->chosen(), std::make_pair(kennedy->i, kennedy->j));
  EXPECT_EQ(kennedy->lines.size(), 2u);
  QTest::mouseMove(v->viewport(), QPoint(5, 5));
  EXPECT_EQ(w.scene()->centresItem()->chosen(), std::make_pair(0, 0));
}

// Work only when needed: accelerations only while the readout that shows them is visible.
TEST(Canvas, AccelerationsOnlyWhileShown) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.show();
  QApplication::processEvents();
  EXPECT_TRUE(w.document()->kinematics().accelerations());
  w.properties().dock->hide();
  QApplication::processEvents();
  EXPECT_FALSE(w.document()->kinematics().accelerations());
  ASSERT_TRUE(w.openExample("wanzer-inversion-1"));  // a new solver keeps the choice
  EXPECT_FALSE(w.document()->kinematics().accelerations());
  w.properties().dock->show();
  QApplication::processEvents();
  // Back, but behind the instant centres' tab: still not seen.
  EXPECT_EQ(w.document()->kinematics().accelerations(),
            !w.properties().dock->visibleRegion().isEmpty());
  w.properties().dock->raise();
  QApplication::processEvents();
  EXPECT_TRUE(w.document()->kinematics().accelerations());
}

// A plate a kilometre long (a point typed 1e6 mm away) at 4 pixels a millimetre: it is drawn
// where it is and nowhere else. Its polygon is cut to the painted area first (at full size the
// raster engine took 0.4 s a paint on its slow path; the random-input test found it).
TEST(Canvas, APlateFarLargerThanTheViewIsDrawnWhereItIs) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  CanvasView* v = w.canvas();
  v->setZoom(4);
  Document* doc = w.document();
  const Vec2 a = doc->kinematics().position(*doc->design().findPoint("coupler.A"));
  v->centerOn(a.x() + 30, a.y());
  QApplication::processEvents();
  const QImage before = v->viewport()->grab().toImage();
  Mechanism m = doc->design();
  m.addPoint(m.bodyNamed("coupler")->id, "far", a + Vec2(1e6, 0));
  doc->setDesign(m);
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  QApplication::processEvents();
  const QImage after = v->viewport()->grab().toImage();
  // Just above the plate's lower edge (the line from A to the far point), 30 mm along: inside
  // the plate now, outside the coupler before. Just below it: outside both.
  const QPoint inside = v->mapFromScene(QPointF(a.x() + 30, a.y() + 2));
  const QPoint outside = v->mapFromScene(QPointF(a.x() + 30, a.y() - 2));
  ASSERT_TRUE(before.rect().contains(inside) && before.rect().contains(outside));
  EXPECT_NE(after.pixel(inside), before.pixel(inside));
  EXPECT_EQ(after.pixel(outside), before.pixel(outside));
  // And the plate runs on to the right edge of the view.
  const QPoint edge =
      v->mapFromScene(v->mapToScene(QPoint(v->viewport()->width() - 5, 0)).x(), a.y() + 2);
  EXPECT_NE(after.pixel(edge), before.pixel(edge));
  shot(v->viewport(), "canvas-kilometre-plate");
}

// The message strip lies over the bottom of the canvas: Fit places the mechanism in the part
// it leaves free (a long red message hid the ground pivots).
TEST(Canvas, FitLeavesThePartUnderTheMessageStripFree) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  MessageStrip* strip = w.messageStrip();
  strip->setMessage(QString("a long warning ").repeated(40), true);
  QApplication::processEvents();
  ASSERT_GE(strip->height(), 4 * strip->fontMetrics().height());
  w.view().fit->trigger();
  const QRect drawn = w.canvas()->mapFromScene(w.scene()->mechanismRect()).boundingRect();
  EXPECT_LT(drawn.bottom(), strip->geometry().top()) << drawn.bottom();
  EXPECT_GT(drawn.top(), 0);
  // Every ground pivot in sight above the strip.
  for (const Point& p : w.document()->design().points)
    if (p.body == w.document()->design().bodies[0].id)
      EXPECT_LT(w.canvas()->mapFromScene(toQt(p.pos)).y(), strip->geometry().top());
  // Centred in that part, as large as it allows: it fills its height (less the margins).
  const QRect free = w.canvas()->uncoveredRect();
  EXPECT_EQ(free.bottom() + 1, strip->geometry().top());
  EXPECT_NEAR(drawn.center().y(), free.center().y(), 2);
  shot(&w, "fit-above-strip");
}

// Coordinates the solver refuses (beyond 1e12 mm) are kept in the design, as typed, and the
// document says why it cannot solve; the canvas draws nothing of them and does not stall (a
// ground slot whose length overflowed to infinity once hatched it forever).
TEST(Canvas, GeometryTheSolverRefusesIsNotDrawnAndSaysWhy) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  Document* doc = w.document();
  Mechanism m = doc->design();
  m.addSlot(m.ground()->id, "far", Vec2(-1e300, 0), Vec2(1e300, 1e300));
  doc->setDesign(m);
  QApplication::processEvents();
  EXPECT_FALSE(doc->solved());
  EXPECT_NE(doc->solveStatus().message.find("1e12"), std::string::npos)
      << doc->solveStatus().message;
  EXPECT_EQ(doc->design().slots.size(), 1u);  // kept as typed
  w.canvas()->viewport()->repaint();          // and painted, with the far slot left out
}

// Issue 26: a selected arc slot was outlined as the capsule around its chord. Its outline runs
// along the arc: it holds the arc's middle, and not the chord's, at any pose of its body.
TEST(Canvas, ASelectedArcSlotIsOutlinedAlongItsArc) {
  Mechanism m;
  const BodyId b = m.addBody("plate");
  const SlotId id =
      m.addArcSlot(b, "arc", Vec2(-50, 0), Vec2(0, 50), Vec2(50, 0));  // a half circle, R 50
  const Slot& s = *m.slot(id);
  const double px = 0.1;  // mm per pixel
  for (const Transform pose : {Transform(), Transform{Rot::of(0.7), Vec2(30, -12)}}) {
    const QPolygonF outline = slotOutline(s, pose, px);
    EXPECT_TRUE(outline.containsPoint(toQt(pose * Vec2(0, 50)), Qt::OddEvenFill));
    EXPECT_TRUE(outline.containsPoint(toQt(pose * Vec2(50 * std::sqrt(0.5), 50 * std::sqrt(0.5))),
                                      Qt::OddEvenFill));
    EXPECT_FALSE(outline.containsPoint(toQt(pose * Vec2(0, 0)), Qt::OddEvenFill));
    // Every vertex within the channel's half width and the margin of the circle.
    const double r = (CanvasStyle::channelWidth / 2 + 3) * px;
    for (const QPointF& q : outline) {
      const Vec2 local = pose.inverse(Vec2(q.x(), q.y()));
      EXPECT_NEAR(local.norm(), 50, r * 1.01) << q.x() << ", " << q.y();
    }
  }
  // A straight slot: the capsule around its two ends, as before.
  const SlotId line = m.addSlot(b, "line", Vec2(0, 0), Vec2(40, 0));
  const QPolygonF capsuleOutline = slotOutline(*m.slot(line), Transform(), px);
  EXPECT_TRUE(capsuleOutline.containsPoint(QPointF(20, 0), Qt::OddEvenFill));
  EXPECT_FALSE(capsuleOutline.containsPoint(QPointF(20, 5), Qt::OddEvenFill));
  // The curved guide's arc selected, to look at.
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "curved-guide"));
  const Mechanism& guide = w.document()->design();
  ASSERT_TRUE(guide.slots.at(0).mid);
  w.tools().selection()->add(guide.slots[0].id);
  QApplication::processEvents();
  shot(&w, "arc-slot-selected");
}

}  // namespace
}  // namespace linkage::ui
