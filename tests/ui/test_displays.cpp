// What the editor shows is what the solver determined, and nothing else: no motion of a
// mechanism the driver does not determine, no state left over from another design, no number
// made of rounding, no window stretched by a number, the history naming what was moved.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QHelpEvent>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolTip>
#include <QUndoStack>

#include "animation/animator.h"
#include "animation/crank_bar.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "centres/centres_panel.h"
#include "cycle/cycle_entries.h"
#include "cycle/cycle_panel.h"
#include "design/design_overlays.h"
#include "design/extremes_item.h"
#include "design/transmission_item.h"
#include "document/commands.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "drawing.h"
#include "figures/qcp.h"
#include "forces/dynamics_item.h"
#include "forces/forces_overlay.h"
#include "forces/forces_panel.h"
#include "linkage/edits.h"
#include "linkage/io/model_file.h"
#include "plots/curve_set.h"
#include "plots/plots_panel.h"
#include "properties/inspector_panel.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/features.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

JointId jointBetween(const Mechanism& m, const char* a, const char* b) {
  const PointId pa = *m.findPoint(a), pb = *m.findPoint(b);
  for (const Joint& j : m.joints)
    if ((j.a == pa && j.b == pb) || (j.a == pb && j.b == pa)) return j.id;
  return {};
}

// The four-bar with the coupler's pin to the rocker deleted: coupler and rocker hang free, two
// degrees of freedom the driver does not determine.
void deleteCouplerPin(MainWindow& w) {
  w.tools().selection()->add(jointBetween(w.document()->design(), "coupler.B", "rocker.B"));
  w.tools().toolbox()->deleteSelection();
  QApplication::processEvents();
  ASSERT_TRUE(w.document()->solved());
  ASSERT_EQ(w.document()->kinematics().structure().freeAfterDriver, 2);
}

TEST(Displays, UndeterminedMotionShowsNoNumbersButWhy) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.view().showTraces->setChecked(true);
  QApplication::processEvents();
  const QTableWidget* t = w.properties().inspector()->motionTable();
  ASSERT_EQ(t->rowCount(), 1);
  ASSERT_FALSE(w.scene()->traceItems()[0]->path().isEmpty());
  EXPECT_TRUE(t->item(0, 2)->text().contains(QLatin1Char(','))) << t->item(0, 2)->text();
  deleteCouplerPin(w);

  // The output points' table: no position, velocity or acceleration; the reason under it.
  ASSERT_EQ(t->rowCount(), 1);
  EXPECT_EQ(t->item(0, 0)->text(), "coupler.P");
  for (int c = 1; c < 4; ++c) EXPECT_EQ(t->item(0, c)->text(), "not determined");
  EXPECT_TRUE(
      w.properties().inspector()->noteText().contains("coupler.P is not determined by the driver"))
      << w.properties().inspector()->noteText();
  // No traced path.
  ASSERT_EQ(w.scene()->traceItems().size(), 1u);
  EXPECT_TRUE(w.scene()->traceItems()[0]->path().isEmpty());
  // No animation, no steps: the crank stays and the message says why.
  const double deg = w.document()->crankDeg();
  w.animation().play->trigger();
  EXPECT_FALSE(w.animator()->playing());
  EXPECT_TRUE(w.messageStrip()->message().startsWith("Cannot play: the motion is not determined"))
      << w.messageStrip()->message();
  EXPECT_FALSE(w.animation().play->isChecked());
  w.animation().stepForward->trigger();
  EXPECT_EQ(w.document()->crankDeg(), deg);
  EXPECT_TRUE(w.messageStrip()->message().contains("not determined"));
  // The plot of the point: no curve, the reason.
  w.plots().dock->show();
  QApplication::processEvents();
  ASSERT_NE(w.plots().panel()->curves(0), nullptr);
  EXPECT_TRUE(w.plots().panel()->curves(0)->empty());
  EXPECT_TRUE(QString::fromStdString(w.plots().panel()->curves(0)->status().message)
                  .contains("not determined"));
  EXPECT_TRUE(w.plots().panel()->cursorText().contains(QString::fromUtf8("vy — mm/s")))
      << w.plots().panel()->cursorText();
  shot(&w, "undetermined");
}

