// The design overlays on the canvas (issue 13): the mechanism drawn at the extreme positions
// findLimits reports, each body where the solver puts it at that crank angle; the transmission
// arcs at every pose equal to transmissionAngle, drawn between the lines they measure, red
// exactly outside the band; nothing computed while they are off; their actions, shortcuts and
// settings.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTest>
#include <cmath>
#include <set>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "design/checks_panel.h"
#include "design/design_choices.h"
#include "design/design_overlays.h"
#include "design/extremes_item.h"
#include "design/extremes_notes.h"
#include "design/transmission_item.h"
#include "document/commands.h"
#include "document/document.h"
#include "window/features.h"
#include "window/message_strip.h"
#include "window/offscreen_window.h"

namespace linkage::ui {
namespace {

constexpr double kDeg = M_PI / 180;

// The pose of every body and pin the overlay draws at each extreme is the solver's at that
// crank angle (a copy of the document's solver turned there on its own), and the point is at
// the extreme's value there.
void expectPosesAtLimits(const Document& d, const ExtremePoses& shown, const LimitMeasure& what,
                         const char* name) {
  const Limits l = findLimits(d.kinematics(), what);
  ASSERT_TRUE(l.status.ok()) << name;
  ASSERT_EQ(shown.poses.size(), l.extremes.size()) << name;
  ASSERT_FALSE(l.extremes.empty()) << name;
  EXPECT_EQ(shown.limits.stroke, l.stroke) << name;
  for (size_t i = 0; i < l.extremes.size(); ++i) {
    const ExtremePose& p = shown.poses[i];
    EXPECT_EQ(p.extreme.crankDeg, l.extremes[i].crankDeg) << name;
    EXPECT_EQ(p.extreme.value, l.extremes[i].value) << name;
    EXPECT_EQ(p.extreme.max, l.extremes[i].max) << name;
    Kinematics k = d.kinematics();
    ASSERT_TRUE(k.moveTo(l.extremes[i].crankDeg).ok()) << name;
    ASSERT_EQ(p.drawing.bodies.size(), d.design().bodies.size()) << name;
    for (const Drawing::Body& b : p.drawing.bodies) {
      const Transform t = k.bodyTransform(b.id);
      EXPECT_NEAR(b.pose.R.c, t.R.c, 1e-9) << name << " " << b.name;
      EXPECT_NEAR(b.pose.R.s, t.R.s, 1e-9) << name << " " << b.name;
      EXPECT_LT((b.pose.t - t.t).norm(), 1e-9) << name << " " << b.name;
    }
    for (const JointSymbol& pin : p.drawing.joints)
      EXPECT_LT((pin.at - k.position(d.design().joint(pin.joint)->a)).norm(), 1e-9) << name;
    if (what.body) {
      EXPECT_NEAR(k.bodyAngle(what.body) / kDeg, l.extremes[i].value, 1e-9) << name;
    } else {
      EXPECT_LT((p.at - k.position(what.point)).norm(), 1e-9) << name;
      EXPECT_NEAR(p.at.dot(what.direction.normalized()), l.extremes[i].value, 1e-9) << name;
    }
  }
}

TEST(DesignOverlays, ExtremePositionsAreWhereFindLimitsSays) {
  for (const char* name : {"needle-876-alpha-35", "wanzer-inversion-2", "four-bar-crank-rocker",
                           "slider-crank-22a-lambda-0.3"}) {
    MainWindow w;
    ASSERT_TRUE(w.openExample(name));
    Document* d = w.document();
    // Wherever the crank is when the overlay is turned on.
    ASSERT_TRUE(d->setCrankDeg(200).ok());
    w.designChecks().showExtremes->setChecked(true);
    const ExtremesItem* item = w.designChecks().overlays()->extremesItem();
    EXPECT_TRUE(item->isVisible());
    const PointId out = d->design().outputs.front();
    const LimitMeasure what = LimitMeasure::along(out, defaultDirection(d->design(), out));
    expectPosesAtLimits(*d, item->poses(), what, name);
    EXPECT_EQ(d->crankDeg(), 200) << name;  // the document's pose stays
  }
}

TEST(DesignOverlays, TheWanzersDwellShowsFourPositions) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  w.designChecks().showExtremes->setChecked(true);
  EXPECT_EQ(w.designChecks().overlays()->extremesItem()->poses().poses.size(), 4u);
}

TEST(DesignOverlays, ExtremesFollowTheSubjectAndEdits) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("needle-876-alpha-0"));
  Document* d = w.document();
  w.designChecks().showExtremes->setChecked(true);
  DesignOverlays* o = w.designChecks().overlays();
  const int before = o->extremeSearches();
  // A body's angle.
  w.designChecks().choices()->setSubject({QString(), QStringLiteral("lever"), std::nullopt});
  EXPECT_EQ(o->extremeSearches(), before + 1);
  const BodyId lever = d->design().bodyNamed("lever")->id;
  expectPosesAtLimits(*d, o->extremesItem()->poses(), LimitMeasure::angleOf(lever), "lever");
  // A point along a direction of the user's.
  w.designChecks().choices()->setSubject({QStringLiteral("rod.E"), QString(), Vec2(1, 1)});
  const PointId e = *d->design().findPoint("rod.E");
  expectPosesAtLimits(*d, o->extremesItem()->poses(), LimitMeasure::along(e, Vec2(1, 1)), "E");
  // An edit: computed again for the new design.
  Mechanism m = d->design();
  m.point(*m.findPoint("ground.F"))->pos.x() += 0.5;
  m.point(*m.findPoint("rocker.F"))->pos.x() += 0.5;
  const int edits = o->extremeSearches();
  editDesign(d, "Move F", m);
  ASSERT_TRUE(d->solved());
  EXPECT_EQ(o->extremeSearches(), edits + 1);
  expectPosesAtLimits(*d, o->extremesItem()->poses(), LimitMeasure::along(e, Vec2(1, 1)), "F");
}

