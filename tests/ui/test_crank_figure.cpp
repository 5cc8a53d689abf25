// What the crank-angle figures share (figures/crank_figure.h): the crank axis, the cursor at the
// pose and its dots on the curves, the crank angle under the mouse, the export without the
// cursor; and each of the plots', forces' and cycle figures with it.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QImage>
#include <QTemporaryDir>

#include "figures/crank_figure.h"
#include "figures/qcp.h"

namespace linkage::ui {
namespace {

double tickStepOf(QCPAxis* x) {
  return qSharedPointerCast<QCPAxisTickerFixed>(x->ticker())->tickStep();
}

TEST(CrankFigure, TheAxisIsTurnsOfTheCrankTickedAtADivisorOfATurn) {
  QCustomPlot plot;
  QCPAxis* x = plot.xAxis;
  setCrankAxis(x, 360, "disk angle [deg], clockwise");
  EXPECT_EQ(x->range().lower, 0);
  EXPECT_EQ(x->range().upper, 360);
  EXPECT_EQ(x->label(), "disk angle [deg], clockwise");
  EXPECT_EQ(tickStepOf(x), 45);  // 8 intervals at most
  setCrankAxis(x, 360, "", 4);
  EXPECT_EQ(tickStepOf(x), 90);
  setCrankAxis(x, 360, "", 12);
  EXPECT_EQ(tickStepOf(x), 30);
  setCrankAxis(x, 720, "", 8);
  EXPECT_EQ(x->range().upper, 720);
  EXPECT_EQ(tickStepOf(x), 90);
  setCrankAxis(x, 360 * 40, "", 8);
  EXPECT_EQ(tickStepOf(x), 360 * 5);  // whole turns past 1440
  // Room at the right for half of the last tick label, centred on the axis's end.
  const int half = QFontMetrics(x->tickLabelFont()).horizontalAdvance("14400") / 2;
  EXPECT_GE(x->axisRect()->minimumMargins().right(), half);
}

// One plot of one curve from 0 to 270 degrees (a crank that stops there).
class OneCurve : public CrankFigure {
 public:
  explicit OneCurve(QCustomPlot* plot) : CrankFigure(plot) {
    setCrankAxis(plot_->xAxis, 360, "crank angle [deg]");
    plot_->yAxis->setRange(-1.5, 1.5);
    graph = plot_->addGraph();
    for (int d = 0; d <= 270; ++d) graph->addData(d, std::sin(d * M_PI / 180));
    addCursorLine(plot_->axisRect());
    addCursorDot(graph);
  }
  QCPGraph* graph;
  QCPItemTracer* dot() const { return plot_->findChild<QCPItemTracer*>(); }
};

TEST(CrankFigure, TheCursorIsAtTheAngleAndItsDotOnlyWhereTheCurveIs) {
  QCustomPlot plot;
  plot.resize(600, 300);
  OneCurve f(&plot);
  plot.replot();
  f.setCursor(90);
  EXPECT_EQ(f.cursor(), 90);
  QCPItemTracer* dot = f.dot();
  ASSERT_TRUE(dot);
  EXPECT_TRUE(dot->visible());
  dot->updatePosition();
  EXPECT_NEAR(dot->position->value(), 1.0, 1e-9);
  f.setCursor(300);  // past where the crank stopped
  EXPECT_FALSE(dot->visible());
}

TEST(CrankFigure, APressOnThePlotAsksForTheAngleUnderItAndADragGoesOnPastTheAxes) {
  QCustomPlot plot;
  plot.resize(600, 300);
  OneCurve f(&plot);
  plot.replot();
  QCPAxis* x = plot.xAxis;
  const double y = plot.axisRect()->center().y();
  EXPECT_NEAR(f.crankAt(QPointF(x->coordToPixel(120), y)), 120, 1e-9);
  EXPECT_TRUE(std::isnan(f.crankAt(QPointF(2, 2))));  // outside the axes
  // A press outside: no drag.
  EXPECT_TRUE(std::isnan(f.crankDragged(QPointF(2, 2), true)));
  EXPECT_FALSE(f.dragging());
  // A press inside, then a drag out to the right: still the plot's angle.
  EXPECT_NEAR(f.crankDragged(QPointF(x->coordToPixel(200), y), true), 200, 1e-9);
  EXPECT_TRUE(f.dragging());
  EXPECT_NEAR(f.crankDragged(QPointF(x->coordToPixel(400), 2), false), 400, 1e-9);
  f.endDrag();
  EXPECT_TRUE(std::isnan(f.crankDragged(QPointF(x->coordToPixel(200), y), false)));
}

TEST(CrankFigure, AnExportHasNoCursorAndLeavesItAsItWas) {
  QCustomPlot plot;
  plot.resize(600, 300);
  OneCurve f(&plot);
  QTemporaryDir dir;
  const QString a = dir.filePath("a.png"), b = dir.filePath("b.png");
  f.setCursor(60);
  QString error;
  ASSERT_TRUE(f.exportFigure(a, QSize(600, 300), &error)) << error;
  EXPECT_TRUE(f.plot()->layer("cursor")->visible());
  f.setCursor(200);
  ASSERT_TRUE(f.exportFigure(b, QSize(600, 300), &error)) << error;
  // The cursor elsewhere, the same picture: it is not in it.
  EXPECT_EQ(QImage(a), QImage(b));
  // Drawn, it would have been.
  const QImage shown = plot.toPixmap(600, 300).toImage();
  f.setCursor(60);
  EXPECT_NE(plot.toPixmap(600, 300).toImage(), shown);
  // A figure drawn without a cursor keeps none after an export.
  f.setCursorVisible(false);
  ASSERT_TRUE(f.exportFigure(a, QSize(600, 300), &error)) << error;
  EXPECT_FALSE(f.plot()->layer("cursor")->visible());
}

TEST(CrankFigure, TheAngleWithinAPeriodAndNearTheCrank) {
  EXPECT_DOUBLE_EQ(crankInPeriod(370, 360), 10);
  EXPECT_DOUBLE_EQ(crankInPeriod(-10, 360), 350);
  EXPECT_DOUBLE_EQ(crankInPeriod(725, 720), 5);
  // A drag to 30 degrees with the crank in its third turn: 750, not 30.
  EXPECT_DOUBLE_EQ(crankNear(30, 800, 360), 750);
  EXPECT_DOUBLE_EQ(crankNear(30, -10, 360), -330);
}

}  // namespace
}  // namespace linkage::ui
