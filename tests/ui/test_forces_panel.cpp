// The forces panel: its curves are sampleForces' numbers, the cursor follows the crank, a click
// asks for the crank angle under the mouse, only determined numbers are shown (a sentence in
// place of the curves otherwise), work only while shown, and its table is the command line's.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "document/document.h"
#include "figures/qcp.h"
#include "forces/force_figure.h"
#include "forces/forces_panel.h"
#include "linkage/force_samples.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/space.h"
#include "linkage/tables/force_table.h"
#include "mechanisms.h"
#include "ui_test.h"
#include "window/features.h"
#include "window/forces_feature.h"

namespace linkage::ui {
namespace {

QString example(const char* name) {
  return QString::fromStdString(*resolveModel(name));
}

class ForcesPanelTest : public ::testing::Test {
 protected:
  void open(const char* name) { ASSERT_TRUE(doc.open(example(name), nullptr)) << name; }
  void showAndSettle() {
    panel.resize(1400, 350);  // the dock of a 1400 x 950 window
    panel.show();
    settle();
  }
  void settle() {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    ASSERT_FALSE(panel.redrawPending());
  }
  // The value a graph draws at sample i.
  static double at(const QCPGraph* g, int i) { return (g->data()->constBegin() + i)->value; }
  static double keyAt(const QCPGraph* g, int i) { return (g->data()->constBegin() + i)->key; }

