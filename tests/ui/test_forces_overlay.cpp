// The forces on the canvas: the joint reactions drawn are the solver's at the pose, on one
// scale for the whole turn; centres of mass and counterweights where the bodies carry them;
// loads marked active or not by their window; and no arrow where the motion or a reaction is
// not determined, but a sentence saying why.
#include <gtest/gtest.h>

#include "ui_test.h"

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "forces/balance_dialog.h"
#include "forces/dynamics_marks.h"
#include "forces/forces_overlay.h"
#include "forces/forces_panel.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/force_samples.h"
#include "window/export_feature.h"
#include "window/features.h"

#include <QApplication>
#include <QDockWidget>
#include <QImage>
#include <QMenuBar>
#include <QUndoStack>

namespace linkage::ui {
namespace {

QPointF qt(const Vec2& v) {
  return QPointF(v.x(), v.y());
}

double distance(const QPointF& a, const QPointF& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

TEST(ForcesOverlay, ReactionsAreTheSolversOnOneScaleForTheTurn) {
  MainWindow w;
  w.resize(1200, 800);
  ASSERT_TRUE(w.openExample("wanzer-inversion-2-masses"));
  Document* d = w.document();
  CanvasScene* s = w.scene();
  EXPECT_TRUE(w.forces().overlay()->item()->marks().reactions.empty());  // hidden: nothing computed
  w.forces().show->setChecked(true);
  ASSERT_TRUE(w.forces().overlay()->reactionsVisible());
  const double scale = w.forces().overlay()->item()->marks().mmPerN;
  ASSERT_GT(scale, 0);
  const ForceSamples turn = sampleForces(d->kinematics(), 72);
  ASSERT_TRUE(turn.complete);
  double most = 0;
  for (const auto& joint : turn.reactionN)
    for (const Vec2& f : joint) most = std::max(most, f.norm());
  const QRectF extent = s->mechanismRect();
  EXPECT_LE(most * scale, 0.25 * std::hypot(extent.width(), extent.height()) * 1.0001);
  EXPECT_GT(most * scale, 0.05 * std::hypot(extent.width(), extent.height()));
  for (double deg : {0.0, 47.0, 181.0, 300.0}) {
    ASSERT_TRUE(d->setCrankDeg(deg).ok());
    const Forces ref = computeForces(d->kinematics());
    const DynamicsMarks& m = w.forces().overlay()->item()->marks();
    EXPECT_EQ(m.mmPerN, scale) << "one scale for the turn";
    ASSERT_EQ(m.reactions.size(), ref.joints.size());
    for (size_t j = 0; j < ref.joints.size(); ++j) {
      EXPECT_TRUE(m.reactions[j].determined);
      EXPECT_LT(distance(m.reactions[j].forceN, qt(ref.joints[j].force)),
                1e-12 * (1 + ref.joints[j].force.norm()));
      EXPECT_LT(distance(m.reactions[j].at, qt(ref.joints[j].at)), 1e-9);
    }
    EXPECT_TRUE(m.legend.contains(QString::number(ref.driverTorqueNm, 'g', 3))) << m.legend;
    // Each load by its window of crank angles.
    const Mechanism& design = d->design();
    ASSERT_EQ(m.loads.size(), design.loads.size());
    for (size_t i = 0; i < design.loads.size(); ++i)
      EXPECT_EQ(m.loads[i].active, design.loads[i].activeAt(deg)) << deg;
  }
  // Centres of mass where the solver moved them.
  const Mechanism& design = d->design();
  size_t massive = 0;
  for (const Body& b : design.bodies)
    if (!b.ground && b.mass && b.mass->kg > 0) {
      const QPointF want = qt(d->kinematics().bodyTransform(b.id) * b.mass->com);
      EXPECT_LT(distance(w.forces().overlay()->item()->marks().masses.at(massive).com, want), 1e-9);
      ++massive;
    }
  EXPECT_EQ(w.forces().overlay()->item()->marks().masses.size(), massive);
  w.forces().show->setChecked(false);
  EXPECT_TRUE(w.forces().overlay()->item()->marks().reactions.empty());
  EXPECT_TRUE(w.forces().overlay()->item()->marks().legend.isEmpty());
}

TEST(ForcesOverlay, CounterweightsOfABalanceAreDrawnOnTheirBodies) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("slider-crank-22a-masses"));
  Document* d = w.document();
  BalanceOptions opt;
  for (const Body& b : d->design().bodies)
    if (b.name == "crank") opt.bodies.push_back(b.id);
  ASSERT_EQ(opt.bodies.size(), 1u);
  const BalanceResult r = balanceShaking(d->kinematics(), opt);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  Mechanism m = d->design();
  addCounterweights(m, r.counterweights);
  commitEdit(d, QStringLiteral("Balance"), m);
  ASSERT_TRUE(d->setCrankDeg(35).ok());
  const Body* crank = d->design().body(opt.bodies[0]);
  ASSERT_EQ(crank->mass->counterweights.size(), 1u);
  bool found = false;
  for (const DynamicsMarks::Mass& mark : w.forces().overlay()->item()->marks().masses)
    if (mark.counterweights.size() == 1) {
      found = true;
      const Vec2 at = d->kinematics().bodyTransform(crank->id) * crank->mass->counterweights[0].at;
      EXPECT_LT(distance(mark.counterweights[0], qt(at)), 1e-9);
      EXPECT_EQ(mark.counterweightKg[0], crank->mass->counterweights[0].kg);
    }
  EXPECT_TRUE(found);
}

TEST(ForcesOverlay, NoArrowWhereNothingIsDeterminedButASentence) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2-masses"));
  Document* d = w.document();
  w.forces().show->setChecked(true);
  // A pin taken out: bodies free with the crank held.
  Mechanism m = d->design();
  m.joints.erase(m.joints.begin() + 2);
  commitEdit(d, QStringLiteral("Delete"), m);
  const DynamicsMarks& marks = w.forces().overlay()->item()->marks();
  EXPECT_TRUE(marks.reactions.empty());
  EXPECT_TRUE(marks.legend.startsWith(QStringLiteral("Forces not shown"))) << marks.legend;
  // No masses: every force is zero, and the window says what to do.
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  EXPECT_TRUE(w.forces().overlay()->item()->marks().reactions.empty());
  EXPECT_TRUE(w.forces().overlay()->item()->marks().legend.startsWith(QStringLiteral("No masses")));
}