TEST(Displays, UndeterminedPointHasNoVelocityChainNorCentres) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.centres().dock->raise();
  w.centres().show->setChecked(true);
  QTest::qWait(20);
  ASSERT_TRUE(w.centres().panel()->chain().has_value());
  const size_t drawn = w.scene()->drawing().centres.size();
  deleteCouplerPin(w);
  QTest::qWait(20);
  EXPECT_FALSE(w.centres().panel()->chain().has_value());
  EXPECT_TRUE(w.centres().panel()->chainText().isEmpty());
  // The chain's words say why (the point is chosen still).
  const QTableWidget* t = w.centres().panel()->table();
  bool any = false;
  for (int r = 0; r < t->rowCount(); ++r) {
    const QString bodies = t->item(r, 1)->text();
    if (!bodies.contains("coupler") && !bodies.contains("rocker")) continue;
    any = true;
    EXPECT_EQ(t->item(r, 2)->text(), QStringLiteral("\u2013")) << bodies.toStdString();
    EXPECT_TRUE(t->item(r, 5)->text().startsWith("not determined")) << bodies.toStdString();
  }
  EXPECT_TRUE(any);
  // On the canvas only the centres of the crank and the ground: 1,2.
  EXPECT_LT(w.scene()->centresItem()->centres().size(), drawn);
  for (const Drawing::Centre& c : w.scene()->centresItem()->centres())
    EXPECT_TRUE(c.i <= 2 && c.j <= 2) << c.i << "," << c.j;
}

TEST(Displays, FitOfAnUndeterminedMechanismShowsItWhereItIs) {
  // The Wanzer with its needle bar's pin deleted: the free bodies' sweep wandered 30 m.
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "wanzer-inversion-2"));
  const double fitted = w.canvas()->zoom();
  w.tools().selection()->add(w.document()->design().joints[2].id);
  w.tools().toolbox()->deleteSelection();
  QApplication::processEvents();
  ASSERT_GT(w.document()->kinematics().structure().freeAfterDriver, 0);
  w.view().fit->trigger();
  const QRectF r = w.scene()->mechanismRect();
  EXPECT_LT(std::max(r.width(), r.height()), 400) << r.width() << " x " << r.height();
  EXPECT_GT(w.canvas()->zoom(), fitted / 2);
}

TEST(Displays, UndoOfAStartAngleBeyondReachLeavesTheDesignSolved) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const int width = w.width();
  // Typed: refused, with the reason, the field as it was.
  auto* f = qobject_cast<QLineEdit*>(
      w.properties().panel()->field(QStringLiteral("Start angle [\u00b0]")));
  ASSERT_NE(f, nullptr);
  f->setFocus();
  f->setText("1e300");
  QTest::keyClick(f, Qt::Key_Return);
  EXPECT_EQ(f->text(), "0");
  EXPECT_TRUE(w.messageStrip()->message().contains("between -3600 and 3600"))
      << w.messageStrip()->message();
  EXPECT_EQ(w.document()->undoStack()->count(), 0);
  // In a design (a file, a script): undone, then Home: solved, playing, stepping.
  Mechanism m = w.document()->design();
  m.driver->startDeg = 1e300;
  editDesign(w.document(), "start", m);
  QApplication::processEvents();
  EXPECT_EQ(w.width(), width);
  // The revolutions under the canvas counted as a number however large (their conversion to a
  // long long was undefined behaviour: UBSan stopped here).
  const double rev = std::floor(w.document()->crankDeg() / 360);
  ASSERT_GT(std::abs(rev), 1e15);
  QString revs;
  for (QLabel* l : w.findChildren<QLabel*>())
    if (l->text().startsWith("rev ")) revs = l->text();
  EXPECT_EQ(revs, "rev " + QString::number(rev, 'g', 6));
  w.edit().undo->trigger();
  w.animation().toStart->trigger();
  QApplication::processEvents();
  EXPECT_TRUE(w.document()->solved()) << w.document()->solveStatus().message;
  EXPECT_FALSE(w.properties().inspector()->summaryText().contains("Not solved"));
  EXPECT_EQ(w.document()->crankDeg(), 0);
  w.animation().stepForward->trigger();
  EXPECT_EQ(w.document()->crankDeg(), 1);
  w.animation().play->trigger();
  EXPECT_TRUE(w.animator()->playing());
  w.animator()->setPlaying(false);
  // No message, however long its number, widens the window.
  w.messageStrip()->setMessage(QString(300, QLatin1Char('9')), true);
  QApplication::processEvents();
  EXPECT_EQ(w.width(), width);
  EXPECT_LE(w.minimumSizeHint().width(), width);
}