  Document doc;
  ForcesPanel panel{&doc};
};

TEST_F(ForcesPanelTest, CurvesAreTheSampledForcesExactly) {
  open("slider-crank-22a-masses");
  showAndSettle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  const ForceSamples s = sampleForces(doc.kinematics());
  ASSERT_EQ(s.size(), 361u);
  const ForceFigure& f = panel.figure();
  // The joints offered are named as the force table's columns name them.
  const QComboBox* joints = panel.findChild<QComboBox*>();
  ASSERT_TRUE(joints);
  ASSERT_EQ(joints->count(), 4);
  const QString header = QString::fromStdString(forceTableHeader(doc.design()));
  for (int i = 0; i < joints->count(); ++i)
    EXPECT_TRUE(header.contains("," + joints->itemText(i) + ".fx_N,")) << joints->itemText(i);
  EXPECT_EQ(joints->itemText(2), "pin:rod.B");
  // The rod's pin to the needle bar (pin:rod.B): the force on the rod.
  const int joint = 2;
  panel.setJoint(joint);
  ASSERT_TRUE(f.curve(ForceFigure::ReactionX));
  for (int i : {0, 37, 90, 181, 359, 360}) {
    SCOPED_TRACE(i);
    EXPECT_EQ(keyAt(f.curve(ForceFigure::TorqueCurve), i), s.crankDeg[i]);
    EXPECT_EQ(at(f.curve(ForceFigure::TorqueCurve), i), s.driverTorqueNm[i]);
    EXPECT_EQ(at(f.curve(ForceFigure::ShakingX), i), s.shakingN[i].x());
    EXPECT_EQ(at(f.curve(ForceFigure::ShakingY), i), s.shakingN[i].y());
    EXPECT_EQ(at(f.curve(ForceFigure::ReactionX), i), s.reactionN[joint][i].x());
    EXPECT_EQ(at(f.curve(ForceFigure::ReactionY), i), s.reactionN[joint][i].y());
    EXPECT_EQ(at(f.curve(ForceFigure::ReactionNorm), i), s.reactionN[joint][i].norm());
    const QCPCurveData& p = *(f.polar()->data()->constBegin() + i);
    EXPECT_EQ(p.key, s.shakingN[i].x());
    EXPECT_EQ(p.value, s.shakingN[i].y());
  }
  // And they are the physics (docs/dynamics.md): at crank 0 the needle bar is at its outer dead
  // centre, the shaking force (0.04 x 17.5 + 0.1 x 22.5) omega^2 / 1000 along the guide, and
  // the rod pushes the bar with the bar's inertia force 0.1 x 22.5 omega^2 / 1000.
  const double w2 = std::pow(doc.kinematics().omega(), 2);
  EXPECT_NEAR(at(f.curve(ForceFigure::ShakingY), 0), (0.04 * 17.5 + 0.1 * 22.5) * w2 / 1000,
              1e-9 * 291);
  EXPECT_NEAR(at(f.curve(ForceFigure::ReactionY), 0), 0.1 * 22.5 * w2 / 1000, 1e-9 * 291);
  // The polar diagram is closed (a whole turn) and drawn on equal scales.
  const QCPCurveData& first = *f.polar()->data()->constBegin();
  const QCPCurveData& last = *(f.polar()->data()->constEnd() - 1);
  EXPECT_NEAR(first.key, last.key, 1e-9 * 291);
  EXPECT_NEAR(first.value, last.value, 1e-9 * 291);
  QCPAxisRect* polar = f.rect(ForceFigure::Polar);
  const double nx = polar->axis(QCPAxis::atBottom)->range().size() / polar->width();
  const double ny = polar->axis(QCPAxis::atLeft)->range().size() / polar->height();
  EXPECT_NEAR(nx, ny, 1e-9 * ny);
  shot(&panel, "forces-panel-slider-crank");
}

TEST_F(ForcesPanelTest, CursorFollowsThePoseAndTheValuesAreThePoses) {
  open("wanzer-inversion-2-masses");
  showAndSettle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  const int computed = panel.computations();
  for (double deg : {123.0, 400.5, 17.25}) {
    ASSERT_TRUE(doc.setCrankDeg(deg).ok());
    const double shown = deg - 360 * std::floor(deg / 360);
    EXPECT_DOUBLE_EQ(panel.cursorDeg(), shown);
    const Forces f = computeForces(doc.kinematics());
    ASSERT_TRUE(f.status.ok());
    EXPECT_TRUE(panel.cursorText().contains(QString::number(f.driverTorqueNm, 'g', 5)))
        << panel.cursorText();
    EXPECT_TRUE(panel.cursorText().contains(QString::number(f.shakingForceN.norm(), 'g', 5)))
        << panel.cursorText();
    // The pose's mark on the polar diagram: between the two samples around it.
    const QPointF mark = panel.figure().polarMark();
    EXPECT_NEAR(mark.x(), f.shakingForceN.x(), 1e-3 * f.shakingForceN.norm() + 1e-2);
    EXPECT_NEAR(mark.y(), f.shakingForceN.y(), 1e-3 * f.shakingForceN.norm() + 1e-2);
  }
  EXPECT_EQ(panel.computations(), computed);  // poses only moved the cursor
  shot(&panel, "forces-panel-wanzer");
}

TEST_F(ForcesPanelTest, ClickAndDragTurnTheCrank) {
  open("slider-crank-22a-masses");
  QObject::connect(&panel, &ForcesPanel::crankAngleRequested, &doc,
                   [this](double d) { doc.setCrankDeg(d); });
  QSignalSpy spy(&panel, &ForcesPanel::crankAngleRequested);
  showAndSettle();
  const ForceFigure& f = panel.figure();
  const QPoint at = f.pixelAt(ForceFigure::Shaking, 123.0, 0).toPoint();
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, at);
  ASSERT_EQ(spy.count(), 1);
  const double asked = spy.at(0).at(0).toDouble();
  EXPECT_DOUBLE_EQ(asked, f.crankAt(at));
  EXPECT_NEAR(asked, 123.0, 2.0);  // within a pixel's worth of degrees
  EXPECT_DOUBLE_EQ(doc.crankDeg(), asked);
  EXPECT_DOUBLE_EQ(panel.cursorDeg(), asked);
  // In the second turn, the angle in that turn (the short way).
  ASSERT_TRUE(doc.setCrankDeg(400).ok());
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {},
                    f.pixelAt(ForceFigure::Torque, 300.0, 0).toPoint());
  ASSERT_EQ(spy.count(), 2);
  EXPECT_NEAR(spy.at(1).at(0).toDouble(), 660.0, 2.0);
  // A click on the polar diagram asks for nothing (it has no crank axis).
  const QPointF mid = f.rect(ForceFigure::Polar)->rect().center();
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, mid.toPoint());
  EXPECT_EQ(spy.count(), 2);
}