// A machine in space with masses: no reaction arrows in one plane (their parts out of it would
// be lost, their points are in other planes' frames), and the sentence says where they are.
TEST(ForcesOverlay, AMachineInSpaceSaysWhereItsReactionsAreInsteadOfArrows) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("rssr-crank-rocker"));
  Document* d = w.document();
  Mechanism m = d->design();
  for (Body& b : m.bodies)
    if (!b.ground) b.mass = Mass{0.05, Vec2::Zero(), 2500, {}, {}};
  commitEdit(d, QStringLiteral("Masses"), m);
  w.forces().show->setChecked(true);
  ASSERT_TRUE(d->setCrankDeg(40).ok());
  QApplication::processEvents();
  const DynamicsMarks& marks = w.forces().overlay()->item()->marks();
  EXPECT_TRUE(marks.reactions.empty());
  EXPECT_TRUE(marks.legend.startsWith(
      QStringLiteral("Reactions not drawn on a machine in space (linkage-cli dynamics")))
      << marks.legend.toStdString();
}

// An animation's frames show what the window shows: the masses and the loads too (the frames'
// scene of their own has the forces' overlay as the window's has).
TEST(ForcesOverlay, AnAnimationsFramesDrawTheMassesAndLoads) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2-masses"));
  Document* d = w.document();
  const QImage with = w.exports().renderFrame(30, QSize(400, 300));
  w.exports().endFrames();
  Mechanism m = d->design();
  ASSERT_FALSE(m.loads.empty());
  m.loads.clear();
  for (Body& b : m.bodies) b.mass.reset();
  commitEdit(d, QStringLiteral("No masses"), m);
  ASSERT_TRUE(d->solved());
  const QImage without = w.exports().renderFrame(30, QSize(400, 300));
  w.exports().endFrames();
  EXPECT_NE(with, without);
  // The same design again: the same picture (what differed was the masses and loads).
  ASSERT_TRUE(d->undoStack()->canUndo());
  d->undoStack()->undo();
  EXPECT_EQ(w.exports().renderFrame(30, QSize(400, 300)), with);
  w.exports().endFrames();
}

