// The plots panel: the cursor follows the crank, a click or drag asks for the crank angle under
// the mouse, work only when shown, units remembered, comparisons, harmonics, extremes.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <cstdlib>

#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/extremes.h"
#include "linkage/io/model_lookup.h"
#include "mechanisms.h"
#include "plots/motion_figure.h"
#include "plots/plots_panel.h"

namespace linkage::ui {
namespace {

QString example(const char* name) {
  return QString::fromStdString(*resolveModel(name));
}

// Saves a picture of a widget when LINKAGE_SHOTS names a directory (to look at it).
void shot(QWidget& w, const char* name) {
  if (const char* dir = std::getenv("LINKAGE_SHOTS"))
    w.grab().save(QString("%1/%2.png").arg(dir, name));
}

class PlotsPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    QSettings().remove("plots");
    ASSERT_TRUE(doc.open(example("wanzer-inversion-2"), nullptr));
    panel.resize(700, 900);
  }
  void TearDown() override { QSettings().remove("plots"); }
  void showAndSettle() {
    panel.show();
    settle();
  }
  // The panel redraws at most 30 times a second, from a timer that a loaded machine may run
  // late: wait a frame's time, then for the redraw that is still due.
  void settle() {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    ASSERT_FALSE(panel.redrawPending());
  }
  // The cursor lines' crank angle, read off the plot's items.
  std::vector<double> cursorLines() {
    std::vector<double> v;
    QCustomPlot* p = panel.plotWidget();
    for (int i = 0; i < p->itemCount(); ++i)
      if (auto* l = qobject_cast<QCPItemStraightLine*>(p->item(i)))
        v.push_back(l->point1->coords().x());
    return v;
  }

  Document doc;
  PlotsPanel panel;
};

TEST_F(PlotsPanelTest, CursorFollowsTheCrankWithoutRecomputing) {
  panel.setDocument(&doc);
  showAndSettle();
  ASSERT_EQ(panel.computations(), 1);
  ASSERT_EQ(panel.figure().rows(), 3);
  for (double deg : {100.0, 250.5, 400.0}) {
    ASSERT_TRUE(doc.setCrankDeg(deg).ok());
    const double shown = std::fmod(deg, 360.0);  // one revolution plotted
    EXPECT_DOUBLE_EQ(panel.cursorDeg(), shown);
    const std::vector<double> lines = cursorLines();
    ASSERT_EQ(lines.size(), 3u);  // one per plot
    for (double x : lines) EXPECT_DOUBLE_EQ(x, shown);
    // The values at the cursor are the solver's, at that angle.
    const PointId G = doc.design().outputs[0];
    const double y = doc.kinematics().position(G).y();
    EXPECT_TRUE(panel.cursorText().contains(QString::number(y, 'g', 5)))
        << panel.cursorText().toStdString();
  }
  EXPECT_EQ(panel.computations(), 1);  // poses only moved the cursor
  shot(panel, "plots-panel");
}

TEST_F(PlotsPanelTest, ClickAndDragAskForTheCrankAngleUnderTheMouse) {
  panel.setDocument(&doc);
  QObject::connect(&panel, &PlotsPanel::crankAngleRequested, &doc,
                   [this](double d) { doc.setCrankDeg(d); });
  QSignalSpy spy(&panel, &PlotsPanel::crankAngleRequested);
  showAndSettle();
  const MotionFigure& f = panel.figure();
  const QPoint at = f.pixelAt(1, 0, 123.0, 0).toPoint();
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, at);
  ASSERT_EQ(spy.count(), 1);
  const double asked = spy.at(0).at(0).toDouble();
  EXPECT_DOUBLE_EQ(asked, f.crankAt(at));
  EXPECT_NEAR(asked, 123.0, 1.0);           // within a pixel's worth of degrees (360 / ~600 px)
  EXPECT_DOUBLE_EQ(doc.crankDeg(), asked);  // the mechanism followed
  EXPECT_DOUBLE_EQ(panel.cursorDeg(), asked);

  // In the second revolution, a click asks for the angle in that revolution (the short way).
  ASSERT_TRUE(doc.setCrankDeg(400).ok());
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, f.pixelAt(2, 0, 300.0, 0).toPoint());
  ASSERT_EQ(spy.count(), 2);
  EXPECT_NEAR(spy.at(1).at(0).toDouble(), 660.0, 1.0);

  // A drag scrubs: each move asks again; past the right end it stops at the end.
  QWidget* w = panel.plotWidget();
  const QPoint from = f.pixelAt(0, 0, 30.0, -50).toPoint();
  QTest::mousePress(w, Qt::LeftButton, {}, from);
  for (double deg : {60.0, 90.0, 500.0}) {
    const QPoint to(f.pixelAt(0, 0, deg, -50).toPoint());
    QMouseEvent move(QEvent::MouseMove, to, w->mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(w, &move);
  }
  QTest::mouseRelease(w, Qt::LeftButton, {}, from);
  ASSERT_EQ(spy.count(), 6);
  EXPECT_NEAR(spy.at(4).at(0).toDouble(), 360 + 90.0, 1.0);
  EXPECT_DOUBLE_EQ(spy.at(5).at(0).toDouble(), 360 + 360.0);
  // A click outside the plots asks for nothing.
  QTest::mouseClick(w, Qt::LeftButton, {}, QPoint(2, 2));
  EXPECT_EQ(spy.count(), 6);
}