// A pendulum pinned to the frame beside the slider-crank: a body the driver does not move.
Mechanism withFreeBody(Mechanism m) {
  const BodyId b = m.addBody("pendulum");
  const PointId p = m.addPoint(b, "P", Vec2(50, 0));
  m.addPin(p, m.addPoint(m.ground()->id, "P", Vec2(50, 0)));
  m.addPoint(b, "Q", Vec2(50, -30));
  m.body(b)->mass = Mass{0.1, Vec2(50, -30), 5, {}, {}};
  return m;
}

TEST_F(ForcesPanelTest, UndeterminedDesignsGetASentenceNotCurves) {
  open("slider-crank-22a-masses");
  showAndSettle();
  ASSERT_TRUE(panel.samples());
  doc.setContents(withFreeBody(doc.design()), "", "free");
  settle();
  ASSERT_FALSE(doc.motionStatus().ok());
  EXPECT_FALSE(panel.samples());
  EXPECT_TRUE(panel.message().contains("not determined")) << panel.message();
  EXPECT_EQ(panel.plotWidget()->plottableCount(), 0);
  EXPECT_FALSE(panel.plotWidget()->isVisible());
  EXPECT_TRUE(panel.cursorText().isEmpty());
  shot(&panel, "forces-panel-undetermined");
  QTemporaryDir dir;
  QString why;
  EXPECT_FALSE(panel.exportTable(dir.filePath("t.csv"), 36, 1, &why));
  EXPECT_TRUE(why.contains("not determined")) << why;
  EXPECT_FALSE(QFile::exists(dir.filePath("t.csv")));
  EXPECT_FALSE(panel.exportFigure(dir.filePath("f.png"), QSize(800, 400), &why));

  // No masses and no loads: every force is zero, and the panel says so.
  open("slider-crank-22a-lambda-0.5");
  settle();
  EXPECT_FALSE(panel.samples());
  EXPECT_EQ(panel.message(),
            "No masses or loads: the forces are all zero; give bodies masses in Properties.");
}

TEST_F(ForcesPanelTest, ARedundantJointsReactionIsASentence) {
  // A parallelogram with a fifth link: the parallel links' shares are not determined.
  test::FourBar f = test::fourBar(60, 20, 60, 20, 70);
  Mechanism m = f.m;
  const BodyId extra = m.addBody("extra");
  const Vec2 E(30, 0), F = m.point(f.A)->pos + Vec2(30, 0);
  const PointId cE = m.addPoint(f.coupler, "E", F), gE = m.addPoint(m.ground()->id, "E", E);
  m.addPin(m.addPoint(extra, "F", F), cE);
  m.addPin(m.addPoint(extra, "E", E), gE);
  for (const Point& p : m.points)
    if (Body* b = m.body(p.body); !b->ground && !b->mass) b->mass = Mass{0.2, p.pos, 30, {}, {}};
  doc.setContents(m, "", "parallelogram");
  showAndSettle();
  const ForceSamples* s = panel.samples();
  ASSERT_TRUE(s) << panel.message();
  ASSERT_FALSE(s->undetermined.empty());
  const int j = m.jointIndex(s->undetermined[0]);
  panel.setJoint(j);
  const ForceFigure& fig = panel.figure();
  EXPECT_FALSE(fig.curve(ForceFigure::ReactionX));
  EXPECT_FALSE(fig.curve(ForceFigure::ReactionY));
  EXPECT_TRUE(fig.curve(ForceFigure::TorqueCurve));  // determined: shown
  bool said = false;
  for (int i = 0; i < panel.plotWidget()->itemCount(); ++i)
    if (auto* t = qobject_cast<QCPItemText*>(panel.plotWidget()->item(i)))
      said = said || t->text().contains("Not determined");
  EXPECT_TRUE(said);
  // This parallelogram reaches a change point: the curves stop there, and the figure says so.
  ASSERT_FALSE(s->complete);
  bool noted = false;
  for (int i = 0; i < panel.plotWidget()->plotLayout()->elementCount(); ++i)
    if (auto* t = qobject_cast<QCPTextElement*>(panel.plotWidget()->plotLayout()->elementAt(i)))
      noted =
          noted || t->text().startsWith(QString("Ends at %1").arg(s->crankDeg.back(), 0, 'f', 1));
  EXPECT_TRUE(noted);
  // The values at the pose: the torque and shaking force, not the undetermined reaction.
  EXPECT_TRUE(panel.cursorText().contains("torque")) << panel.cursorText();
  EXPECT_FALSE(panel.cursorText().contains("; pin:")) << panel.cursorText();
  shot(&panel, "forces-panel-redundant");
}

