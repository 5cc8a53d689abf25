#include "cycle/cycle_figure.h"

#include <algorithm>
#include <cmath>

#include "cycle/clearance_text.h"
#include "figures/qcp.h"

namespace linkage::ui {

namespace {

constexpr double kRowPitch = 1.4;  // a row's height: the curve's 1, and the gap

QColor rowColour(int i) {
  static const QColor c[] = {QColor(31, 119, 180), QColor(44, 160, 44),  QColor(148, 103, 189),
                             QColor(255, 127, 14), QColor(23, 190, 207), QColor(140, 86, 75)};
  return c[i % 6];
}

const QColor kConflict(214, 39, 40);

// Shades [from, to] (wrapping past 360 drawn as two pieces) between heights lo and hi.
void shade(QCustomPlot& p, const AngleInterval& i, double lo, double hi, QColor fill) {
  auto rect = [&](double a, double b) {
    auto* r = new QCPItemRect(&p);
    r->topLeft->setCoords(a, hi);
    r->bottomRight->setCoords(b, lo);
    r->setPen(Qt::NoPen);
    r->setBrush(fill);
    r->setLayer("background");
  };
  rect(i.fromDeg, std::min(i.toDeg, 360.0));
  if (i.toDeg > 360) rect(0, i.toDeg - 360);
}

QCPItemText* label(QCustomPlot& p, double x, double y, const QString& text, QColor colour) {
  auto* t = new QCPItemText(&p);
  t->position->setCoords(x, y);
  t->setText(text);
  t->setColor(colour);
  t->setFont(QFont(p.font().family(), 8));
  t->setClipToAxisRect(true);
  return t;
}

// A label centred at crank angle x, moved in from either end of the cycle to be read whole.
QCPItemText* labelAt(QCustomPlot& p, double x, double y, const QString& text, QColor colour,
                     Qt::Alignment vertical) {
  QCPItemText* t = label(p, x, y, text, colour);
  if (x < 25) {
    t->position->setCoords(1, y);
    t->setPositionAlignment(Qt::AlignLeft | vertical);
  } else if (x > 335) {
    t->position->setCoords(359, y);
    t->setPositionAlignment(Qt::AlignRight | vertical);
  } else {
    t->setPositionAlignment(Qt::AlignHCenter | vertical);
  }
  return t;
}

// The middle of an interval's longer piece (a wrapping one is drawn in two).
double middleOf(const AngleInterval& i) {
  if (i.toDeg <= 360) return 0.5 * (i.fromDeg + i.toDeg);
  return 360 - i.fromDeg >= i.toDeg - 360 ? 0.5 * (i.fromDeg + 360) : 0.5 * (i.toDeg - 360);
}

QString mm(double v) {
  return QString::number(v, 'g', 4) + QStringLiteral(" mm");
}

}  // namespace

CycleFigure::CycleFigure(QCustomPlot* plot) : CrankFigure(plot) {}

double CycleFigure::base(int row) const {
  return kRowPitch * static_cast<double>(rows_ - 1 - row);
}

int CycleFigure::heightFor(int rows) {
  return 90 + 70 * std::max(rows, 1);
}

int CycleFigure::leastHeightFor(int rows) {
  return 70 + 48 * std::max(rows, 1);
}

void CycleFigure::clear() {
  clearPlot();
  // The title's row, when there is one above the axes.
  if (plot_->plotLayout()->rowCount() > 1) {
    plot_->plotLayout()->removeAt(0);
    plot_->plotLayout()->simplify();
  }
  labels_.clear();
  rows_ = 0;
}

void CycleFigure::build(const CycleDiagram& d, const std::vector<CycleWindow>& windows,
                        const std::vector<CycleClearanceRow>& clearances, const QString& title,
                        const QString& crankLabel) {
  clear();
  rows_ = static_cast<int>(d.rows.size() + clearances.size());
  drawRows(d);
  drawWindows(d, windows);
  for (size_t c = 0; c < clearances.size(); ++c)
    drawClearance(clearances[c], static_cast<int>(d.rows.size() + c));
  auto ticks = QSharedPointer<QCPAxisTickerText>::create();
  for (int r = 0; r < rows_; ++r) ticks->addTick(base(r) + 0.5, labels_[r]);
  plot_->yAxis->setTicker(ticks);
  plot_->yAxis->setRange(-0.3, kRowPitch * rows_ - 0.2);
  // Ticks every 30 degrees: the diagram is as wide as the dock, the angles read off it.
  setCrankAxis(plot_->xAxis, 360, crankLabel, 12);
  if (!title.isEmpty()) {
    plot_->plotLayout()->insertRow(0);
    plot_->plotLayout()->addElement(0, 0, new QCPTextElement(plot_, title));
  }
  addCursorLine(plot_->axisRect());
  setCursor(cursor());
  plot_->replot();
}

void CycleFigure::drawRows(const CycleDiagram& d) {
  for (size_t r = 0; r < d.rows.size(); ++r) {
    const CycleRow& row = d.rows[r];
    const double b = base(static_cast<int>(r));
    QVector<double> x, y;
    for (size_t i = 0; i < row.value.size(); ++i) {
      x << row.crankDeg[i];
      y << b + row.normalised[i];
    }
    QCPGraph* g = plot_->addGraph();
    g->setData(x, y, true);
    g->setPen(QPen(rowColour(static_cast<int>(r)), 1.5));
    QCPGraph* dots = plot_->addGraph();
    dots->setLineStyle(QCPGraph::lsNone);
    dots->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, Qt::black, 5));
    const double span = row.max > row.min ? row.max - row.min : 1;
    for (const LocalExtreme& e : row.extremes)
      dots->addData(e.crankDeg, b + (e.value - row.min) / span);
    for (const AngleInterval& w : row.dwells) shade(*plot_, w, b, b + 1, QColor(0, 0, 0, 25));
    labels_.push_back(QString::fromStdString(row.output.name) + "\n" +
                      QString::number(row.max - row.min, 'g', 4) +
                      (row.output.measure.body ? QStringLiteral("°") : QStringLiteral(" mm")));
  }
}