TEST_F(PlotsPanelTest, HiddenPanelComputesNothingAndEditsResampleOnlyWhatIsShown) {
  panel.setDocument(&doc);
  EXPECT_EQ(panel.computations(), 0);
  Mechanism edited = doc.design();
  edited.point(*edited.findPoint("triangle.G"))->pos.y() -= 1;
  doc.setDesign(edited);
  settle();
  EXPECT_EQ(panel.computations(), 0);
  showAndSettle();
  EXPECT_EQ(panel.computations(), 1);
  // A burst of edits while shown: sampled once, when the events are processed.
  doc.setDesign(doc.design());
  doc.setDesign(doc.design());
  settle();
  EXPECT_EQ(panel.computations(), 2);
  panel.hide();
  doc.setDesign(doc.design());
  settle();
  EXPECT_EQ(panel.computations(), 2);
  showAndSettle();
  EXPECT_EQ(panel.computations(), 3);
  // Accelerations are not sampled when no plot shows them.
  CurveRequest r = panel.request();
  r.orders = {true, true, false, false};
  panel.setRequest(r);
  settle();
  ASSERT_NE(panel.curves(0), nullptr);
  EXPECT_TRUE(panel.curves(0)->curve(Order::Acceleration).values.empty());
  EXPECT_EQ(panel.figure().rows(), 2);
}

TEST_F(PlotsPanelTest, UnitsAreSwitchedInTheLabelsAndRemembered) {
  panel.setDocument(&doc);
  showAndSettle();
  PlotUnits u;
  u.velocity = VelocityUnit::MetrePerSecond;
  u.acceleration = AccelerationUnit::G;
  panel.setUnits(u);
  EXPECT_EQ(panel.figure().axisRect(1, 0)->axis(QCPAxis::atLeft)->label(), "Velocity vy [m/s]");
  EXPECT_EQ(panel.figure().axisRect(2, 0)->axis(QCPAxis::atLeft)->label(), "Acceleration ay [g]");
  EXPECT_EQ(panel.computations(), 1);  // units change the figure, not the samples
  // The plotted acceleration is the solver's divided by 9806.65 mm/s^2.
  QCPGraph* g = nullptr;  // the first graph of the third plot is its curve
  for (int i = panel.plotWidget()->graphCount() - 1; i >= 0; --i)
    if (panel.plotWidget()->graph(i)->keyAxis() ==
        panel.figure().axisRect(2, 0)->axis(QCPAxis::atBottom))
      g = panel.plotWidget()->graph(i);
  ASSERT_NE(g, nullptr);
  const Curve& a = panel.curves(0)->curve(Order::Acceleration);
  EXPECT_DOUBLE_EQ(g->data()->at(17)->value, a.values[17] / 9806.65);
  PlotsPanel other;
  EXPECT_EQ(other.units(), u);
}