// Issue 26: forces past 1e154 N (a mass of 1e300 kg then, a load now) read "torque 0 N m;
// shaking force (0, 0) N" (the peak's norm() overflowed, and everything was rounding next to it)
// and filled the plots solid (axes past QCustomPlot's 1e250). Forces the plots can draw are
// drawn and read as the solver has them; larger ones are a sentence with their numbers; forces
// that overflow say so. Never 0 where they are not, never inf or NaN.
Mechanism withLoad(Mechanism m, double n, int loads = 1) {
  Load l;
  l.point = *m.findPoint("needlebar.B");
  l.forceN = Vec2(n, -n);
  for (int i = 0; i < loads; ++i) m.addLoad(l);
  return m;
}

TEST_F(ForcesPanelTest, HugeForcesReadAsTheyAreNeverAsZero) {
  open("slider-crank-22a-masses");
  showAndSettle();
  doc.setContents(withLoad(doc.design(), 1e200), "", "1e200 N");
  ASSERT_TRUE(doc.setCrankDeg(40).ok());
  settle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  const Forces f = computeForces(doc.kinematics());
  ASSERT_TRUE(f.status.ok()) << f.status.message;
  const double norm = std::hypot(f.shakingForceN.x(), f.shakingForceN.y());
  ASSERT_GT(norm, 1e200);
  const QString text = panel.cursorText();
  for (double v : {f.driverTorqueNm, f.shakingForceN.x(), f.shakingForceN.y(), norm})
    EXPECT_TRUE(text.contains(QString::number(v, 'g', 5))) << v << ": " << text;
  EXPECT_FALSE(text.contains("(0, 0)")) << text;
  // The shaking force's plot spans its curves, and the |F| curve is a number.
  const ForceFigure& fig = panel.figure();
  const QCPRange y = fig.rect(ForceFigure::Shaking)->axis(QCPAxis::atLeft)->range();
  EXPECT_GE(y.upper, 1e200);
  EXPECT_LE(y.lower, -1e200);
  EXPECT_LT(y.size(), 1e202);
  for (int i = 0; i < 361; i += 30)
    EXPECT_TRUE(std::isfinite(at(fig.curve(ForceFigure::ReactionNorm), i)));
  shot(&panel, "forces-panel-1e200");

  doc.setContents(withLoad(doc.design(), 1e300), "", "1e300 N");
  settle();
  EXPECT_FALSE(panel.samples());
  EXPECT_TRUE(panel.message().contains("too large to plot")) << panel.message();
  EXPECT_TRUE(panel.message().contains("e+300 N")) << panel.message();
  EXPECT_FALSE(panel.plotWidget()->isVisible());

  doc.setContents(withLoad(doc.design(), 1e308, 2), "", "overflow");
  settle();
  EXPECT_FALSE(panel.samples());
  EXPECT_TRUE(panel.message().contains("overflow (beyond 1e308 N")) << panel.message();
  for (const char* word : {"inf", "nan"})
    EXPECT_FALSE(panel.message().contains(word, Qt::CaseInsensitive)) << panel.message();
  shot(&panel, "forces-panel-overflow");
}

// Masses on every moving body of an example in space, each centre of mass off its points (so
// that everything shakes).
Mechanism withMassesInSpace(const char* name) {
  Mechanism m = *loadMechanismFile(*resolveModel(name)).mechanism;
  double kg = 0.05;
  for (Body& b : m.bodies) {
    if (b.ground) continue;
    Vec2 c = Vec2::Zero();
    int n = 0;
    for (const Point& p : m.points)
      if (p.body == b.id) c += p.pos, ++n;
    b.mass = Mass{kg += 0.02, c / std::max(n, 1) + Vec2(1.5, -0.7), 20, {}, {}};
  }
  m.gravity = Vec2(0, 0);
  m.gravityZ = -9.81;
  return m;
}