TEST(DesignOverlays, ExtremesAreDrawnOnTheCanvas) {
  MainWindow w;
  w.resize(1000, 700);
  ASSERT_TRUE(w.openExample("needle-876-alpha-35"));
  w.show();
  QApplication::processEvents();
  w.canvas()->fitToMechanism();
  const QImage off = w.canvas()->viewport()->grab().toImage();
  w.designChecks().showExtremes->setChecked(true);
  QApplication::processEvents();
  const QImage on = w.canvas()->viewport()->grab().toImage();
  ASSERT_EQ(off.size(), on.size());
  int changed = 0;
  for (int y = 0; y < on.height(); ++y)
    for (int x = 0; x < on.width(); ++x) changed += on.pixel(x, y) != off.pixel(x, y);
  EXPECT_GT(changed, 500);
  shot(&w, "design-extremes");
  // Across the view: the rod's E along x, the labels above or below the dimension.
  w.designChecks().choices()->setSubject({QStringLiteral("rod.E"), QString(), Vec2(1, 0)});
  QApplication::processEvents();
  EXPECT_GE(w.designChecks().overlays()->extremesItem()->poses().poses.size(), 2u);
  shot(&w, "design-extremes-across");
}

// A small window (900 x 650, the plots and centres shown, a message of three lines over the
// canvas): the extremes' labels stay in the part of the view the message strip leaves free,
// none on another label of the paint (the centres', the chain's, the output's).
TEST(DesignOverlays, ExtremesLabelsStayAboveTheMessageStripApart) {
  MainWindow w;
  OffscreenOptions o;
  o.model = "wanzer-inversion-2";
  o.extremes = o.plots = o.ics = true;
  o.size = QSize(900, 650);
  ASSERT_EQ(setUpOffscreen(w, o), 0);
  w.messageStrip()->setMessage(QString("a message long enough to wrap ").repeated(9), false);
  QApplication::processEvents();
  CanvasView* v = w.canvas();
  ASSERT_GT(v->viewport()->height() - v->uncoveredRect().height(), 50);
  v->viewport()->grab();
  shot(&w, "extremes-small-window");
  const std::vector<QRectF>& notes = w.designChecks().overlays()->extremesNotes()->labelRects();
  ASSERT_EQ(notes.size(), 1 + w.designChecks().overlays()->extremesItem()->poses().poses.size());
  const QRectF free = v->uncoveredRect();
  for (const QRectF& r : notes) EXPECT_TRUE(free.contains(r)) << r.top() << " " << r.bottom();
  const std::vector<QRectF>& all = w.scene()->context()->labels.rects();
  EXPECT_GE(all.size(), notes.size() + 5);  // the centres' too
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j)
      EXPECT_FALSE(all[i].intersects(all[j])) << i << " " << j;
}

