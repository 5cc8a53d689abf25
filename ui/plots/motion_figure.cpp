#include "plots/motion_figure.h"

#include <algorithm>
#include <cmath>

#include "plots/qcp.h"

namespace linkage::ui {

namespace {

// Crank-angle ticks: a divisor or multiple of a turn, at most 8 intervals over the range.
double tickStep(double range) {
  for (double s : {15.0, 30.0, 45.0, 90.0, 180.0, 360.0, 720.0, 1440.0})
    if (range / s <= 8 + 1e-9) return s;
  return 360.0 * std::ceil(range / 8 / 360);
}

// Words broken into lines of at most `width` characters.
QString wrapped(const QString& text, int width) {
  QStringList lines;
  QString line;
  for (const QString& word : text.split(' ', Qt::SkipEmptyParts)) {
    if (!line.isEmpty() && line.size() + 1 + word.size() > width) {
      lines << line;
      line.clear();
    }
    line += (line.isEmpty() ? "" : " ") + word;
  }
  if (!line.isEmpty()) lines << line;
  return lines.join('\n');
}

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

}  // namespace

QColor MotionFigure::colour(int set) {
  static const QColor colours[] = {QColor(31, 119, 180), QColor(214, 39, 40),
                                   QColor(44, 160, 44),  QColor(148, 103, 189),
                                   QColor(255, 127, 14), QColor(140, 86, 75)};
  return colours[set % 6];
}

MotionFigure::MotionFigure(QCustomPlot* plot) : plot_(plot) {
  // A legend added to the layout makes itself the plot's legend, which would then collect
  // every graph (markers included): the figure adds the curves itself.
  plot_->setAutoAddPlottableToLegend(false);
  // Curves as one polyline each (not segment by segment): a replot costs a fraction, which a
  // drag that reshapes the design and redraws the curves 30 times a second needs.
  plot_->setPlottingHint(QCP::phFastPolylines, true);
  plot_->addLayer("cursor", plot_->layer("main"), QCustomPlot::limAbove);
  cursorLayer_ = plot_->layer("cursor");
  // Its own paint buffer: replotting it leaves the curves' buffer as it is.
  cursorLayer_->setMode(QCPLayer::lmBuffered);
  // A resized widget (a dock made lower or higher) lays the rows out again: refit the labels.
  QObject::connect(plot_, &QCustomPlot::afterReplot, plot_, [this] {
    if (fitLabels()) plot_->replot(QCustomPlot::rpQueuedReplot);
  });
}

void MotionFigure::clear() {
  plot_->clearItems();
  plot_->clearPlottables();
  plot_->plotLayout()->clear();
  for (QCPMarginGroup* g : groups_) delete g;
  groups_.clear();
  rects_.clear();
  lines_.clear();
  tracers_.clear();
  rowOrders_.clear();
  labels_.clear();
  slots_.clear();
  key_.clear();
  columns_ = 0;
  legend_ = nullptr;
}

bool MotionFigure::fitLabels() {
  bool changed = false;
  for (size_t i = 0; i < rects_.size() && i < labels_.size(); ++i) {
    QCPAxis* y = rects_[i]->axis(QCPAxis::atLeft);
    const QFontMetrics fm(y->labelFont());
    const bool fits = fm.horizontalAdvance(labels_[i].first) + 8 <= rects_[i]->outerRect().height();
    const QString& want = fits ? labels_[i].first : labels_[i].second;
    if (y->label() != want) {
      y->setLabel(want);
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
      << QString::number(r.body) << QString::number(s->periodic()) << QString::number(s->empty());
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

bool MotionFigure::refresh(const std::vector<const CurveSet*>& sets, const Options& opt) {
  if (slots_.empty() || rects_.empty() || layoutKey(sets, opt) != key_) return false;
  const CurveRequest& req = sets[0]->request();
  std::vector<double> lo(rows(), INFINITY), hi(rows(), -INFINITY);
  for (const GraphSlot& slot : slots_) {
    const CurveSet& set = *sets[slot.set];
    const Curve& curve = set.curve(slot.order);
    const double scale = opt.units.scale(slot.order, req.body);
    const int row = static_cast<int>(std::find(rowOrders_.begin(), rowOrders_.end(), slot.order) -
                                     rowOrders_.begin());
    QVector<double> keys(curve.crankDeg.begin(), curve.crankDeg.end()), values;
    values.reserve(keys.size());
    for (double v : curve.values) {
      values.push_back(v * scale);
      lo[row] = std::min(lo[row], values.back());
      hi[row] = std::max(hi[row], values.back());
    }
    slot.curve->setData(keys, values, true);
    if (slot.marks) {
      slot.marks->data()->clear();
      const int turns = set.periodic() ? req.revs : 1;
      for (const Extreme* e : {&set.extremes(slot.order).max, &set.extremes(slot.order).min})
        for (int t = 0; t < turns; ++t)
          slot.marks->addData(e->crankDeg + 360.0 * t, e->value * scale);
    }
  }
  for (int r = 0; r < rows(); ++r) {
    double l = lo[r], h = hi[r];
    if (!(l <= h)) l = -1, h = 1;
    const double pad = h > l ? 0.06 * (h - l) : std::max(1.0, std::abs(h)) * 0.1;
    for (int c = 0; c < columns_; ++c)
      axisRect(r, c)->axis(QCPAxis::atLeft)->setRange(l - pad, h + pad);
  }
  for (QCPItemTracer* t : tracers_) t->updatePosition();
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
  const bool side = opt.layout == Layout::SideBySide;
  columns_ = side ? static_cast<int>(sets.size()) : 1;
  xMax_ = 360.0 * req.revs;
  QCPLayoutGrid* layout = plot_->plotLayout();
  layout->setRowSpacing(0);
  const QFont base = plot_->font();
  QFont titleFont = base;
  titleFont.setBold(true);
  titleFont.setPointSizeF(base.pointSizeF() + 1);

  // Row 0: titles; row 1: why curves stop early, if any do; then the plots; last row: the
  // crank angle's label.
  int firstRow = 1;
  std::vector<QCPTextElement*> footer;
  auto setsOf = [&](int column) {
    std::vector<int> v;
    for (int i = 0; i < static_cast<int>(sets.size()); ++i)
      if (!side || i == column) v.push_back(i);
    return v;
  };
  for (int c = 0; c < columns_; ++c) {
    const QString target = req.target;
    const QString title =
        side || sets.size() == 1 ? QString("%1: %2").arg(sets[c]->title(), target) : target;
    auto* head = new QCPTextElement(plot_, title, titleFont);
    auto* foot = new QCPTextElement(plot_, sets[c]->crankLabel(), base);
    head->setMargins(QMargins(2, 4, 2, 2));
    foot->setMargins(QMargins(2, 0, 2, 6));
    if (!side && sets.size() > 1) {
      // Overlaid mechanisms: their names in a row beside the title, off the curves.
      auto* legend = new QCPLegend;
      legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
      legend->setBorderPen(Qt::NoPen);
      legend->setBrush(Qt::NoBrush);
      auto* top = new QCPLayoutGrid;
      layout->addElement(0, c, top);
      top->addElement(0, 0, head);
      top->addElement(0, 1, legend);
      legend->setLayer("legend");
      legend_ = legend;
    } else {
      layout->addElement(0, c, head);
    }
    // Lines as long as the column is wide (at the size the figure is laid out for).
    const int chars = std::max(
        40, plot_->width() / columns_ / std::max(1, QFontMetrics(base).averageCharWidth()) - 4);
    QStringList notes;
    for (int i : setsOf(c))
      if (!sets[i]->status().ok()) notes << statusNote(*sets[i], !side && sets.size() > 1, chars);
    if (!notes.isEmpty()) {
      auto* note = new QCPTextElement(plot_, notes.join('\n'), base);
      note->setTextColor(QColor(150, 20, 20));
      layout->addElement(1, c, note);
      firstRow = 2;
    }
    footer.push_back(foot);
  }
  for (int c = 0; c < columns_; ++c) layout->addElement(firstRow + rows(), c, footer[c]);
  auto* rowsGroup = new QCPMarginGroup(plot_);
  groups_.push_back(rowsGroup);
  for (int c = 0; c < columns_; ++c) groups_.push_back(new QCPMarginGroup(plot_));

  auto ticker = QSharedPointer<QCPAxisTickerFixed>::create();
  ticker->setTickStep(tickStep(xMax_));
  ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
  for (int r = 0; r < rows(); ++r) {
    const Order o = rowOrders_[r];
    const double scale = opt.units.scale(o, req.body);
    double lo = INFINITY, hi = -INFINITY;
    for (int c = 0; c < columns_; ++c) {
      auto* rect = new QCPAxisRect(plot_);
      layout->addElement(firstRow + r, c, rect);
      rects_.push_back(rect);
      rect->setMarginGroup(QCP::msTop | QCP::msBottom, rowsGroup);
      rect->setMarginGroup(QCP::msLeft | QCP::msRight, groups_[1 + c]);
      QCPAxis* x = rect->axis(QCPAxis::atBottom);
      QCPAxis* y = rect->axis(QCPAxis::atLeft);
      x->setTicker(ticker);
      x->setRange(0, xMax_);
      // All rows keep room for tick labels (the margin group), so every plot is as tall;
      // only the bottom row writes them.
      x->setTickLabels(r + 1 == rows());
      // The last tick label is centred on the right edge: leave room for its half.
      rect->setMinimumMargins(QMargins(
          0, 0, QFontMetrics(x->tickLabelFont()).horizontalAdvance(QString::number(xMax_)) / 2 + 6,
          0));
      labels_.emplace_back(axisLabel(req.body, req.component, req.directionDeg, o, opt.units),
                           shortAxisLabel(req.body, req.component, req.directionDeg, o, opt.units));
      y->setLabel(labels_.back().first);
      int notes = 0;
      for (int i : setsOf(c)) {
        const CurveSet& set = *sets[i];
        const Curve& curve = set.curve(o);
        if (!set.empty() && !curve.status.ok()) {
          addNote(plot_, rect, QString::fromStdString(curve.status.message), notes++);
          continue;
        }
        if (curve.values.empty()) continue;
        QVector<double> keys(curve.crankDeg.begin(), curve.crankDeg.end()), values;
        values.reserve(keys.size());
        for (double v : curve.values) {
          values.push_back(v * scale);
          lo = std::min(lo, values.back());
          hi = std::max(hi, values.back());
        }
        QCPGraph* g = plot_->addGraph(x, y);
        g->setData(keys, values, true);
        slots_.push_back(GraphSlot{g, nullptr, i, o});
        g->setPen(QPen(colour(i), 1.5));
        // Adaptive sampling draws dense data as one min-max bar per pixel column, which makes
        // steep parts look bold: only for curves far denser than any figure's pixels.
        g->setAdaptiveSampling(keys.size() > 20000);
        g->setName(set.title());
        if (opt.extremes && set.extremes(o).status.ok()) {
          QCPGraph* marks = plot_->addGraph(x, y);
          slots_.back().marks = marks;
          marks->setLineStyle(QCPGraph::lsNone);
          marks->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colour(i), 7));
          const int turns = set.periodic() ? req.revs : 1;
          for (const Extreme* e : {&set.extremes(o).max, &set.extremes(o).min})
            for (int t = 0; t < turns; ++t)
              marks->addData(e->crankDeg + 360.0 * t, e->value * scale);
        }
        auto* tracer = new QCPItemTracer(plot_);
        tracer->setLayer(cursorLayer_);
        tracer->setGraph(g);
        tracer->setInterpolating(true);
        tracer->setStyle(QCPItemTracer::tsCircle);
        tracer->setSize(6);
        tracer->setPen(QPen(colour(i).darker(130)));
        tracer->setBrush(QBrush(Qt::white));
        tracer->setClipAxisRect(rect);
        tracers_.push_back(tracer);
      }
      auto* line = new QCPItemStraightLine(plot_);
      line->setLayer(cursorLayer_);
      line->setClipAxisRect(rect);
      line->point1->setAxes(x, y);
      line->point2->setAxes(x, y);
      line->setPen(QPen(QColor(60, 60, 60), 1, Qt::DashLine));
      lines_.push_back(line);
    }
    if (!(lo <= hi)) lo = -1, hi = 1;
    const double pad = hi > lo ? 0.06 * (hi - lo) : std::max(1.0, std::abs(hi)) * 0.1;
    for (int c = 0; c < columns_; ++c)
      axisRect(r, c)->axis(QCPAxis::atLeft)->setRange(lo - pad, hi + pad);
  }
  if (legend_) {
    for (int i = 0; i < plot_->graphCount(); ++i) {
      QCPGraph* g = plot_->graph(i);
      if (rows() > 0 && g->keyAxis() == axisRect(0, 0)->axis(QCPAxis::atBottom) &&
          g->lineStyle() != QCPGraph::lsNone)
        g->addToLegend(legend_);
    }
  }
  cursorLayer_->setVisible(opt.cursor);
  setCursor(cursorDeg_);
  plot_->replot();
  // The rows' heights are known once laid out: labels that do not fit are shortened.
  if (fitLabels()) plot_->replot();
}

void MotionFigure::setCursor(double deg) {
  cursorDeg_ = deg;
  for (QCPItemStraightLine* l : lines_) {
    l->point1->setCoords(deg, 0);
    l->point2->setCoords(deg, 1);
  }
  for (QCPItemTracer* t : tracers_) {
    t->setGraphKey(deg);
    // Outside a curve that stops early the tracer would sit at its end: hide it there.
    const QCPGraph* g = t->graph();
    const bool inside = !g->data()->isEmpty() && deg >= g->data()->constBegin()->key &&
                        deg <= (g->data()->constEnd() - 1)->key;
    t->setVisible(inside);
  }
  cursorLayer_->replot();
}

void MotionFigure::setCursorVisible(bool on) {
  cursorLayer_->setVisible(on);
  cursorLayer_->replot();
}

double MotionFigure::crankAt(const QPointF& pixel, int* rect) const {
  if (rect) *rect = -1;
  for (size_t i = 0; i < rects_.size(); ++i)
    if (rects_[i]->rect().contains(pixel.toPoint())) {
      if (rect) *rect = static_cast<int>(i);
      return crankAtX(static_cast<int>(i), pixel.x());
    }
  return NAN;
}

double MotionFigure::crankAtX(int rect, double pixelX) const {
  if (rect < 0 || rect >= static_cast<int>(rects_.size())) return NAN;
  return rects_[rect]->axis(QCPAxis::atBottom)->pixelToCoord(pixelX);
}

QPointF MotionFigure::pixelAt(int row, int column, double deg, double value) const {
  QCPAxisRect* r = axisRect(row, column);
  return {r->axis(QCPAxis::atBottom)->coordToPixel(deg),
          r->axis(QCPAxis::atLeft)->coordToPixel(value)};
}

}  // namespace linkage::ui