void CycleFigure::drawWindows(const CycleDiagram& d, const std::vector<CycleWindow>& ws) {
  // Each window of a row names itself a line below the one before it on that row: two windows
  // of one output overlap (the needle below the plate, and in the hook's zone), and their
  // names, both at the row's top, were printed over each other.
  std::vector<QCPItemText*> lastOnRow(d.rows.size(), nullptr);
  for (size_t w = 0; w < ws.size() && w < d.windows.size(); ++w) {
    const auto row = std::find_if(d.rows.begin(), d.rows.end(), [&](const CycleRow& r) {
      return r.output.name == ws[w].output.name;
    });
    if (row == d.rows.end()) continue;
    const int r = static_cast<int>(row - d.rows.begin());
    const double b = base(r);
    QColor fill = rowColour(r);
    fill.setAlpha(50);
    QCPItemText* first = nullptr;
    for (const AngleInterval& i : d.windows[w].intervals) {
      shade(*plot_, i, b - 0.15, b + 1.15, fill);
      QCPItemText* t = labelAt(*plot_, middleOf(i), b + 1.13, QString::fromStdString(ws[w].name),
                               Qt::black, Qt::AlignTop);
      if (QCPItemText* above = lastOnRow[r]) {
        // Its top a pixel under the bottom of the name above (in pixels, whatever the zoom).
        t->position->setTypeY(QCPItemPosition::ptAbsolute);
        t->position->setParentAnchorY(above->bottom);
        t->position->setCoords(t->position->coords().x(), 1);
      }
      if (!first) first = t;
    }
    if (first) lastOnRow[r] = first;
  }
  const double top = kRowPitch * rows_;
  for (const Conflict& c : d.conflicts)
    for (const AngleInterval& i : c.overlaps) {
      QColor fill = kConflict;
      fill.setAlpha(60);
      shade(*plot_, i, -0.3, top - 0.2, fill);
      // Under the rows, where no window's name is.
      labelAt(*plot_, middleOf(i), -0.28, QString::fromStdString(c.first + "+" + c.second),
              kConflict.darker(130), Qt::AlignBottom);
    }
}

void CycleFigure::drawClearance(const CycleClearanceRow& c, int row) {
  const Clearance& k = c.clearance;
  const double b = base(row);
  double top = 0;
  for (double v : k.distance) top = std::max(top, v);
  if (c.minMm) top = std::max(top, 1.25 * *c.minMm);
  if (!(top > 0)) top = 1;
  QVector<double> x, y, under;
  for (size_t i = 0; i < k.distance.size(); ++i) {
    x << k.crankDeg[i];
    y << b + k.distance[i] / top;
    under << (c.minMm && k.distance[i] < *c.minMm ? y.back() : qQNaN());
  }
  QCPGraph* g = plot_->addGraph();
  g->setData(x, y, true);
  g->setPen(QPen(QColor(60, 60, 60), 1.5));
  QCPGraph* red = plot_->addGraph();
  red->setData(x, under, true);
  red->setPen(QPen(kConflict, 2.5));
  const bool tooClose = c.minMm && k.closest.distance < *c.minMm;
  if (c.minMm) {
    auto* line = new QCPItemLine(plot_);
    line->start->setCoords(0, b + *c.minMm / top);
    line->end->setCoords(360, b + *c.minMm / top);
    line->setPen(QPen(kConflict, 1, Qt::DashLine));
    label(*plot_, 359, b + *c.minMm / top + 0.04, QStringLiteral("min ") + mm(*c.minMm), kConflict)
        ->setPositionAlignment(Qt::AlignRight | Qt::AlignBottom);
  }
  QCPGraph* dot = plot_->addGraph();
  dot->setLineStyle(QCPGraph::lsNone);
  dot->setScatterStyle(
      QCPScatterStyle(QCPScatterStyle::ssDisc, tooClose ? kConflict : QColor(Qt::black), 6));
  dot->addData(k.closest.crankDeg, b + k.closest.distance / top);
  // Above the dot: the closest approach is the row's lowest point.
  // What it is: the closest approach, where the two meet, or where the point is on the part.
  QCPItemText* t = label(*plot_, k.closest.crankDeg, b + k.closest.distance / top + 0.06,
                         clearanceNote(k), tooClose ? kConflict : QColor(Qt::black));
  // Kept inside the plot at either end of the cycle.
  t->setPositionAlignment(k.closest.crankDeg < 60    ? Qt::AlignLeft | Qt::AlignBottom
                          : k.closest.crankDeg > 300 ? Qt::AlignRight | Qt::AlignBottom
                                                     : Qt::AlignHCenter | Qt::AlignBottom);
  labels_.push_back(c.label + "\n" + QStringLiteral("0 to ") + mm(top));
}

QString CycleFigure::rowLabel(int row) const {
  return row >= 0 && row < static_cast<int>(labels_.size()) ? labels_[row] : QString();
}

QPointF CycleFigure::pixelAt(double crankDeg, double rowHeight, int row) const {
  return {plot_->xAxis->coordToPixel(crankDeg), plot_->yAxis->coordToPixel(base(row) + rowHeight)};
}

}  // namespace linkage::ui