// Issue 27: on a machine in space the plots draw what `linkage-cli dynamics` writes, in the
// world's axes: the shaking force's x, y and z; a bearing's force, its class frame's fx and fy
// and what it bears along the normal (fn) lifted by the plane's axes here, from the solver's
// reaction at each sample; a ball rod's tension; a bevel pair's couple (its tooth force is not
// computed). The titles and the values at the pose say "world axes".
TEST_F(ForcesPanelTest, AMachineInSpacePlotsTheWorldsForces) {
  doc.setContents(withMassesInSpace("rssr-crank-rocker"), "", "rssr");
  showAndSettle();
  const ForceSamples* s = panel.samples();
  ASSERT_TRUE(s) << panel.message();
  ASSERT_TRUE(s->inSpace);
  const ForceFigure& f = panel.figure();
  ASSERT_TRUE(f.curve(ForceFigure::ShakingZ));
  // The rocker's bearing, pin:ground.H: in the rocker's plane (its x and y axes, normal x x y).
  const Plane& p = *planeNamed(doc.design(), "rocker");
  panel.setJoint(1);
  ASSERT_TRUE(f.curve(ForceFigure::ReactionZ));
  Kinematics k = doc.kinematics();
  k.setAccelerations(true);
  ForceSolver solver;
  ASSERT_TRUE(solver.prepare(k).ok());
  double peak = 0, worst = 0;
  for (int i : {0, 37, 90, 181, 300, 360}) {
    SCOPED_TRACE(i);
    ASSERT_TRUE(k.moveTo(s->crankDeg[i]).ok());
    const Forces& r = solver.compute(k);
    // (The sweep reaches each angle from the one before, this solver straight: rounding apart.)
    const Vec3 shaking(at(f.curve(ForceFigure::ShakingX), i), at(f.curve(ForceFigure::ShakingY), i),
                       at(f.curve(ForceFigure::ShakingZ), i));
    EXPECT_LT((shaking - r.shakingForce3N).norm(), 1e-12 * r.shakingForce3N.norm());
    const JointReaction& h = r.joints[1];
    const Vec3 w = h.force.x() * p.xAxis + h.force.y() * p.yAxis + h.normalN * p.normal();
    const Vec3 drawn(at(f.curve(ForceFigure::ReactionX), i), at(f.curve(ForceFigure::ReactionY), i),
                     at(f.curve(ForceFigure::ReactionZ), i));
    worst = std::max(worst, (drawn - w).norm());
    peak = std::max(peak, w.norm());
    EXPECT_NEAR(at(f.curve(ForceFigure::ReactionNorm), i), w.norm(), 1e-11 * w.norm());
  }
  ASSERT_GT(peak, 0.01);
  EXPECT_LT(worst, 1e-11 * peak);
  auto titled = [&](const QString& text) {
    for (QCPLayoutElement* e : panel.plotWidget()->plotLayout()->elements(true))
      if (auto* t = qobject_cast<QCPTextElement*>(e); t && t->text() == text) return true;
    return false;
  };
  EXPECT_TRUE(titled("Shaking force, world axes"));
  EXPECT_TRUE(titled("Reaction pin:ground.H (on ground), world axes"));
  ASSERT_TRUE(doc.setCrankDeg(40).ok());
  EXPECT_TRUE(panel.cursorText().startsWith("At 40.0°, world axes: torque")) << panel.cursorText();
  EXPECT_TRUE(panel.cursorText().contains("about its plane's x and y")) << panel.cursorText();
  shot(&panel, "forces-panel-space-bearing");
  // The rod: its tension, the solver's multiplier.
  panel.setJoint(2);
  EXPECT_TRUE(titled("Tension of ball-rod:crank.A"));
  ASSERT_TRUE(f.curve(ForceFigure::ReactionScalar));
  EXPECT_FALSE(f.curve(ForceFigure::ReactionX));
  for (int i : {0, 90, 270}) {
    ASSERT_TRUE(k.moveTo(s->crankDeg[i]).ok());
    const double T = solver.compute(k).joints[2].axialN;
    EXPECT_NEAR(at(f.curve(ForceFigure::ReactionScalar), i), T, 1e-11 * std::abs(T));
  }
  EXPECT_TRUE(panel.cursorText().contains("; ball-rod:crank.A tension ")) << panel.cursorText();
  shot(&panel, "forces-panel-space-rod");
  // A bevel pair: the couple on a's shaft about its axis.
  doc.setContents(withMassesInSpace("lockstitch-bevel"), "", "bevel");
  settle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  panel.setJoint(5);
  EXPECT_TRUE(titled("Couple gear:armshaft.O (on armshaft)"));
  ASSERT_TRUE(f.curve(ForceFigure::ReactionScalar));
  EXPECT_EQ(f.rect(ForceFigure::Reaction)->axis(QCPAxis::atLeft)->label(), "Couple [N m]");
  EXPECT_EQ(at(f.curve(ForceFigure::ReactionScalar), 10), panel.samples()->axialOrCouple[5][10]);
  EXPECT_TRUE(std::isfinite(at(f.curve(ForceFigure::ReactionScalar), 10)));
  shot(&panel, "forces-panel-space-bevel");
}