// Long text in the docks (a 250-character mechanism name typed in Properties widened the
// window from 1400 to 3091 px, past the screen, and undo did not shrink it): every dock shown in
// turn, with long names of the mechanism, a body and a point and a long path, keeps the width.
TEST(Displays, LongNamesDoNotWidenTheWindow) {
  QTemporaryDir dir;
  const QString deep = dir.filePath(QString("folder").repeated(30));
  ASSERT_TRUE(QDir().mkpath(deep));
  const QString path = deep + "/four-bar.linkage.json";
  ASSERT_TRUE(QFile::copy(LINKAGE_EXAMPLES_DIR "/four-bar-crank-rocker.linkage.json", path));
  MainWindow w;
  w.resize(1400, 900);
  ASSERT_TRUE(w.openFile(path));
  w.show();
  QApplication::processEvents();
  const int width = w.width();
  ASSERT_EQ(width, 1400);
  QLineEdit* name = qobject_cast<QLineEdit*>(w.properties().panel()->field("Name"));
  ASSERT_NE(name, nullptr);
  name->setFocus();
  name->selectAll();
  QTest::keyClicks(name, QString(250, QLatin1Char('N')));
  QTest::keyClick(name, Qt::Key_Return);
  ASSERT_EQ(w.document()->design().name, std::string(250, 'N'));
  QApplication::processEvents();
  EXPECT_EQ(w.width(), width);
  // A body and a point named as long (the choices of points in the plots, the centres, the
  // design checks and the forces list them).
  Mechanism m = w.document()->design();
  m.body(m.bodyNamed("coupler")->id)->name = std::string(200, 'C');
  m.point(*m.findPoint(std::string(200, 'C') + ".P"))->name = std::string(200, 'P');
  editDesign(w.document(), "long names", m);
  for (QDockWidget* d : w.findChildren<QDockWidget*>()) {
    d->show();
    d->raise();
    QTest::qWait(30);
    EXPECT_EQ(w.width(), width) << d->objectName().toStdString();
    EXPECT_LE(w.minimumSizeHint().width(), width) << d->objectName().toStdString();
    EXPECT_LE(w.minimumWidth(), width) << d->objectName().toStdString();
  }
  shot(&w, "long-names");
  w.edit().undo->trigger();
  w.edit().undo->trigger();
  QApplication::processEvents();
  EXPECT_EQ(w.width(), width);
}

// The crank-angle label of every figure in its footer or x axis (the motion curves', the
// forces', the cycle diagram's).
QStringList crankLabels(QCustomPlot* plot) {
  QStringList out;
  for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
    if (auto* t = dynamic_cast<QCPTextElement*>(e); t && t->text().contains("angle"))
      out << t->text();
  for (QCPAxisRect* r : plot->axisRects())
    if (r->axis(QCPAxis::atBottom)->label().contains("angle"))
      out << r->axis(QCPAxis::atBottom)->label();
  return out;
}

