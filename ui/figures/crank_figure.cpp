#include "figures/crank_figure.h"

#include <cmath>

#include "figures/figure_export.h"
#include "figures/qcp.h"

namespace linkage::ui {

namespace {

// A divisor or multiple of a turn, at most `intervals` of them over the range.
double tickStep(double range, int intervals) {
  for (double s : {15.0, 30.0, 45.0, 90.0, 180.0, 360.0, 720.0, 1440.0})
    if (range / s <= intervals + 1e-9) return s;
  return 360.0 * std::ceil(range / intervals / 360);
}

}  // namespace

void setCrankAxis(QCPAxis* x, double xMax, const QString& label, int intervals) {
  auto ticker = QSharedPointer<QCPAxisTickerFixed>::create();
  ticker->setTickStep(tickStep(xMax, intervals));
  ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
  x->setTicker(ticker);
  x->setRange(0, xMax);
  x->setLabel(label);
  const int half = QFontMetrics(x->tickLabelFont()).horizontalAdvance(QString::number(xMax)) / 2;
  QMargins m = x->axisRect()->minimumMargins();
  m.setRight(half + 6);
  x->axisRect()->setMinimumMargins(m);
}

double crankInPeriod(double deg, double period) {
  return deg - period * std::floor(deg / period);
}

double crankNear(double deg, double current, double period) {
  return period * std::floor(current / period) + deg;
}

CrankFigure::CrankFigure(QCustomPlot* plot) : plot_(plot) {
  // A figure adds to a legend what it names itself (a graph's extremes are no entry of it).
  plot_->setAutoAddPlottableToLegend(false);
  // Curves as one polyline each (not segment by segment): a replot costs a fraction, which a
  // drag that reshapes the design and redraws the curves 30 times a second needs.
  plot_->setPlottingHint(QCP::phFastPolylines, true);
  cursorLayer_ = plot_->layer("cursor");
  if (!cursorLayer_) {
    plot_->addLayer("cursor", plot_->layer("main"), QCustomPlot::limAbove);
    cursorLayer_ = plot_->layer("cursor");
    // Its own paint buffer: replotting it leaves the curves' buffer as it is.
    cursorLayer_->setMode(QCPLayer::lmBuffered);
  }
}

void CrankFigure::clearPlot() {
  plot_->clearItems();
  plot_->clearPlottables();
  crankRects_.clear();
  lines_.clear();
  dots_.clear();
  dragRect_ = -1;
}

void CrankFigure::addCursorLine(QCPAxisRect* rect) {
  auto* line = new QCPItemStraightLine(plot_);
  line->setLayer(cursorLayer_);
  line->setClipAxisRect(rect);
  line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  line->setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
  crankRects_.push_back(rect);
  lines_.push_back(line);
}

void CrankFigure::addCursorDot(QCPGraph* graph) {
  auto* dot = new QCPItemTracer(plot_);
  dot->setLayer(cursorLayer_);
  dot->setGraph(graph);
  dot->setInterpolating(true);
  dot->setStyle(QCPItemTracer::tsCircle);
  dot->setSize(6);
  dot->setPen(QPen(graph->pen().color().darker(130)));
  dot->setBrush(Qt::white);
  dot->setClipAxisRect(graph->keyAxis()->axisRect());
  dots_.push_back(dot);
}

void CrankFigure::placeCursorDots() {
  for (QCPItemTracer* t : dots_) t->updatePosition();
}

void CrankFigure::setCursor(double deg) {
  cursorDeg_ = deg;
  for (QCPItemStraightLine* l : lines_) {
    l->point1->setCoords(deg, 0);
    l->point2->setCoords(deg, 1);
  }
  for (QCPItemTracer* t : dots_) {
    t->setGraphKey(deg);
    // Outside a curve that stops early the dot would sit at its end: hidden there.
    const QCPGraph* g = t->graph();
    t->setVisible(!g->data()->isEmpty() && deg >= g->data()->constBegin()->key &&
                  deg <= (g->data()->constEnd() - 1)->key);
  }
  cursorMoved(deg);
  cursorLayer_->replot();
}

void CrankFigure::setCursorVisible(bool on) {
  cursorLayer_->setVisible(on);
  cursorLayer_->replot();
}

double CrankFigure::crankAt(const QPointF& pixel, int* rect) const {
  if (rect) *rect = -1;
  for (size_t i = 0; i < crankRects_.size(); ++i)
    if (crankRects_[i]->rect().contains(pixel.toPoint())) {
      if (rect) *rect = static_cast<int>(i);
      return crankAtX(static_cast<int>(i), pixel.x());
    }
  return NAN;
}

double CrankFigure::crankAtX(int rect, double pixelX) const {
  if (rect < 0 || rect >= static_cast<int>(crankRects_.size())) return NAN;
  return crankRects_[rect]->axis(QCPAxis::atBottom)->pixelToCoord(pixelX);
}

double CrankFigure::crankDragged(const QPointF& pixel, bool press) {
  if (press) crankAt(pixel, &dragRect_);
  return crankAtX(dragRect_, pixel.x());
}

bool CrankFigure::exportFigure(const QString& path, QSize size, QString* error) {
  const bool shown = cursorLayer_->visible();
  setCursorVisible(false);
  const bool ok = exportPlot(plot_, path, size, error);
  setCursorVisible(shown);
  return ok;
}

}  // namespace linkage::ui
