#include "cycle/level_lines.h"

#include <algorithm>
#include <cmath>

#include "figures/qcp.h"

namespace linkage::ui {

namespace {

// The band a window's shading covers in its row (cycle/cycle_figure.cpp): a threshold outside
// the stroke is drawn at its edge, where the window always or never holds.
constexpr double kBandLo = -0.15, kBandHi = 1.15;

QString levelText(const CycleWindow& w, bool angle) {
  const QString v = QString::number(w.level, 'f', 2);
  return (w.below ? QObject::tr("%1: below %2%3") : QObject::tr("%1: above %2%3"))
      .arg(QString::fromStdString(w.name), v, angle ? QStringLiteral("°") : QStringLiteral(" mm"));
}

}  // namespace

LevelLines::LevelLines(QCustomPlot* plot, const CycleFigure& figure)
    : plot_(plot), figure_(figure) {}

double LevelLines::coordOf(const Line& l) const {
  return figure_.rowCoord(l.row, l.height);
}

void LevelLines::draw(const CycleDiagram& d, const std::vector<CycleWindow>& windows, int current) {
  lines_.assign(windows.size(), Line{});
  for (size_t w = 0; w < windows.size(); ++w) {
    const auto row = std::find_if(d.rows.begin(), d.rows.end(), [&](const CycleRow& r) {
      return r.output.name == windows[w].output.name;
    });
    if (row == d.rows.end()) continue;
    Line& l = lines_[w];
    l.row = static_cast<int>(row - d.rows.begin());
    l.min = row->min;
    l.span = row->max > row->min ? row->max - row->min : 1;
    l.height = std::clamp((windows[w].level - l.min) / l.span, kBandLo, kBandHi);
    const double y = coordOf(l);
    const bool on = static_cast<int>(w) == current;
    auto* line = new QCPItemLine(plot_);
    line->start->setCoords(0, y);
    line->end->setCoords(360, y);
    line->setPen(on ? QPen(QColor(20, 20, 20), 1.5)
                    : QPen(QColor(60, 60, 60, 150), 1, Qt::DashLine));
    if (!on) continue;
    auto* t = new QCPItemText(plot_);
    t->position->setCoords(359, y);
    t->setPositionAlignment(Qt::AlignRight | Qt::AlignBottom);
    t->setText(levelText(windows[w], row->output.measure.body.value != 0));
    t->setFont(QFont(plot_->font().family(), 8));
    t->setBrush(QColor(255, 255, 255, 200));
    t->setPadding(QMargins(2, 0, 2, 0));
    t->setClipToAxisRect(true);
  }
}

int LevelLines::windowAt(const QPointF& pixel, double reach) const {
  if (!plot_->axisRect()->rect().contains(pixel.toPoint())) return -1;
  int best = -1;
  double nearest = reach;
  for (size_t w = 0; w < lines_.size(); ++w) {
    if (lines_[w].row < 0) continue;
    const double dy = std::abs(plot_->yAxis->coordToPixel(coordOf(lines_[w])) - pixel.y());
    if (dy <= nearest) {
      nearest = dy;
      best = static_cast<int>(w);
    }
  }
  return best;
}

double LevelLines::levelAt(int window, double pixelY) const {
  const Line& l = lines_.at(static_cast<size_t>(window));
  const double h = plot_->yAxis->pixelToCoord(pixelY) - figure_.rowCoord(l.row, 0);
  return l.min + std::clamp(h, kBandLo, kBandHi) * l.span;
}

std::optional<QPointF> LevelLines::pixelOf(int window, double crankDeg) const {
  if (window < 0 || window >= static_cast<int>(lines_.size()) || lines_[window].row < 0)
    return std::nullopt;
  return QPointF(plot_->xAxis->coordToPixel(crankDeg),
                 plot_->yAxis->coordToPixel(coordOf(lines_[window])));
}

}  // namespace linkage::ui
