// The cycle (timing) diagram of a machine in a QCustomPlot (linkage/timing.h): a row per output
// over one machine cycle (crank angle 0 to 360 of the main shaft), normalised to its stroke,
// with its dead centres (dots) and dwells (grey); each window shaded in its output's row and
// named; the overlaps of windows that must not overlap in red across every row; under them a
// row per clearance watched (linkage/clearance.h), in mm from 0 at the row's foot, with its
// least allowed distance (a red line), the closest approach marked and named, and what is under
// the minimum drawn red. The cursor at the pose (figures/crank_figure.h).
//
// Drawn by the editor's Cycle dock and by linkage-plot (linkage-cli timing --out).
#pragma once

#include <QPointF>
#include <QString>
#include <optional>
#include <vector>

#include "figures/crank_figure.h"
#include "linkage/clearance.h"
#include "linkage/timing.h"

class QCustomPlot;

namespace linkage::ui {

struct CycleClearanceRow {
  QString label;  // "hook.K – segment needlebar.N-B" (cycle/clearance_text.h)
  Clearance clearance;
  std::optional<double> minMm;
  ClearanceWatch watch;  // what it measures (whose frames the solver's places are in)
};

class CycleFigure : public CrankFigure {
 public:
  explicit CycleFigure(QCustomPlot* plot);

  // `windows` are those the diagram was made with (each names its output's row).
  void build(const CycleDiagram& d, const std::vector<CycleWindow>& windows,
             const std::vector<CycleClearanceRow>& clearances, const QString& title,
             const QString& crankLabel);
  void clear();
  // The height in pixels the rows want (an export's or the dock's).
  static int heightFor(int rows);
  // The least height the rows are read at (their two-line labels apart, a window's name or two
  // above the curve): below it the dock scrolls.
  static int leastHeightFor(int rows);

  // For tests and tools: the rows drawn (outputs, then clearances), top first.
  int rowCount() const { return rows_; }
  QString rowLabel(int row) const;
  QPointF pixelAt(double crankDeg, double rowHeight, int row) const;
  // The plot's y coordinate of a height in a row (0 its foot, 1 its top): what is drawn over
  // the rows (cycle/level_lines.h) is placed by it.
  double rowCoord(int row, double rowHeight) const { return base(row) + rowHeight; }

 private:
  void drawRows(const CycleDiagram& d);
  void drawWindows(const CycleDiagram& d, const std::vector<CycleWindow>& windows);
  void drawClearance(const CycleClearanceRow& c, int row);
  double base(int row) const;

  std::vector<QString> labels_;
  int rows_ = 0;
};

}  // namespace linkage::ui