// Issue 26: at the window's first layout (1280 x 800) the Forces dock drew its four plots two
// by two, about 40 px high, and the polar diagram on equal scales as a flat strip. Each plot has
// a height to read its curves by, and the polar diagram is square; in a dock lower still the
// plots keep that height and the dock scrolls.
TEST(ForcesDock, AtTheFirstLayoutEachPlotHasAHeightToReadAndThePolarDiagramIsSquare) {
  MainWindow w;
  w.resize(1280, 800);
  ASSERT_TRUE(w.openExample("wanzer-inversion-2-masses"));
  w.show();
  QApplication::processEvents();
  w.forces().dock->show();
  w.forces().dock->raise();  // its tab in front of the Plots'
  ForcesPanel* panel = w.forces().panel();
  auto settle = [&] {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel->redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    panel->plotWidget()->replot();
  };
  settle();
  ASSERT_TRUE(panel->samples()) << panel->message();
  const ForceFigure& f = panel->figure();
  auto readable = [&](const char* when) {
    SCOPED_TRACE(when);
    for (ForceFigure::Plot p :
         {ForceFigure::Torque, ForceFigure::Shaking, ForceFigure::Polar, ForceFigure::Reaction}) {
      EXPECT_GE(f.rect(p)->height(), 80) << p;
      EXPECT_GE(f.rect(p)->width(), 80) << p;
    }
    // Square, or near it: never a strip.
    const QCPAxisRect* polar = f.rect(ForceFigure::Polar);
    EXPECT_LE(std::max(polar->width(), polar->height()),
              1.2 * std::min(polar->width(), polar->height()))
        << polar->width() << " x " << polar->height();
    const double nx = polar->axis(QCPAxis::atBottom)->range().size() / polar->width();
    const double ny = polar->axis(QCPAxis::atLeft)->range().size() / polar->height();
    EXPECT_NEAR(nx, ny, 1e-9 * ny);
  };
  readable("the first layout");
  EXPECT_EQ(f.columns(), 4);  // a dock under the canvas, wide and low: one row
  shot(&w, "forces-dock-1280x800");
  // The dock made lower than the plots need: they keep their height, and it scrolls.
  w.forces().dock->setMaximumHeight(150);
  settle();
  readable("a low dock");
  EXPECT_GE(panel->plotWidget()->height(), ForceFigure::kLeastPlotHeight);
  shot(&w, "forces-dock-low");
}

TEST_F(ForcesPanelTest, WorksOnlyWhenShown) {
  open("slider-crank-22a-masses");
  EXPECT_EQ(panel.computations(), 0);
  doc.setCrankDeg(40);
  EXPECT_EQ(panel.computations(), 0);
  showAndSettle();
  EXPECT_EQ(panel.computations(), 1);
  panel.hide();
  open("wanzer-inversion-2-masses");
  QTest::qWait(50);
  EXPECT_EQ(panel.computations(), 1);
  panel.show();
  settle();
  EXPECT_EQ(panel.computations(), 2);
}