TEST_F(PlotsPanelTest, ComparisonOverlaidOrSideBySideAndEditsOfOneResampleOne) {
  Document inv1;
  ASSERT_TRUE(inv1.open(example("wanzer-inversion-1"), nullptr));
  panel.setDocument(&doc);
  panel.setComparisonDocuments({&doc, &inv1});  // the document itself is not compared
  showAndSettle();
  EXPECT_EQ(panel.figure().columns(), 1);
  EXPECT_EQ(panel.curves(1), nullptr);  // comparison off: not sampled
  panel.setCompare(PlotsPanel::Compare::SideBySide);
  settle();
  EXPECT_EQ(panel.figure().columns(), 2);
  ASSERT_NE(panel.curves(1), nullptr);
  EXPECT_EQ(panel.curves(1)->title(), "Wanzer needle bar, inversion 1");
  const int before = panel.computations();
  Mechanism edited = inv1.design();
  edited.point(*edited.findPoint("triangle.G"))->pos.y() -= 1;
  inv1.setDesign(edited);
  settle();
  EXPECT_EQ(panel.computations(), before + 1);
  panel.setCompare(PlotsPanel::Compare::Overlay);
  settle();
  EXPECT_EQ(panel.figure().columns(), 1);
  EXPECT_EQ(panel.computations(), before + 1);  // the same curves, laid out again
  shot(panel, "plots-panel-overlay");
}

TEST_F(PlotsPanelTest, ExtremesAreListedAndMarked) {
  ASSERT_TRUE(doc.open(example("slider-crank-22a-lambda-0.5"), nullptr));
  panel.setDocument(&doc);
  showAndSettle();
  const QString text = panel.extremesText();
  // The stroke of the slider-crank is 2 r = 30 mm, top dead centre at 0, bottom at 180.
  EXPECT_TRUE(
      text.contains("Position y (stroke): max 45 mm at 0.00°, min 15 mm at 180.00°, range 30 mm"))
      << text.toStdString();
  const Extremes& v = panel.curves(0)->extremes(Order::Velocity);
  EXPECT_TRUE(text.contains(QString("max %1 mm/s").arg(QString::number(v.max.value, 'g', 5))));
}

TEST_F(PlotsPanelTest, HarmonicsViewShowsTheAmplitudes) {
  ASSERT_TRUE(doc.open(example("slider-crank-22a-lambda-0.3"), nullptr));
  panel.setDocument(&doc);
  panel.setHarmonicsShown(true);
  showAndSettle();
  QCustomPlot* h = nullptr;
  for (QCustomPlot* p : panel.findChildren<QCustomPlot*>())
    if (p != panel.plotWidget()) h = p;
  ASSERT_NE(h, nullptr);
  ASSERT_EQ(h->plottableCount(), 3);  // position, velocity, acceleration
  auto* bars = qobject_cast<QCPBars*>(h->plottable(0));
  ASSERT_NE(bars, nullptr);
  ASSERT_EQ(bars->data()->size(), 20);
  // y = r cos(phi) + l sqrt(1 - lambda^2 sin^2 phi): the first harmonic is r = 15 mm.
  EXPECT_NEAR(bars->data()->at(0)->value, 15.0, 1e-9);
  // No third harmonic: its bar is at the floor of the logarithmic axis, 1e-10 of the largest.
  EXPECT_NEAR(bars->data()->at(2)->value, 15.0 * 1e-10, 1e-12);
  // And the numbers listed: amplitude and phase of each.
  EXPECT_TRUE(panel.extremesText().contains("Position y: k=1 15 mm 0.00°"))
      << panel.extremesText().toStdString();
  shot(panel, "plots-panel-harmonics");
}

TEST_F(PlotsPanelTest, ControlsChangeWhatIsPlotted) {
  panel.setDocument(&doc);
  showAndSettle();
  QComboBox* acceleration = nullptr;
  for (QComboBox* c : panel.findChildren<QComboBox*>())
    if (c->findText("g") >= 0) acceleration = c;
  ASSERT_NE(acceleration, nullptr);
  acceleration->setCurrentIndex(acceleration->findText("g"));
  EXPECT_EQ(panel.units().acceleration, AccelerationUnit::G);
  EXPECT_EQ(panel.figure().axisRect(2, 0)->axis(QCPAxis::atLeft)->label(), "Acceleration ay [g]");
  QCheckBox* jerk = nullptr;
  for (QCheckBox* c : panel.findChildren<QCheckBox*>())
    if (c->text() == "Jerk") jerk = c;
  ASSERT_NE(jerk, nullptr);
  QTest::mouseClick(jerk, Qt::LeftButton);
  settle();
  EXPECT_TRUE(panel.request().orders[3]);
  EXPECT_EQ(panel.figure().rows(), 4);
  EXPECT_EQ(panel.figure().axisRect(3, 0)->axis(QCPAxis::atLeft)->label(), "Jerk jy [g/s]");
  EXPECT_TRUE(panel.curves(0)->curve(Order::Jerk).status.ok());
}

