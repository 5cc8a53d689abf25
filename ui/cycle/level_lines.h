// The windows' thresholds on the cycle diagram (issue 26): a level line across the row of each
// window's output (the row is that output over the cycle, normalised to its stroke), the window
// being edited drawn solid and named with its threshold, the others dashed. The Cycle dock
// grabs a line pressed within a few pixels and turns the height the drag reaches into a level
// of the output: the threshold dragged on the plot.
#pragma once

#include <QPointF>
#include <optional>
#include <vector>

#include "cycle/cycle_figure.h"

class QCustomPlot;

namespace linkage::ui {

class LevelLines {
 public:
  LevelLines(QCustomPlot* plot, const CycleFigure& figure);

  // After each build of the figure (which clears its items): a line per window whose output
  // is a row; `current` (-1: none) solid and labelled.
  void draw(const CycleDiagram& d, const std::vector<CycleWindow>& windows, int current);
  // The window whose line is within `reach` pixels of `pixel` (the current one first), or -1.
  int windowAt(const QPointF& pixel, double reach = 6) const;
  // The level of window i's output at a pixel's height, kept within its row's band (the
  // stroke and a little more, where the window's shading is drawn).
  double levelAt(int window, double pixelY) const;
  // Where window i's line is, in the plot's pixels, at a crank angle (nullopt: not drawn).
  std::optional<QPointF> pixelOf(int window, double crankDeg) const;

 private:
  struct Line {
    int row = -1;  // -1: its output is not drawn
    double min = 0, span = 1, height = 0;
  };
  double coordOf(const Line& l) const;

  QCustomPlot* plot_;
  const CycleFigure& figure_;
  std::vector<Line> lines_;
};

}  // namespace linkage::ui