// The Wanzer homework's disk turns clockwise: every figure's crank-angle axis says so (the
// plots, the forces, the cycle diagram, and so their exports), and follows the direction typed.
TEST(Displays, EveryCrankAngleAxisSaysTheWayTheCrankTurns) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "wanzer-inversion-2-masses"));
  QString why;
  ASSERT_TRUE(w.cycle().panel()->addEntry(EntryKind::Window, "low=needlebar.G:y<-60", &why)) << why;
  // Each figure brought to the front in turn: its crank-angle labels (one at least) are `want`.
  auto allSay = [&](const QString& want) {
    const std::pair<QDockWidget*, QCustomPlot*> figures[] = {
        {w.plots().dock, w.plots().panel()->plotWidget()},
        {w.forces().dock, w.forces().panel()->plotWidget()},
        {w.cycle().dock, w.cycle().panel()->plotWidget()}};
    for (const auto& [dock, plot] : figures) {
      dock->show();
      dock->raise();
      QTest::qWait(50);
      ASSERT_TRUE(plot->isVisible()) << dock->objectName();
      const QStringList l = crankLabels(plot);
      EXPECT_FALSE(l.isEmpty()) << dock->objectName();
      for (const QString& t : l) EXPECT_EQ(t, want) << dock->objectName();
    }
  };
  allSay("disk angle [deg], clockwise");
  // Turned the other way in the Properties: counter-clockwise, everywhere.
  Mechanism m = w.document()->design();
  m.driver->direction = Direction::Ccw;
  editDesign(w.document(), "direction", m);
  allSay("disk angle [deg], counter-clockwise");
}

TEST(Displays, AFileThatCannotBeSolvedLeavesNoVelocityChainBehind) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.centres().dock->raise();
  QTest::qWait(20);
  ASSERT_TRUE(w.centres().panel()->chainText().contains("mm/s"));
  // The same four-bar with a coupler too short to close: 1 mm, with a rocker of 51 mm, 53 mm
  // from the crank pin.
  Mechanism m = w.document()->design();
  m.point(*m.findPoint("coupler.B"))->pos = Vec2(11, 17.320508075688775);
  QTemporaryDir dir;
  const QString path = dir.filePath("short.linkage.json");
  ASSERT_TRUE(saveMechanismFile(m, path.toStdString()).ok);
  QString why;
  ASSERT_TRUE(w.openFile(path, &why)) << why.toStdString();
  QTest::qWait(20);
  ASSERT_FALSE(w.document()->solved());
  EXPECT_EQ(w.centres().panel()->table()->rowCount(), 0);
  EXPECT_FALSE(w.centres().panel()->chain().has_value());
  EXPECT_FALSE(w.centres().panel()->chainText().contains("mm/s"));
  w.properties().dock->raise();
  QTest::qWait(20);
  EXPECT_EQ(w.properties().inspector()->motionTable()->rowCount(), 0);
  EXPECT_TRUE(w.properties().inspector()->noteText().startsWith("Not solved"));
}

// The four-bar example with a coupler too short to close: 1 mm, with a rocker of 51 mm, 53 mm
// from the crank pin.
Mechanism shortCoupler(Mechanism m) {
  m.point(*m.findPoint("coupler.B"))->pos = Vec2(11, 17.320508075688775);
  return m;
}

Mechanism shortCoupler() {
  return shortCoupler(
      *loadMechanismFile(LINKAGE_EXAMPLES_DIR "/four-bar-crank-rocker.linkage.json").mechanism);
}