TEST_F(PlotsPanelTest, APointTheEditRemovesGivesWayToTheFirstOutput) {
  panel.setDocument(&doc);
  CurveRequest r = panel.request();
  r.target = "triangle.E";
  panel.setRequest(r);
  showAndSettle();
  ASSERT_EQ(panel.curves(0)->quantity().point, *doc.design().findPoint("triangle.E"));
  Mechanism edited = doc.design();
  edited.remove(*edited.findPoint("triangle.E"));  // and the joints at E
  edited.addPin(edited.addPoint(edited.bodyNamed("triangle")->id, "E2", Vec2(0, 0)),
                *edited.findPoint("slider4.E"));
  doc.setDesign(edited);
  settle();
  EXPECT_EQ(panel.request().target, "needlebar.G");
  ASSERT_NE(panel.curves(0), nullptr);
  EXPECT_EQ(panel.curves(0)->quantity().point, *doc.design().findPoint("needlebar.G"));
}

// Issue 26: a point chosen in the plots' list stayed chosen when another design was opened in
// the window (by name: the last design's point). It stays through edits of its design; a design
// opened in its place plots its own default point.
TEST_F(PlotsPanelTest, AnotherDesignOpenedPlotsItsOwnPoint) {
  panel.setDocument(&doc);
  showAndSettle();
  auto* target = panel.findChild<QComboBox*>("plotTarget");
  ASSERT_TRUE(target);
  const int e = target->findText("triangle.E");
  target->setCurrentIndex(e);  // as the user picks it
  Q_EMIT target->activated(e);
  settle();
  ASSERT_EQ(panel.request().target, "triangle.E");
  Mechanism edited = doc.design();
  edited.point(*edited.findPoint("triangle.G"))->pos += Vec2(0.5, 0);
  doc.setDesign(edited);
  settle();
  EXPECT_EQ(panel.request().target, "triangle.E");  // the user's choice, through an edit
  // Another design with a triangle.E of its own: its own first output.
  ASSERT_TRUE(doc.open(example("wanzer-inversion-2-masses"), nullptr));
  settle();
  ASSERT_TRUE(doc.design().findPoint("triangle.E"));
  EXPECT_EQ(panel.request().target, "needlebar.G");
  ASSERT_NE(panel.curves(0), nullptr);
  EXPECT_EQ(panel.curves(0)->quantity().point, *doc.design().findPoint("needlebar.G"));
}

TEST_F(PlotsPanelTest, EmptyDocumentSaysWhy) {
  Document empty;  // a ground and nothing else: no driver, nothing to plot
  panel.setDocument(&empty);
  showAndSettle();
  ASSERT_NE(panel.curves(0), nullptr);
  EXPECT_TRUE(panel.curves(0)->empty());
  EXPECT_FALSE(panel.curves(0)->status().ok());
  EXPECT_TRUE(panel.cursorText().isEmpty() || panel.cursorText().contains(QString::fromUtf8("—")));
  panel.setDocument(nullptr);
  settle();
  QString err;
  EXPECT_FALSE(panel.exportFigure("/tmp/never.png", QSize(400, 300), &err));
  EXPECT_FALSE(err.isEmpty());
}

TEST_F(PlotsPanelTest, CrankThatStopsPlotsThePartThatExistsAndClicksStayInIt) {
  auto f = test::fourBar(100, 60, 40, 70, 30);  // locks 52.8 degrees on
  doc.setContents(f.m, QString());
  panel.setDocument(&doc);
  QSignalSpy spy(&panel, &PlotsPanel::crankAngleRequested);
  showAndSettle();
  const CurveSet* set = panel.curves(0);
  ASSERT_NE(set, nullptr);
  EXPECT_EQ(set->status().code, StatusCode::Unreachable);
  EXPECT_DOUBLE_EQ(set->lastDeg(), 52);
  EXPECT_FALSE(set->periodic());
  const QPoint at(panel.figure().pixelAt(1, 0, 200.0, 0).x(),
                  panel.figure().axisRect(1, 0)->center().y());
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, at);
  ASSERT_EQ(spy.count(), 1);
  EXPECT_DOUBLE_EQ(spy.at(0).at(0).toDouble(), 52);  // the end of what exists
  shot(panel, "plots-panel-partial");
}

