// The motion curves as a figure in a QCustomPlot: one row per order shown (position, velocity,
// acceleration, jerk) sharing the crank-angle axis, one column per mechanism side by side (the
// homework's 3 x 2 figure) or all of them overlaid in one column; extremes marked; the cursor
// on every plot (figures/crank_figure.h). The plots panel and `linkage-cli plot` both draw
// with it.
#pragma once

#include <QColor>
#include <QPointF>
#include <cmath>
#include <vector>

#include "figures/crank_figure.h"
#include "figures/units.h"
#include "plots/curve_set.h"

class QCustomPlot;
class QCPAxisRect;
class QCPLegend;
class QCPItemText;
class QCPMarginGroup;

namespace linkage::ui {

class MotionFigure : public CrankFigure {
 public:
  enum class Layout { Overlay, SideBySide };
  struct Options {
    Layout layout = Layout::Overlay;
    PlotUnits units;
    bool extremes = true;  // mark each curve's maximum and minimum
    bool cursor = true;
  };

  explicit MotionFigure(QCustomPlot* plot);

  // Lays the figure out anew for these curve sets (the first is the main document's) and
  // replots. The sets must outlive the next build (the figure keeps no copy of them).
  void build(const std::vector<const CurveSet*>& sets, const Options& options);
  // New values for the figure as built (an edit of the design while dragging): the curves'
  // data, marks and value ranges replaced and one replot, without laying the figure out
  // again. False, and nothing done, when the layout would differ: build() then.
  bool refresh(const std::vector<const CurveSet*>& sets, const Options& options);

  // The pixel of a crank angle on a plot (for tests and tools).
  QPointF pixelAt(int row, int column, double deg, double value) const;

  int rows() const { return static_cast<int>(rowOrders_.size()); }
  int columns() const { return columns_; }
  Order rowOrder(int row) const { return rowOrders_[row]; }
  QCPAxisRect* axisRect(int row, int column) const;
  double xMax() const { return xMax_; }

  static QColor colour(int set);
  // Long y labels where the plots are tall enough for them, short ones where not (a low dock),
  // and where not even those fit beside the plot, the short one across its top right corner
  // (rotated labels taller than their plots ran into each other: "ay [mm/s2]vy [mm/s]");
  // true when a label changed (the caller replots).
  bool fitLabels();
  // The label written inside a plot when its axis has none (hidden otherwise; for tests).
  QCPItemText* cornerLabel(int row, int column) const;

  // The smallest and largest value of a row's curves (none yet: empty); public for the
  // helpers of motion_figure.cpp that scale the curves.
  struct ValueRange {
    double lo = INFINITY, hi = -INFINITY;
  };

 private:
  void clear();
  // The parts build() lays out, in its order: titles, notes and crank-angle labels (returns
  // the first row of plots), the plots and their curves, the legend's entries.
  int addTitles(const std::vector<const CurveSet*>& sets, bool side);
  void addTitle(const std::vector<const CurveSet*>& sets, int column, bool side);
  bool addStatusNote(const std::vector<const CurveSet*>& sets, int column, bool side);
  void addPlots(const std::vector<const CurveSet*>& sets, const Options& opt, int firstRow);
  // `frame`: the plane a point's x and y are of ("" in a planar machine), for the label.
  QCPAxisRect* addAxisRect(const CurveRequest& req, const PlotUnits& units, int row, int column,
                           int firstRow, const QString& frame);
  void addCurve(const CurveSet& set, int index, Order o, QCPAxisRect* rect,
                const CurveRequest& main, const Options& opt, ValueRange& range);
  void addLegendEntries();
  // A row's value axes over its range, padded.
  void setValueRange(int row, ValueRange range);

  std::vector<std::pair<QString, QString>> labels_;  // long and short, per axis rect
  std::vector<QCPItemText*> corners_;                // per axis rect
  struct GraphSlot {
    QCPGraph* curve;
    QCPGraph* marks;
    int set;
    Order order;
  };
  std::vector<GraphSlot> slots_;  // the graphs in the order build() made them
  QString key_;                   // the layout they were made for

  std::vector<QCPMarginGroup*> groups_;
  std::vector<Order> rowOrders_;
  int columns_ = 0;
  std::vector<QCPAxisRect*> rects_;  // row-major
  QCPLegend* legend_ = nullptr;
  double xMax_ = 360;
};

}  // namespace linkage::ui