// Every overlay of the canvas that draws numbers, none drawing any.
void expectNoOverlayNumbers(MainWindow& w) {
  EXPECT_TRUE(w.scene()->centresItem()->centres().empty())
      << w.scene()->centresItem()->centres().size() << " centres";
  EXPECT_TRUE(w.scene()->drawing().centres.empty());
  EXPECT_TRUE(w.scene()->chainItem()->dimensions().empty());
  for (const QGraphicsPathItem* t : w.scene()->traceItems()) EXPECT_TRUE(t->path().isEmpty());
  EXPECT_TRUE(w.designChecks().overlays()->extremesItem()->poses().poses.empty());
  EXPECT_TRUE(w.designChecks().overlays()->transmissionItem()->arcs().empty());
  EXPECT_TRUE(w.forces().overlay()->item()->marks().reactions.empty());
}

void showEveryOverlay(MainWindow& w) {
  w.centres().dock->raise();
  w.centres().show->setChecked(true);
  w.view().showTraces->setChecked(true);
  w.designChecks().showExtremes->setChecked(true);
  w.designChecks().showTransmission->setChecked(true);
  w.forces().show->setChecked(true);
  QTest::qWait(30);
}

TEST(Displays, AFileThatCannotBeSolvedShowsNoOverlayOfTheDocumentBefore) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "wanzer-inversion-2"));
  showEveryOverlay(w);
  ASSERT_FALSE(w.scene()->centresItem()->centres().empty());
  QTemporaryDir dir;
  const QString path = dir.filePath("short.linkage.json");
  ASSERT_TRUE(saveMechanismFile(shortCoupler(), path.toStdString()).ok);
  QString why;
  ASSERT_TRUE(w.openFile(path, &why)) << why.toStdString();
  QTest::qWait(30);
  ASSERT_FALSE(w.document()->solved());
  expectNoOverlayNumbers(w);
  shot(&w, "unsolved-file-after-wanzer");
}

TEST(Displays, ARefusedEditShowsNoOverlayOfTheLastSolvedDesign) {
  // The solver keeps the last good state of a refused edit of the same shape and the canvas
  // draws its pose: its centres, paths and arcs are of that other design.
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  showEveryOverlay(w);
  ASSERT_FALSE(w.scene()->centresItem()->centres().empty());
  ASSERT_FALSE(w.scene()->traceItems().at(0)->path().isEmpty());
  ASSERT_FALSE(w.scene()->chainItem()->dimensions().empty());
  editDesign(w.document(), "short", shortCoupler(w.document()->design()));
  QTest::qWait(30);
  ASSERT_FALSE(w.document()->solved());
  ASSERT_TRUE(w.scene()->solverShown());
  expectNoOverlayNumbers(w);
  // Undone: the overlays of the solved design again.
  w.edit().undo->trigger();
  QTest::qWait(30);
  EXPECT_FALSE(w.scene()->centresItem()->centres().empty());
  EXPECT_FALSE(w.scene()->traceItems().at(0)->path().isEmpty());
}

// What every display says of a design the solver has not taken: the document's reason, and
// nothing of the last design that could be solved.
void expectOneReason(MainWindow& w) {
  const QString why = QString::fromStdString(w.document()->solveStatus().message);
  ASSERT_FALSE(why.isEmpty());
  const CurveSet* set = w.plots().panel()->curves(0);
  ASSERT_NE(set, nullptr);
  EXPECT_TRUE(set->empty());
  EXPECT_EQ(QString::fromStdString(set->status().message), why);
  EXPECT_TRUE(w.plots().panel()->statusText().contains(why)) << w.plots().panel()->statusText();
  EXPECT_FALSE(w.plots().panel()->statusText().contains("last design"));
  const QString summary = w.properties().inspector()->summaryText();
  EXPECT_TRUE(summary.contains("Not solved")) << summary;
  EXPECT_FALSE(summary.contains("Solved ")) << summary;
  EXPECT_FALSE(summary.contains("Degrees of freedom")) << summary;
  const QLabel* driver = w.animation().crankBar()->driverLabel();
  if (w.document()->design().driver) {
    EXPECT_TRUE(driver->text().contains("rpm")) << driver->text();
    EXPECT_TRUE(driver->text().contains("not solved")) << driver->text();
    EXPECT_TRUE(driver->toolTip().contains(why)) << driver->toolTip();
  }
  EXPECT_FALSE(w.animation().crankBar()->isEnabled());
}