// Each arc is transmissionAngle's value at the pose, spans exactly that angle between the lines
// it measures (the two links, or the rod and its slot's normal), and sits at the joint.
void expectArcsAtPose(const Kinematics& k, const TransmissionItem& item, const std::string& at) {
  const std::vector<TransmissionJoint> joints = transmissionJoints(k.mechanism());
  ASSERT_EQ(item.arcs().size(), joints.size()) << at;
  for (size_t i = 0; i < joints.size(); ++i) {
    const TransmissionArc& a = item.arcs()[i];
    const TransmissionJoint& t = joints[i];
    EXPECT_EQ(a.index, static_cast<int>(i));
    EXPECT_EQ(a.mu, transmissionAngle(k, t).deg) << at << " " << t.label;
    EXPECT_NEAR(a.sweepDeg, a.mu, 1e-9) << at << " " << t.label;
    EXPECT_LT((a.centre - t.linkAt.at(k)).norm(), 1e-12) << at;
    const Vec2 start = a.from;
    const double end = std::atan2(a.from.y(), a.from.x()) + a.sweepDeg * kDeg;
    const Vec2 stop(std::cos(end), std::sin(end));
    const Vec2 rod = (t.linkOuter.at(k) - a.centre).normalized();
    const Vec2 other = t.kind == TransmissionKind::Dyad
                           ? Vec2((t.otherOuter.at(k) - t.otherAt.at(k)).normalized())
                           : a.normal;
    if (t.kind != TransmissionKind::Dyad) {
      const Kinematics::Segment s = k.slotEnds(t.slot);
      EXPECT_NEAR(a.normal.dot((s.p1 - s.p0).normalized()), 0, 1e-12) << at;
    }
    // The arc runs from one line to the other, either way round.
    const double ends = std::min((start - rod).norm() + (stop - other).norm(),
                                 (start - other).norm() + (stop - rod).norm());
    EXPECT_LT(ends, 1e-9) << at << " " << t.label;
  }
}

TEST(DesignOverlays, TransmissionArcsAreTheSolversAnglesAtEveryPose) {
  for (const char* name : {"needle-876-alpha-35", "slider-crank-22a-lambda-0.5",
                           "four-bar-crank-rocker", "wanzer-inversion-1"}) {
    MainWindow w;
    ASSERT_TRUE(w.openExample(name));
    Document* d = w.document();
    w.designChecks().showTransmission->setChecked(true);
    const TransmissionItem* item = w.designChecks().overlays()->transmissionItem();
    EXPECT_TRUE(item->isVisible());
    for (double deg : {0.0, 37.0, 90.0, 181.5, 270.0, 333.3, 725.0}) {
      ASSERT_TRUE(d->setCrankDeg(deg).ok()) << name << " " << deg;
      expectArcsAtPose(d->kinematics(), *item, std::string(name) + " at " + std::to_string(deg));
    }
    if (std::string(name) == "needle-876-alpha-35") EXPECT_EQ(item->arcs().size(), 3u);
  }
}

