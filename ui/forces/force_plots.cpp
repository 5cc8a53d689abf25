#include "forces/force_plots.h"

#include <algorithm>
#include <cmath>

#include "figures/crank_figure.h"
#include "figures/qcp.h"

namespace linkage::ui {

QCPAxisRect* addCrankRect(QCustomPlot* plot, const QString& crankLabel, const QString& yLabel) {
  auto* rect = new QCPAxisRect(plot);
  rect->setMinimumMargins(QMargins());  // no room beyond the axes' own (QCPAxisRect keeps 15 px)
  // Ticks every 90 degrees: the plots are narrow, four of them side by side.
  setCrankAxis(rect->axis(QCPAxis::atBottom), 360, crankLabel, 4);
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  y->setLabel(yLabel);
  y->ticker()->setTickCount(5);
  return rect;
}

QCPGraph* addCurve(QCPAxisRect* rect, const std::vector<double>& deg,
                   const std::vector<double>& values, const QColor& colour, const QString& name,
                   Qt::PenStyle style) {
  QCPGraph* g =
      rect->parentPlot()->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  g->setData(QVector<double>(deg.begin(), deg.end()), QVector<double>(values.begin(), values.end()),
             true);
  g->setPen(QPen(colour, 1.6, style));
  g->setName(name);
  return g;
}

double peakOf(const std::vector<double>& v) {
  double p = 0;
  for (double x : v)
    if (std::isfinite(x)) p = std::max(p, std::abs(x));
  return p;
}

double peakOf(const std::vector<Vec2>& v) {
  double p = 0;
  for (const Vec2& x : v)
    if (x.allFinite()) p = std::max(p, std::hypot(x.x(), x.y()));  // norm() overflows past 1e154
  return p;
}

double peakOf(const std::vector<Vec3>& v) {
  double p = 0;
  for (const Vec3& x : v)
    if (x.allFinite()) p = std::max(p, std::hypot(x.x(), x.y(), x.z()));
  return p;
}

void fitValues(QCPAxisRect* rect, double minHalfRange) {
  double lo = INFINITY, hi = -INFINITY;
  for (QCPGraph* g : rect->graphs()) {
    bool found = false;
    const QCPRange r = g->getValueRange(found);
    if (!found) continue;
    lo = std::min(lo, r.lower);
    hi = std::max(hi, r.upper);
  }
  if (!(lo <= hi)) lo = -1, hi = 1;
  // Zero in view: a force's sign matters, and a small ripple should not look like a big one.
  lo = std::min(lo, 0.0);
  hi = std::max(hi, 0.0);
  const double pad = 0.08 * (hi - lo);
  lo -= pad;
  hi += pad;
  if (hi - lo < 2 * minHalfRange || !(hi > lo)) {
    const double c = hi - lo < 2 * minHalfRange && hi > lo ? (hi + lo) / 2 : 0;
    const double h = minHalfRange > 0 ? minHalfRange : 1;
    lo = c - h;
    hi = c + h;
  }
  rect->axis(QCPAxis::atLeft)->setRange(lo, hi);
}

void addZeroLines(QCPAxisRect* rect, bool vertical) {
  QCustomPlot* plot = rect->parentPlot();
  for (int i = 0; i < (vertical ? 2 : 1); ++i) {
    auto* line = new QCPItemStraightLine(plot);
    line->setClipAxisRect(rect);
    line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
    line->point1->setCoords(0, 0);
    line->point2->setCoords(i == 0 ? 1 : 0, i == 0 ? 0 : 1);
    line->setPen(QPen(QColor(170, 170, 170), 1));
    line->setLayer("background");
  }
}

namespace {

// The corner of the rect with the fewest curve points, top right first on a tie.
Qt::Alignment emptiestCorner(QCPAxisRect* rect) {
  const QCPRange x = rect->axis(QCPAxis::atBottom)->range();
  const QCPRange y = rect->axis(QCPAxis::atLeft)->range();
  int count[4] = {};
  auto visit = [&](double kx, double vy) {
    const double fx = (kx - x.lower) / x.size(), fy = (vy - y.lower) / y.size();
    const bool right = fx > 0.55, left = fx<0.45, top = fy> 0.6, bottom = fy < 0.4;
    count[0] += right && top;
    count[1] += left && top;
    count[2] += right && bottom;
    count[3] += left && bottom;
  };
  for (QCPGraph* g : rect->graphs())
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
      visit(it->key, it->value);
  for (QCPAbstractPlottable* p : rect->plottables())
    if (auto* c = qobject_cast<QCPCurve*>(p))
      for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it)
        visit(it->key, it->value);
  const Qt::Alignment corners[4] = {Qt::AlignTop | Qt::AlignRight, Qt::AlignTop | Qt::AlignLeft,
                                    Qt::AlignBottom | Qt::AlignRight,
                                    Qt::AlignBottom | Qt::AlignLeft};
  return corners[std::min_element(count, count + 4) - count];
}

}  // namespace

QCPLayoutGrid* addPlotCell(QCPLayoutGrid* grid, int row, int column, QCPAxisRect* rect) {
  auto* cell = new QCPLayoutGrid;
  grid->addElement(row, column, cell);
  cell->addElement(0, 0, rect);
  cell->setColumnSpacing(2);
  return cell;
}