TEST(Displays, AnUnsolvedDesignSaysItsOneReasonEverywhere) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.plots().dock->show();
  w.properties().dock->raise();
  QTest::qWait(60);
  ASSERT_FALSE(w.plots().panel()->curves(0)->empty());
  // An edit the solver refuses: it keeps the last design it could solve, whose curves these
  // are not.
  editDesign(w.document(), "short", shortCoupler(w.document()->design()));
  QTest::qWait(60);
  ASSERT_FALSE(w.document()->solved());
  expectOneReason(w);
  // A file that cannot be solved: it has a driver.
  QTemporaryDir dir;
  const QString path = dir.filePath("short.linkage.json");
  ASSERT_TRUE(saveMechanismFile(shortCoupler(), path.toStdString()).ok);
  ASSERT_TRUE(w.openFile(path));
  QTest::qWait(60);
  expectOneReason(w);
  EXPECT_FALSE(w.animation().crankBar()->driverLabel()->text().contains("no driver"));
}

TEST(Displays, AStructureGivenADriverSaysWhyItCannotTurn) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.plots().dock->show();
  // The four-bar without its driver, its coupler point strutted to the ground: a structure.
  Mechanism m = w.document()->design();
  m.driver.reset();
  const Vec2 p = m.point(*m.findPoint("coupler.P"))->pos;
  const BodyId strut = m.addBody("strut");
  const PointId top = m.addPoint(strut, "T", Vec2(30, 100));
  m.addPin(m.addPoint(strut, "P", p), *m.findPoint("coupler.P"));
  m.addPin(top, m.addPoint(m.bodies[0].id, "T", Vec2(30, 100)));
  editDesign(w.document(), "strut", m);
  QTest::qWait(60);
  ASSERT_TRUE(w.document()->solved()) << w.document()->solveStatus().message;
  ASSERT_EQ(w.document()->kinematics().structure().mobility, 0);
  // The Driver tool on the crank's pivot.
  test::Draw d{w};
  d.key("M");
  d.click(0, 0);
  QTest::qWait(60);
  ASSERT_TRUE(w.document()->design().driver);
  ASSERT_FALSE(w.document()->solved());
  EXPECT_FALSE(w.messageStrip()->message().contains("drives the mechanism"))
      << w.messageStrip()->message();
  EXPECT_TRUE(w.messageStrip()->problem().contains("cannot turn")) << w.messageStrip()->problem();
  expectOneReason(w);
  EXPECT_FALSE(w.plots().panel()->statusText().contains("no driver"));
}

// The extremes marked on the plots: points of the graphs drawn without lines.
int extremeMarks(const MainWindow& w) {
  QCustomPlot* plot = w.plots().panel()->plotWidget();
  int n = 0;
  for (int i = 0; i < plot->graphCount(); ++i)
    if (plot->graph(i)->lineStyle() == QCPGraph::lsNone) n += plot->graph(i)->dataCount();
  return n;
}