TEST(DesignOverlays, ArcsTurnRedExactlyOutsideTheBand) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("needle-876-alpha-35"));
  ASSERT_TRUE(w.document()->setCrankDeg(60).ok());
  w.designChecks().showTransmission->setChecked(true);
  DesignChoices* c = w.designChecks().choices();
  const TransmissionBand was = c->band();
  const TransmissionItem* item = w.designChecks().overlays()->transmissionItem();
  const QColor warning = w.scene()->style().warning;
  ASSERT_EQ(item->arcs().size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const double mu = item->arcs()[i].mu;
    auto expectOutside = [&](bool out) {
      EXPECT_EQ(item->arcs()[i].outside, out)
          << i << " band " << c->band().lo << " " << c->band().hi;
      EXPECT_EQ(item->colourOf(item->arcs()[i]) == warning, out) << i;
    };
    ASSERT_TRUE(c->setBand({mu, 180}));  // on the band's edge: inside
    expectOutside(false);
    ASSERT_TRUE(c->setBand({std::nextafter(mu, 180.0), 180}));
    expectOutside(true);
    ASSERT_TRUE(c->setBand({0, mu}));
    expectOutside(false);
    ASSERT_TRUE(c->setBand({0, std::nextafter(mu, 0.0)}));
    expectOutside(true);
  }
  // The default band: the 876 at alpha = 35 stays in it at this pose.
  ASSERT_TRUE(c->setBand({30, 150}));
  for (const TransmissionArc& a : item->arcs()) EXPECT_FALSE(a.outside) << a.mu;
  EXPECT_FALSE(c->setBand({100, 90}));  // refused
  EXPECT_EQ(c->band().lo, 30);
  c->setBand(was);
}

TEST(DesignOverlays, NothingIsComputedWhileTheyAreOff) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("needle-876-alpha-0"));
  Document* d = w.document();
  DesignOverlays* o = w.designChecks().overlays();
  ASSERT_FALSE(w.designChecks().showExtremes->isChecked());
  ASSERT_FALSE(w.designChecks().showTransmission->isChecked());
  auto work = [&] {
    for (double deg : {10.0, 20.0, 30.0}) ASSERT_TRUE(d->setCrankDeg(deg).ok());
    Mechanism m = d->design();
    m.point(*m.findPoint("ground.C"))->pos.y() += 0.25;
    editDesign(d, "Move C", m);
    w.designChecks().choices()->setSubject({QStringLiteral("rod.E"), QString(), std::nullopt});
    w.designChecks().choices()->setSubject({});
  };
  work();
  EXPECT_EQ(o->extremeSearches(), 0);
  EXPECT_EQ(o->transmissionUpdates(), 0);
  EXPECT_TRUE(o->extremesItem()->poses().poses.empty());
  EXPECT_TRUE(o->transmissionItem()->arcs().empty());
  EXPECT_FALSE(o->extremesItem()->isVisible());
  EXPECT_FALSE(o->transmissionItem()->isVisible());
  // On: computed; the arcs once per pose change.
  w.designChecks().showExtremes->setChecked(true);
  w.designChecks().showTransmission->setChecked(true);
  EXPECT_EQ(o->extremeSearches(), 1);
  const int arcs = o->transmissionUpdates();
  EXPECT_GE(arcs, 1);
  ASSERT_TRUE(d->setCrankDeg(45).ok());
  EXPECT_EQ(o->transmissionUpdates(), arcs + 1);
  EXPECT_EQ(o->extremeSearches(), 1);  // a pose is not a design
  // Off again: nothing more, and nothing drawn.
  w.designChecks().showExtremes->setChecked(false);
  w.designChecks().showTransmission->setChecked(false);
  const int searches = o->extremeSearches(), updates = o->transmissionUpdates();
  work();
  EXPECT_EQ(o->extremeSearches(), searches);
  EXPECT_EQ(o->transmissionUpdates(), updates);
  EXPECT_TRUE(o->extremesItem()->poses().poses.empty());
  EXPECT_TRUE(o->transmissionItem()->arcs().empty());
}

TEST(DesignOverlays, ADesignTheSolverCannotTakeShowsNothing) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  Document* d = w.document();
  w.designChecks().showExtremes->setChecked(true);
  w.designChecks().showTransmission->setChecked(true);
  ASSERT_FALSE(w.designChecks().overlays()->extremesItem()->poses().poses.empty());
  // The rocker's pivot far away: the loop cannot close.
  Mechanism m = d->design();
  m.point(*m.findPoint("ground.O4"))->pos.x() += 500;
  editDesign(d, "Move O4", m);
  ASSERT_FALSE(d->solved());
  EXPECT_TRUE(w.designChecks().overlays()->extremesItem()->poses().poses.empty());
  EXPECT_TRUE(w.designChecks().overlays()->transmissionItem()->arcs().empty());
  d->undoStack()->undo();
  ASSERT_TRUE(d->solved());
  EXPECT_FALSE(w.designChecks().overlays()->extremesItem()->poses().poses.empty());
  EXPECT_FALSE(w.designChecks().overlays()->transmissionItem()->arcs().empty());
}

