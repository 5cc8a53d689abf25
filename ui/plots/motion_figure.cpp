#include "plots/motion_figure.h"

#include <algorithm>
#include <cmath>

#include "figures/qcp.h"

namespace linkage::ui {

namespace {

// Why a set's curves stop early or are missing, under its column's title.
QString statusNote(const CurveSet& set, bool named, int width) {
  QString why = QString::fromStdString(set.status().message);
  if (!set.empty())
    why = QString::fromUtf8("Ends at %1°: %2").arg(set.lastDeg(), 0, 'f', 1).arg(why);
  return wrapped(named ? set.title() + ": " + why : why, width);
}

// A note in the top left corner of a plot, one line below another.
void addNote(QCustomPlot* plot, QCPAxisRect* rect, const QString& text, int line) {
  auto* t = new QCPItemText(plot);
  t->setClipAxisRect(rect);
  t->position->setType(QCPItemPosition::ptAxisRectRatio);
  t->position->setAxisRect(rect);
  t->position->setCoords(0.01, 0.02 + 0.1 * line);
  t->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
  t->setText(text);
  t->setColor(QColor(150, 20, 20));
  t->setBrush(QBrush(QColor(255, 255, 255, 220)));
}

// A y label across a plot's top right corner, on a backing: the curves may pass under it.
QCPItemText* addCornerLabel(QCustomPlot* plot, QCPAxisRect* rect, const QString& text) {
  auto* t = new QCPItemText(plot);
  t->setClipAxisRect(rect);
  t->position->setType(QCPItemPosition::ptAxisRectRatio);
  t->position->setAxisRect(rect);
  t->position->setCoords(0.995, 0.03);
  t->setPositionAlignment(Qt::AlignRight | Qt::AlignTop);
  t->setText(text);
  t->setFont(rect->axis(QCPAxis::atLeft)->labelFont());
  t->setColor(rect->axis(QCPAxis::atLeft)->labelColor());
  t->setBrush(QBrush(QColor(255, 255, 255, 200)));
  t->setVisible(false);
  return t;
}

}  // namespace

QColor MotionFigure::colour(int set) {
  static const QColor colours[] = {QColor(31, 119, 180), QColor(214, 39, 40),
                                   QColor(44, 160, 44),  QColor(148, 103, 189),
                                   QColor(255, 127, 14), QColor(140, 86, 75)};
  return colours[set % 6];
}

MotionFigure::MotionFigure(QCustomPlot* plot) : CrankFigure(plot) {
  // A resized widget (a dock made lower or higher) lays the rows out again: refit the labels.
  QObject::connect(plot_, &QCustomPlot::afterReplot, plot_, [this] {
    if (fitLabels()) plot_->replot(QCustomPlot::rpQueuedReplot);
  });
}

void MotionFigure::clear() {
  clearPlot();
  plot_->plotLayout()->clear();
  for (QCPMarginGroup* g : groups_) delete g;
  groups_.clear();
  rects_.clear();
  rowOrders_.clear();
  labels_.clear();
  corners_.clear();
  slots_.clear();
  key_.clear();
  columns_ = 0;
  legend_ = nullptr;
}

bool MotionFigure::fitLabels() {
  auto fits = [this](size_t i, const QString& l) {
    const QFontMetrics fm(rects_[i]->axis(QCPAxis::atLeft)->labelFont());
    return fm.horizontalAdvance(l) + 8 <= rects_[i]->outerRect().height();
  };
  const size_t n = std::min(rects_.size(), labels_.size());
  // In the corners all or none: a figure reads one way.
  bool corners = false;
  for (size_t i = 0; i < n; ++i) corners = corners || !fits(i, labels_[i].second);
  bool changed = false;
  for (size_t i = 0; i < n; ++i) {
    QCPAxis* y = rects_[i]->axis(QCPAxis::atLeft);
    const QString& want = corners                     ? QString()
                          : fits(i, labels_[i].first) ? labels_[i].first
                                                      : labels_[i].second;
    if (y->label() != want) {
      y->setLabel(want);
      changed = true;
    }
    if (corners_[i]->visible() != corners) {
      corners_[i]->setVisible(corners);
      changed = true;
    }
    // About one value tick per 30 pixels of height, so that low plots do not crowd them.
    const int ticks = std::clamp(rects_[i]->height() / 30, 2, 6);
    if (y->ticker()->tickCount() != ticks) {
      y->ticker()->setTickCount(ticks);
      changed = true;
    }
  }
  return changed;
}

QCPItemText* MotionFigure::cornerLabel(int row, int column) const {
  return corners_.at(static_cast<size_t>(row * columns_ + column));
}

QCPAxisRect* MotionFigure::axisRect(int row, int column) const {
  return rects_.at(static_cast<size_t>(row * columns_ + column));
}

namespace {

// Everything of the curve sets and options that decides the figure's layout (not its values):
// equal keys, the same axes, graphs and notes in the same places.
QString layoutKey(const std::vector<const CurveSet*>& sets, const MotionFigure::Options& opt) {
  QStringList k;
  k << QString::number(int(opt.layout)) << QString::number(opt.extremes)
    << QString::number(opt.cursor) << QString::number(sets.size());
  k << QString::number(int(opt.units.velocity)) << QString::number(int(opt.units.acceleration));
  for (const CurveSet* s : sets) {
    const CurveRequest& r = s->request();
    k << s->title() << s->crankLabel() << r.target << QString::number(r.revs)
      << QString::number(int(r.component)) << QString::number(r.directionDeg)
      << QString::number(r.elevationDeg) << r.other << QString::number(r.body)
      << QString::number(s->periodic()) << QString::number(s->empty());
    for (int o = 0; o < kOrders; ++o) {
      k << QString::number(r.orders[o]);
      if (!r.orders[o]) continue;
      const Curve& c = s->curve(static_cast<Order>(o));
      k << QString::fromStdString(c.status.message) << QString::number(c.values.empty())
        << QString::number(s->extremes(static_cast<Order>(o)).status.ok());
    }
  }
  return k.join(QChar(0x1f));
}

}  // namespace

namespace {

// The sets drawn in a column: all of them overlaid, else the column's own.
std::vector<int> setsInColumn(size_t count, bool side, int column) {
  std::vector<int> v;
  for (int i = 0; i < static_cast<int>(count); ++i)
    if (!side || i == column) v.push_back(i);
  return v;
}

// A curve's values in the units shown, taken into the range of their row.
QVector<double> scaled(const std::vector<double>& values, double scale,
                       MotionFigure::ValueRange& range) {
  QVector<double> out;
  out.reserve(static_cast<qsizetype>(values.size()));
  for (double v : values) {
    out.push_back(v * scale);
    range.lo = std::min(range.lo, out.back());
    range.hi = std::max(range.hi, out.back());
  }
  return out;
}

// A curve's maximum and minimum marked on every turn plotted where the motion repeats (a flat
// curve's have no angle: none).
void markExtremes(QCPGraph* marks, const CurveSet& set, Order o, int revs, double scale) {
  const int turns = set.periodic() ? revs : 1;
  for (const Extreme* e : {&set.extremes(o).max, &set.extremes(o).min})
    if (std::isfinite(e->crankDeg))
      for (int t = 0; t < turns; ++t) marks->addData(e->crankDeg + 360.0 * t, e->value * scale);
}

}  // namespace

bool MotionFigure::refresh(const std::vector<const CurveSet*>& sets, const Options& opt) {
  if (slots_.empty() || rects_.empty() || layoutKey(sets, opt) != key_) return false;
  const CurveRequest& req = sets[0]->request();
  std::vector<ValueRange> ranges(rows());
  for (const GraphSlot& slot : slots_) {
    const CurveSet& set = *sets[slot.set];
    const Curve& curve = set.curve(slot.order);
    const double scale = opt.units.scale(slot.order, req.body);
    const int row = static_cast<int>(std::find(rowOrders_.begin(), rowOrders_.end(), slot.order) -
                                     rowOrders_.begin());
    QVector<double> keys(curve.crankDeg.begin(), curve.crankDeg.end());
    slot.curve->setData(keys, scaled(curve.values, scale, ranges[row]), true);
    if (slot.marks) {
      slot.marks->data()->clear();
      markExtremes(slot.marks, set, slot.order, req.revs, scale);
    }
  }
  for (int r = 0; r < rows(); ++r) setValueRange(r, ranges[r]);
  placeCursorDots();
  plot_->replot();
  return true;
}

void MotionFigure::build(const std::vector<const CurveSet*>& sets, const Options& opt) {
  clear();
  key_ = sets.empty() ? QString() : layoutKey(sets, opt);
  if (sets.empty()) {
    plot_->replot();
    return;
  }
  const CurveRequest& req = sets[0]->request();
  for (int o = 0; o < kOrders; ++o)
    if (req.orders[o]) rowOrders_.push_back(static_cast<Order>(o));
  columns_ = opt.layout == Layout::SideBySide ? static_cast<int>(sets.size()) : 1;
  xMax_ = 360.0 * req.revs;
  plot_->plotLayout()->setRowSpacing(0);
  const int firstRow = addTitles(sets, opt.layout == Layout::SideBySide);
  addPlots(sets, opt, firstRow);
  addLegendEntries();
  cursorLayer()->setVisible(opt.cursor);
  setCursor(cursor());
  plot_->replot();
  // The rows' heights are known once laid out: labels that do not fit are shortened.
  if (fitLabels()) plot_->replot();
}

int MotionFigure::addTitles(const std::vector<const CurveSet*>& sets, bool side) {
  // Row 0: titles; row 1: why curves stop early, if any do; then the plots; last row: the
  // crank angle's label.
  int firstRow = 1;
  std::vector<QCPTextElement*> footer;
  for (int c = 0; c < columns_; ++c) {
    addTitle(sets, c, side);
    auto* foot = new QCPTextElement(plot_, sets[c]->crankLabel(), plot_->font());
    foot->setMargins(QMargins(2, 0, 2, 6));
    if (addStatusNote(sets, c, side)) firstRow = 2;
    footer.push_back(foot);
  }
  for (int c = 0; c < columns_; ++c)
    plot_->plotLayout()->addElement(firstRow + rows(), c, footer[c]);
  return firstRow;
}

void MotionFigure::addTitle(const std::vector<const CurveSet*>& sets, int column, bool side) {
  QFont titleFont = plot_->font();
  titleFont.setBold(true);
  titleFont.setPointSizeF(plot_->font().pointSizeF() + 1);
  const QString target = sets[0]->request().target;
  const QString title =
      side || sets.size() == 1 ? QString("%1: %2").arg(sets[column]->title(), target) : target;
  auto* head = new QCPTextElement(plot_, title, titleFont);
  head->setMargins(QMargins(2, 4, 2, 2));
  QCPLayoutGrid* layout = plot_->plotLayout();
  if (side || sets.size() == 1) {
    layout->addElement(0, column, head);
    return;
  }
  // Overlaid mechanisms: their names in a row beside the title, off the curves.
  auto* legend = new QCPLegend;
  legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
  legend->setBorderPen(Qt::NoPen);
  legend->setBrush(Qt::NoBrush);
  auto* top = new QCPLayoutGrid;
  layout->addElement(0, column, top);
  top->addElement(0, 0, head);
  top->addElement(0, 1, legend);
  legend->setLayer("legend");
  legend_ = legend;
}

bool MotionFigure::addStatusNote(const std::vector<const CurveSet*>& sets, int column, bool side) {
  const QFont base = plot_->font();
  // Lines as long as the column is wide (at the size the figure is laid out for).
  const int chars = std::max(
      40, plot_->width() / columns_ / std::max(1, QFontMetrics(base).averageCharWidth()) - 4);
  QStringList notes;
  for (int i : setsInColumn(sets.size(), side, column))
    if (!sets[i]->status().ok()) notes << statusNote(*sets[i], !side && sets.size() > 1, chars);
  if (notes.isEmpty()) return false;
  auto* note = new QCPTextElement(plot_, notes.join('\n'), base);
  note->setTextColor(QColor(150, 20, 20));
  plot_->plotLayout()->addElement(1, column, note);
  return true;
}

void MotionFigure::addPlots(const std::vector<const CurveSet*>& sets, const Options& opt,
                            int firstRow) {
  // Plots in a row share their top and bottom margins, in a column their left and right ones.
  groups_.push_back(new QCPMarginGroup(plot_));
  for (int c = 0; c < columns_; ++c) groups_.push_back(new QCPMarginGroup(plot_));
  const CurveRequest& req = sets[0]->request();
  const bool side = opt.layout == Layout::SideBySide;
  for (int r = 0; r < rows(); ++r) {
    ValueRange range;
    for (int c = 0; c < columns_; ++c) {
      QCPAxisRect* rect = addAxisRect(req, opt.units, r, c, firstRow, sets[0]->frame());
      int notes = 0;
      for (int i : setsInColumn(sets.size(), side, c)) {
        const Curve& curve = sets[i]->curve(rowOrders_[r]);
        // A set with samples but not this order's curve: why not, on the plot.
        if (!sets[i]->empty() && !curve.status.ok())
          addNote(plot_, rect, QString::fromStdString(curve.status.message), notes++);
        else if (!curve.values.empty())
          addCurve(*sets[i], i, rowOrders_[r], rect, req, opt, range);
      }
      addCursorLine(rect);
    }
    setValueRange(r, range);
  }
}

QCPAxisRect* MotionFigure::addAxisRect(const CurveRequest& req, const PlotUnits& units, int row,
                                       int column, int firstRow, const QString& frame) {
  auto* rect = new QCPAxisRect(plot_);
  plot_->plotLayout()->addElement(firstRow + row, column, rect);
  rects_.push_back(rect);
  rect->setMarginGroup(QCP::msTop | QCP::msBottom, groups_[0]);
  rect->setMarginGroup(QCP::msLeft | QCP::msRight, groups_[1 + column]);
  // The crank angle's label is under the bottom row, across the column (addTitles).
  // No room kept beyond the axes' own (QCPAxisRect keeps 15 px a side): the rows stay tall.
  rect->setMinimumMargins(QMargins());
  QCPAxis* x = rect->axis(QCPAxis::atBottom);
  setCrankAxis(x, xMax_, QString());
  // All rows keep room for tick labels (the margin group), so every plot is as tall;
  // only the bottom row writes them.
  x->setTickLabels(row + 1 == rows());
  const Order o = rowOrders_[row];
  labels_.emplace_back(axisLabel(req.body, req.name(), o, units),
                       shortAxisLabel(req.body, req.name(), o, units));
  // In a machine in space x and y are of a plane, not of the world: the label says which.
  if (!frame.isEmpty() && !req.body && req.component != Quantity::Component::Magnitude) {
    labels_.back().first += QStringLiteral(", %1").arg(frame);
    labels_.back().second += QStringLiteral(" (%1)").arg(frame);
  }
  rect->axis(QCPAxis::atLeft)->setLabel(labels_.back().first);
  corners_.push_back(addCornerLabel(plot_, rect, labels_.back().second));
  return rect;
}

void MotionFigure::addCurve(const CurveSet& set, int index, Order o, QCPAxisRect* rect,
                            const CurveRequest& main, const Options& opt, ValueRange& range) {
  const Curve& curve = set.curve(o);
  const double scale = opt.units.scale(o, main.body);
  QCPAxis* x = rect->axis(QCPAxis::atBottom);
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  QVector<double> keys(curve.crankDeg.begin(), curve.crankDeg.end());
  QCPGraph* g = plot_->addGraph(x, y);
  g->setData(keys, scaled(curve.values, scale, range), true);
  slots_.push_back(GraphSlot{g, nullptr, index, o});
  g->setPen(QPen(colour(index), 1.5));
  // Adaptive sampling draws dense data as one min-max bar per pixel column, which makes
  // steep parts look bold: only for curves far denser than any figure's pixels.
  g->setAdaptiveSampling(keys.size() > 20000);
  g->setName(set.title());
  if (opt.extremes && set.extremes(o).status.ok()) {
    QCPGraph* marks = plot_->addGraph(x, y);
    slots_.back().marks = marks;
    marks->setLineStyle(QCPGraph::lsNone);
    marks->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colour(index), 7));
    markExtremes(marks, set, o, main.revs, scale);
  }
  addCursorDot(g);
}

void MotionFigure::setValueRange(int row, ValueRange range) {
  double lo = range.lo, hi = range.hi;
  if (!(lo <= hi)) lo = -1, hi = 1;
  const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(1.0, std::abs(hi)) * 0.1;
  for (int c = 0; c < columns_; ++c)
    axisRect(row, c)->axis(QCPAxis::atLeft)->setRange(lo - pad, hi + pad);
}

void MotionFigure::addLegendEntries() {
  if (!legend_ || rows() == 0) return;
  // The top plot's curves, not their marks.
  for (int i = 0; i < plot_->graphCount(); ++i) {
    QCPGraph* g = plot_->graph(i);
    if (g->keyAxis() == axisRect(0, 0)->axis(QCPAxis::atBottom) &&
        g->lineStyle() != QCPGraph::lsNone)
      g->addToLegend(legend_);
  }
}

QPointF MotionFigure::pixelAt(int row, int column, double deg, double value) const {
  QCPAxisRect* r = axisRect(row, column);
  return {r->axis(QCPAxis::atBottom)->coordToPixel(deg),
          r->axis(QCPAxis::atLeft)->coordToPixel(value)};
}

}  // namespace linkage::ui