TEST(Displays, RoundingIsNeitherPlottedNorPrintedAsASign) {
  EXPECT_EQ(fixedText(-1e-9, 3), "0.000");
  EXPECT_EQ(fixedText(-0.0, 3), "0.000");
  EXPECT_EQ(fixedText(-0.0006, 3), "-0.001");
  EXPECT_EQ(fixedText(NAN, 3), QStringLiteral("\u2013"));
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.plots().dock->show();
  // The rocker's pivot: fixed, its velocity computed through the turning rocker.
  CurveRequest r = w.plots().panel()->request();
  r.target = "rocker.O4";
  w.plots().panel()->setRequest(r);
  QTest::qWait(60);
  const CurveSet* set = w.plots().panel()->curves(0);
  ASSERT_NE(set, nullptr);
  for (Order o : {Order::Velocity, Order::Acceleration})
    for (double v : set->curve(o).values) ASSERT_EQ(v, 0.0);
  EXPECT_EQ(set->extremes(Order::Velocity).max.value, 0.0);
  // Flat to rounding: no extreme marked on the zero line, none at an angle in the list (the
  // rounding's peaks were marked at 210 and 257 degrees on ay).
  EXPECT_EQ(extremeMarks(w), 0);
  for (Order o : {Order::Position, Order::Velocity, Order::Acceleration}) {
    EXPECT_FALSE(std::isfinite(set->extremes(o).max.crankDeg));
    EXPECT_FALSE(std::isfinite(set->extremes(o).min.crankDeg));
  }
  EXPECT_FALSE(w.plots().panel()->extremesText().contains(QString::fromUtf8("0°")))
      << w.plots().panel()->extremesText();
  // A moving point's curve keeps its small values (no flattening of a real signal).
  r.target = "coupler.P";
  w.plots().panel()->setRequest(r);
  QTest::qWait(60);
  int nonzero = 0;
  for (double v : w.plots().panel()->curves(0)->curve(Order::Velocity).values) nonzero += v != 0;
  EXPECT_GT(nonzero, 300);
  EXPECT_EQ(extremeMarks(w), 6);  // a maximum and a minimum on each of its three curves
  // The inspector prints no "-0.000".
  Mechanism m = w.document()->design();
  toggleOutput(m, *m.findPoint("rocker.O4"));
  editDesign(w.document(), "output", m);
  QApplication::processEvents();
  const QTableWidget* t = w.properties().inspector()->motionTable();
  ASSERT_EQ(t->rowCount(), 2);
  EXPECT_EQ(t->item(1, 2)->text(), "0.000, 0.000");
  EXPECT_EQ(t->item(1, 3)->text(), "0.000, 0.000");
}

TEST(Displays, TheHistoryNamesTheDraggedPoint) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  test::Draw d{w};
  const Vec2 p =
      w.document()->kinematics().position(*w.document()->design().findPoint("coupler.P"));
  d.drag(p.x(), p.y(), p.x() + 5, p.y() + 3, Qt::ControlModifier);
  ASSERT_EQ(w.document()->undoStack()->count(), 1);
  EXPECT_EQ(w.document()->undoStack()->text(0), "Move coupler.P");
}

// Issue 26: the editor's messages named "joints[0]" where the canvas shows a pin at A. In the
// editor a joint is named as it is seen: its kind and the points it joins.
TEST(Displays, MessagesNameAJointAsTheCanvasShowsIt) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  // The rocker's pivot 200 mm away: the loop cannot close at the rocker's pin to the coupler.
  Mechanism m = w.document()->design();
  for (Point& p : m.points)
    if (p.name == "O4" && p.body == m.ground()->id) p.pos += Vec2(200, 0);
  editDesign(w.document(), "far", m);
  QTest::qWait(60);
  ASSERT_FALSE(w.document()->solved());
  const QString problem = w.messageStrip()->problem();
  EXPECT_TRUE(problem.contains(QRegularExpression(
      R"(pin (crank\.A - coupler\.A|coupler\.B - rocker\.B|rocker\.O4 - ground\.O4) stays)")))
      << problem;
  EXPECT_FALSE(problem.contains("joints[")) << problem;
  // The joint's Properties and its tooltip on the canvas: the same name.
  w.document()->undoStack()->undo();
  QTest::qWait(60);
  ASSERT_TRUE(w.document()->solved());
  const Mechanism& back = w.document()->design();
  w.tools().selection()->add(back.joints[2].id);
  QApplication::processEvents();
  EXPECT_EQ(w.properties().panel()->title(), "<b>Joint</b> pin coupler.B - rocker.B");
}