TEST(DesignOverlays, ActionsShortcutsAndSettings) {
  {
    MainWindow w;
    ASSERT_TRUE(w.openExample("needle-876-alpha-35"));
    w.show();
    QApplication::processEvents();
    QAction* e = w.designChecks().showExtremes;
    QAction* a = w.designChecks().showTransmission;
    EXPECT_EQ(e->shortcut(), QKeySequence(QStringLiteral("Shift+E")));
    EXPECT_EQ(a->shortcut(), QKeySequence(QStringLiteral("Shift+A")));
    // Every shortcut of the window is one action's.
    std::set<QString> keys;
    for (QAction* act : w.findChildren<QAction*>())
      for (const QKeySequence& k : act->shortcuts())
        EXPECT_TRUE(keys.insert(k.toString()).second) << k.toString().toStdString();
    // The keys on the canvas toggle them.
    QTest::keyClick(w.canvas(), Qt::Key_E, Qt::ShiftModifier);
    QTest::keyClick(w.canvas(), Qt::Key_A, Qt::ShiftModifier);
    EXPECT_TRUE(e->isChecked());
    EXPECT_TRUE(a->isChecked());
    EXPECT_TRUE(w.designChecks().overlays()->extremesVisible());
    EXPECT_TRUE(w.designChecks().overlays()->transmissionVisible());
    // In the View menu and the Analysis menu, with the dock and the study.
    auto menu = [&](const QString& title) -> QMenu* {
      for (QAction* m : w.menuBar()->actions())
        if (m->menu() && m->text().remove('&') == title) return m->menu();
      return nullptr;
    };
    QMenu* view = menu(QStringLiteral("View"));
    QMenu* analysis = menu(QStringLiteral("Analysis"));
    ASSERT_TRUE(view && analysis);
    for (QAction* act : {e, a}) {
      EXPECT_TRUE(view->actions().contains(act));
      EXPECT_TRUE(analysis->actions().contains(act));
    }
    EXPECT_TRUE(analysis->actions().contains(w.designChecks().parameterStudy));
    EXPECT_TRUE(analysis->actions().contains(w.designChecks().show));
    EXPECT_EQ(w.designChecks().show->shortcut(), QKeySequence(QStringLiteral("Shift+D")));
    EXPECT_TRUE(w.close());
  }
  {
    MainWindow w;  // remembered
    EXPECT_TRUE(w.designChecks().showExtremes->isChecked());
    EXPECT_TRUE(w.designChecks().showTransmission->isChecked());
    w.designChecks().showExtremes->setChecked(false);
    w.designChecks().showTransmission->setChecked(false);
    EXPECT_TRUE(w.close());
  }
  MainWindow w;
  EXPECT_FALSE(w.designChecks().showExtremes->isChecked());
  EXPECT_FALSE(w.designChecks().showTransmission->isChecked());
}

TEST(DesignOverlays, TheBandIsRemembered) {
  {
    DesignChoices c;
    ASSERT_TRUE(c.setBand({35, 145}));
  }
  DesignChoices c;
  EXPECT_EQ(c.band().lo, 35);
  EXPECT_EQ(c.band().hi, 145);
  ASSERT_TRUE(c.setBand({30, 150}));
}

// The band is the user's: typed in one window's Design Checks, every open window takes it.
TEST(DesignOverlays, TheBandTypedInOneWindowReachesTheOthers) {
  MainWindow a, b;
  a.designChecks().panel()->bandLo()->setValue(40);
  EXPECT_EQ(a.designChecks().choices()->band().lo, 40);
  EXPECT_EQ(b.designChecks().choices()->band().lo, 40);
  EXPECT_EQ(b.designChecks().panel()->bandLo()->value(), 40);
  ASSERT_TRUE(a.designChecks().choices()->setBand({30, 150}));
  EXPECT_EQ(b.designChecks().panel()->bandLo()->value(), 30);
}

}  // namespace
}  // namespace linkage::ui