// Under the canvas (wide) the units and the comparison share the first row, which leaves the
// plots a row more; beside it (narrow) they take a row of their own, and the dock can still be
// narrowed from wide to narrow.
TEST_F(PlotsPanelTest, ControlsTakeTwoRowsWhenWideAndThreeWhenNarrow) {
  panel.setDocument(&doc);
  panel.resize(1000, 500);
  showAndSettle();
  QComboBox *target = panel.findChild<QComboBox*>("plotTarget"), *units = nullptr;
  for (QComboBox* c : panel.findChildren<QComboBox*>())
    if (c->findText("m/s") >= 0) units = c;
  ASSERT_TRUE(target && units);
  auto row = [](QWidget* w) { return w->mapTo(w->window(), QPoint(0, w->height() / 2)).y(); };
  EXPECT_EQ(row(units), row(target));
  const int plotTopWide = panel.plotWidget()->mapTo(&panel, QPoint()).y();
  // No wider a minimum than with three rows (the orders' row sets it).
  const int narrowest = panel.minimumSizeHint().width();
  panel.resize(narrowest + 10, 500);
  // The layouts redo themselves from posted events: wait for the third row and the plot moved
  // below it (up to 5 s; a fixed 20 ms failed once on a loaded machine).
  auto relaid = [&] {
    return row(units) > row(target) + target->height() / 2 &&
           panel.plotWidget()->mapTo(&panel, QPoint()).y() > plotTopWide;
  };
  for (int i = 0; i < 500 && !relaid(); ++i) QTest::qWait(10);
  EXPECT_EQ(panel.minimumSizeHint().width(), narrowest);
  EXPECT_GT(row(units), row(target) + target->height() / 2);
  EXPECT_GT(panel.plotWidget()->mapTo(&panel, QPoint()).y(), plotTopWide);
  EXPECT_LE(units->mapTo(&panel, QPoint(units->width(), 0)).x(), panel.width());
}

// The y labels never run into each other: each is as long as its plot is high at most (a
// rotated label longer than that reaches into the next plot's: "ay [mm/s2]vy [mm/s]"), long
// where there is room, short where less, across the plot's corner where not even that fits.
TEST_F(PlotsPanelTest, YLabelsFitTheirPlotsInALowDock) {
  panel.setDocument(&doc);
  for (int height : {900, 420, 330, 260}) {
    panel.resize(1000, height);
    showAndSettle();
    const MotionFigure& f = panel.figure();
    ASSERT_EQ(f.rows(), 3);
    int inCorner = 0;
    for (int r = 0; r < f.rows(); ++r) {
      QCPAxisRect* rect = f.axisRect(r, 0);
      QCPAxis* y = rect->axis(QCPAxis::atLeft);
      const int length = QFontMetrics(y->labelFont()).horizontalAdvance(y->label());
      EXPECT_LE(length, rect->outerRect().height()) << height << " px, row " << r;
      const bool corner = f.cornerLabel(r, 0)->visible();
      EXPECT_EQ(corner, y->label().isEmpty()) << height << " px, row " << r;
      inCorner += corner;
      if (corner) {
        EXPECT_FALSE(f.cornerLabel(r, 0)->text().isEmpty());
        // Inside its own plot.
        const QRectF at(f.cornerLabel(r, 0)->topLeft->pixelPosition(),
                        f.cornerLabel(r, 0)->bottomRight->pixelPosition());
        EXPECT_TRUE(QRectF(rect->rect()).contains(at)) << height << " px, row " << r;
      }
    }
    if (height == 900) {
      EXPECT_EQ(inCorner, 0);
      EXPECT_EQ(f.axisRect(2, 0)->axis(QCPAxis::atLeft)->label(), "Acceleration ay [mm/s²]");
    }
    // All or none in the corners.
    EXPECT_TRUE(inCorner == 0 || inCorner == f.rows()) << height << " px";
    if (height == 260) EXPECT_EQ(inCorner, 3);
  }
}

}  // namespace
}  // namespace linkage::ui