// Issue 26: a red message was clipped at both ends: a word longer than the line (a 300-digit
// number, a path) ran past the canvas's edge, and on a low canvas the strip's first rows were
// above it. Each row fits the canvas's width, the strip lies within the canvas, a message past
// its rows ends in an ellipsis, and the whole text is the strip's tooltip.
TEST(Displays, ALongRedMessageFitsTheCanvasAndIsWholeInItsTooltip) {
  MainWindow w;
  w.resize(1280, 800);
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.show();
  QApplication::processEvents();
  MessageStrip* strip = w.messageStrip();
  auto* label = strip->findChild<QLabel*>("message");
  ASSERT_TRUE(label);
  auto fits = [&](const char* when) {
    SCOPED_TRACE(when);
    EXPECT_GE(strip->geometry().top(), 0);
    EXPECT_LE(strip->geometry().bottom(), w.canvas()->height());
    const QStringList rows = label->text().split('\n');
    for (const QString& r : rows)
      EXPECT_LE(label->fontMetrics().horizontalAdvance(r), label->width()) << r;
    EXPECT_LE(label->geometry().bottom(), strip->height());
    return rows;
  };
  const QString digits = "Mass [kg]: \"" + QString(150, QLatin1Char('9')) + "\" is not a number";
  strip->setMessage(digits, true);
  QApplication::processEvents();
  QStringList rows = fits("150 digits");
  EXPECT_GE(rows.size(), 2);
  EXPECT_EQ(rows.join("").remove(' '), QString(digits).remove(' '));  // all of it, in rows
  EXPECT_EQ(strip->message(), digits);
  shot(&w, "message-strip-digits");
  // Longer than three rows: elided, and whole in the tooltip over the strip.
  const QString path =
      "Could not open " + QString("/a/folder/of/many/sewing/machines").repeated(20) + ".json";
  strip->setMessage(path, true);
  QApplication::processEvents();
  rows = fits("a long path");
  EXPECT_EQ(rows.size(), 3);
  EXPECT_TRUE(rows.back().endsWith(QChar(0x2026))) << rows.back();
  const QPoint inStrip = strip->geometry().center();
  EXPECT_TRUE(strip->toolTipAt(inStrip).contains(path));
  EXPECT_EQ(strip->toolTipAt(QPoint(inStrip.x(), strip->geometry().top() - 5)), "");
  auto* view = qobject_cast<QAbstractScrollArea*>(w.canvas());
  QHelpEvent help(QEvent::ToolTip, view->viewport()->mapFrom(w.canvas(), inStrip),
                  w.canvas()->mapToGlobal(inStrip));
  QApplication::sendEvent(view->viewport(), &help);
  EXPECT_TRUE(QToolTip::text().contains(path)) << QToolTip::text();
  // A low canvas: one row each, all within it.
  strip->setProblem(QString("cannot assemble the mechanism as drawn ").repeated(8));
  strip->setHint(QString("Select: click a point, joint, slot or link ").repeated(4));
  w.resize(700, 360);
  QApplication::processEvents();
  rows = fits("a low canvas");
  EXPECT_EQ(rows.size(), 1);
  shot(&w, "message-strip-low");
}

// A result next to others of its quantity (Find Dimensions' table): rounding of 0 is 0, digits
// down to 1e-9 of the scale and at most 10 of them, no exponent where none is needed.
TEST(Displays, AResultIsShownToItsScale) {
  EXPECT_EQ(resultText(5.822746424e-13, 1.579745201), "0");
  EXPECT_EQ(resultText(-1.5797452011234, 1.5797452011234), "-1.579745201");
  EXPECT_EQ(resultText(2.3821523734, 20.549712345), "2.38215237");
  EXPECT_EQ(resultText(0.000123456789, 20.549712345), "0.00012346");
  EXPECT_EQ(resultText(1.2345e-20, 1.2345e-20), "1.2345e-20");
  EXPECT_EQ(resultText(0, 0), "0");
  EXPECT_EQ(resultText(NAN, 1), QStringLiteral("\u2013"));
}

}  // namespace
}  // namespace linkage::ui