// The window's reactions and an animation's frames draw one document: the frames' overlay (no
// reactions) coming and going leaves the window's reactions computed.
TEST(ForcesOverlay, AnAnimationsFramesLeaveTheWindowsReactionsComputed) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2-masses"));
  Document* d = w.document();
  w.forces().show->setChecked(true);
  ASSERT_TRUE(d->kinematics().accelerations());
  w.exports().renderFrame(30, QSize(400, 300));
  EXPECT_TRUE(d->kinematics().accelerations());
  w.exports().endFrames();
  EXPECT_TRUE(d->kinematics().accelerations());
  ASSERT_TRUE(d->setCrankDeg(47).ok());
  EXPECT_TRUE(d->forces().status.ok()) << d->forces().status.message;
  EXPECT_FALSE(w.forces().overlay()->item()->marks().reactions.empty());
  // Hidden again: nobody asks, nothing is computed for them.
  w.forces().show->setChecked(false);
  EXPECT_FALSE(d->kinematics().accelerations());
}

TEST(ForcesOverlay, TheScaleIsAOneTwoFiveStepOfNewtonsPerTenMillimetres) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("drop-feed"));
  w.forces().show->setChecked(true);
  const double perTen = 10 / w.forces().overlay()->item()->marks().mmPerN;
  const double decade = std::pow(10.0, std::floor(std::log10(perTen) + 1e-12));
  const double digit = perTen / decade;
  EXPECT_TRUE(std::abs(digit - 1) < 1e-9 || std::abs(digit - 2) < 1e-9 ||
              std::abs(digit - 5) < 1e-9)
      << perTen;
}

// Every action of forces is on a menu, with a status tip.
bool onAMenu(MainWindow& w, QAction* a) {
  for (QMenu* m : w.menuBar()->findChildren<QMenu*>())
    if (m->actions().contains(a)) return true;
  return false;
}

TEST(ForcesOverlay, TheWindowHasTheForcesDockTheBalanceAndTheExports) {
  MainWindow w;
  w.resize(1300, 900);
  ASSERT_TRUE(w.openExample("slider-crank-22a-masses"));
  w.show();
  QApplication::processEvents();
  const ForcesFeature& f = w.forces();
  for (auto [a, name] : {std::pair{f.show, "showForces"},
                         {f.showPanel, "showForcesPanel"},
                         {f.balance, "balance"},
                         {f.exportTable, "exportForcesTable"},
                         {f.exportFigure, "exportForcesFigure"}}) {
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->objectName(), QString::fromLatin1(name));
    EXPECT_FALSE(a->statusTip().isEmpty()) << name;
    EXPECT_TRUE(onAMenu(w, a)) << name;
  }
  QDockWidget* dock = w.forces().dock;
  ASSERT_NE(dock, nullptr);
  EXPECT_FALSE(dock->isVisible());
  w.forces().showPanel->trigger();
  QApplication::processEvents();
  EXPECT_TRUE(dock->isVisible());
  // The panel's crank requests turn this window's crank.
  emit w.forces().panel()->crankAngleRequested(77);
  EXPECT_DOUBLE_EQ(w.document()->crankDeg(), 77);
  // Balance opens its dialog on this document, once.
  w.forces().balance->trigger();
  auto* dialog = w.findChild<BalanceDialog*>();
  ASSERT_NE(dialog, nullptr);
  EXPECT_TRUE(dialog->isVisible());
  dialog->close();
  w.forces().balance->trigger();
  EXPECT_EQ(w.findChildren<BalanceDialog*>().size(), 1);
}

}  // namespace
}  // namespace linkage::ui