void addLegend(QCPAxisRect* rect, const std::vector<QCPAbstractPlottable*>& items,
               QCPLayoutGrid* cell) {
  auto* legend = new QCPLegend;
  if (cell) {
    // Beside the plot, level with its top.
    auto* column = new QCPLayoutGrid;
    cell->addElement(0, 1, column);
    cell->setColumnStretchFactor(1, 0.01);
    column->addElement(0, 0, legend);
    column->addElement(1, 0, new QCPLayoutElement(rect->parentPlot()));
    column->setRowStretchFactor(0, 0.01);
    column->setMargins(QMargins(0, 6, 0, 0));
    // As wide as its widest entry (icon, gaps, text): the grid would squeeze it otherwise.
    QFont f = rect->parentPlot()->font();
    f.setPointSizeF(f.pointSizeF() - 1);
    int text = 0;
    for (QCPAbstractPlottable* p : items)
      text = std::max(text, QFontMetrics(f).horizontalAdvance(p->name()));
    column->setMinimumSize(22 + text + 24, 0);
  } else {
    rect->insetLayout()->addElement(legend, emptiestCorner(rect));
  }
  legend->setLayer("legend");
  legend->setBrush(QColor(255, 255, 255, 210));
  legend->setBorderPen(QPen(QColor(200, 200, 200)));
  legend->setRowSpacing(0);
  legend->setIconSize(22, 10);
  QFont f = rect->parentPlot()->font();
  f.setPointSizeF(f.pointSizeF() - 1);
  legend->setFont(f);
  for (QCPAbstractPlottable* p : items) p->addToLegend(legend);
}

void addRectNote(QCPAxisRect* rect, const QString& text) {
  auto* t = new QCPItemText(rect->parentPlot());
  t->setClipAxisRect(rect);
  t->position->setType(QCPItemPosition::ptAxisRectRatio);
  t->position->setAxisRect(rect);
  t->position->setCoords(0.5, 0.5);
  t->setPositionAlignment(Qt::AlignCenter);
  t->setText(text);
  t->setColor(forceColours::kNote);
  t->setPadding(QMargins(6, 4, 6, 4));
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  y->setTickLabels(false);
  y->setRange(-1, 1);
}

void addTitle(QCPLayoutGrid* grid, int row, int column, const QString& text) {
  QFont f = grid->parentPlot()->font();
  f.setBold(true);
  auto* title = new QCPTextElement(grid->parentPlot(), text, f);
  title->setMargins(QMargins(2, 3, 2, 1));
  grid->addElement(row, column, title);
}

QCPAxisRect* addPolarRect(QCustomPlot* plot) {
  auto* rect = new QCPAxisRect(plot);
  rect->axis(QCPAxis::atBottom)->setLabel("Shaking fx [N]");
  rect->axis(QCPAxis::atLeft)->setLabel("Shaking fy [N]");
  for (QCPAxis* a : {rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft)})
    a->ticker()->setTickCount(4);
  return rect;
}

QCPCurve* addPolarCurve(QCPAxisRect* rect, const std::vector<Vec2>& f, const QColor& colour,
                        const QString& name, double width) {
  auto* c = new QCPCurve(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
  QVector<double> t, x, y;
  for (size_t i = 0; i < f.size(); ++i) {
    t.push_back(static_cast<double>(i));
    x.push_back(f[i].x());
    y.push_back(f[i].y());
  }
  c->setData(t, x, y, true);
  c->setPen(QPen(colour, width));
  c->setName(name);
  return c;
}

void polarBox(QCPAxisRect* rect, QCPRange& x, QCPRange& y) {
  x = QCPRange(0, 0);
  y = QCPRange(0, 0);
  for (QCPAbstractPlottable* p : rect->plottables()) {
    bool found = false;
    const QCPRange kx = p->getKeyRange(found);
    if (!found) continue;
    const QCPRange vy = p->getValueRange(found);
    if (!found) continue;
    x.expand(kx);
    y.expand(vy);
  }
}

bool fitEqualScales(QCPAxisRect* rect) {
  QCPRange bx, by;
  polarBox(rect, bx, by);
  const int w = rect->width(), h = rect->height();
  if (w < 10 || h < 10) return false;
  // Newtons per pixel: the larger need, with a margin, on both axes.
  double span = std::max(bx.size() / w, by.size() / h) * 1.12;
  if (!(span > 0)) span = 2.0 / std::min(w, h);
  const QCPRange x(bx.center() - span * w / 2, bx.center() + span * w / 2);
  const QCPRange y(by.center() - span * h / 2, by.center() + span * h / 2);
  QCPAxis* ax = rect->axis(QCPAxis::atBottom);
  QCPAxis* ay = rect->axis(QCPAxis::atLeft);
  auto same = [span](const QCPRange& a, const QCPRange& b) {
    return std::abs(a.lower - b.lower) <= 1e-6 * span && std::abs(a.upper - b.upper) <= 1e-6 * span;
  };
  if (same(ax->range(), x) && same(ay->range(), y)) return false;
  ax->setRange(x);
  ay->setRange(y);
  return true;
}

}  // namespace linkage::ui