#ifdef LINKAGE_CLI
QByteArray cliDynamics(const QString& model, int steps) {
  QProcess p;
  p.start(LINKAGE_CLI, {"dynamics", model, "--steps", QString::number(steps)});
  if (!p.waitForFinished(60000) || p.exitCode() != 0) return "failed: " + p.readAllStandardError();
  return p.readAllStandardOutput();
}

TEST_F(ForcesPanelTest, TheTableIsTheCommandLinesByteForByte) {
  QTemporaryDir dir;
  for (const char* name : {"slider-crank-22a-masses", "wanzer-inversion-2-masses", "drop-feed"}) {
    SCOPED_TRACE(name);
    open(name);
    const QString path = dir.filePath(QString(name) + ".csv");
    QString why;
    ASSERT_TRUE(panel.exportTable(path, 72, 1, &why)) << why;
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray ours = f.readAll();
    EXPECT_EQ(ours, cliDynamics(example(name), 72));
    EXPECT_EQ(ours.count('\n'), 74);  // header and 73 rows
  }
}
#endif

TEST_F(ForcesPanelTest, LaysTheExamplesOutInARowOrTwoByTwo) {
  open("drop-feed");
  showAndSettle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  EXPECT_EQ(panel.figure().columns(), 4);  // the dock of a 1400 px window: one row
  shot(&panel, "forces-panel-drop-feed");
  panel.resize(620, 600);  // a dock at the side: two by two
  settle();
  EXPECT_EQ(panel.figure().columns(), 2);
  const ForceFigure& f = panel.figure();
  EXPECT_LT(f.rect(ForceFigure::Torque)->bottom(), f.rect(ForceFigure::Polar)->top());
  shot(&panel, "forces-panel-drop-feed-narrow");
}

// The crank-angle axes' labels fit under their plots: four in a row in a dock beside the
// Properties ran "armshaft angle [deg], counter-clockwise" into each other; the long form
// where there is room, the brief one ("armshaft [deg], ccw") where there is not.
TEST_F(ForcesPanelTest, CrankAxisLabelsFitTheirPlots) {
  open("drop-feed");
  showAndSettle();
  ASSERT_TRUE(panel.samples()) << panel.message();
  const ForceFigure& f = panel.figure();
  auto label = [&](ForceFigure::Plot p) { return f.rect(p)->axis(QCPAxis::atBottom)->label(); };
  for (int width : {1400, 960, 620}) {
    panel.resize(width, 350);
    settle();
    for (ForceFigure::Plot p : {ForceFigure::Torque, ForceFigure::Shaking, ForceFigure::Reaction}) {
      const QCPAxis* x = f.rect(p)->axis(QCPAxis::atBottom);
      EXPECT_LE(QFontMetrics(x->labelFont()).horizontalAdvance(x->label()),
                f.rect(p)->outerRect().width())
          << width << " px: " << x->label().toStdString();
      EXPECT_TRUE(label(p).startsWith("armshaft")) << label(p).toStdString();
    }
    if (width == 960) EXPECT_EQ(label(ForceFigure::Torque), "armshaft [deg], ccw");
  }
  panel.resize(2400, 350);
  settle();
  EXPECT_EQ(label(ForceFigure::Torque), "armshaft angle [deg], counter-clockwise");
}

TEST_F(ForcesPanelTest, ExportsTheFigure) {
  open("wanzer-inversion-2-masses");
  QTemporaryDir dir;
  QString why;
  for (const char* suffix : {"png", "svg", "pdf"}) {
    const QString path = dir.filePath(QString("forces.") + suffix);
    ASSERT_TRUE(panel.exportFigure(path, QSize(1600, 700), &why)) << why;
    EXPECT_GT(QFileInfo(path).size(), 1000) << suffix;
  }
  const QImage png(dir.filePath("forces.png"));
  EXPECT_EQ(png.size(), QSize(1600, 700));
  EXPECT_FALSE(panel.exportFigure(dir.filePath("forces.bmp"), QSize(800, 400), &why));
  EXPECT_TRUE(why.contains("unknown format")) << why;
}

}  // namespace
}  // namespace linkage::ui
