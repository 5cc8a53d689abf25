// What every figure against the crank angle shares (the plots' motion curves, the forces', the
// cycle diagram): the crank-angle axis (setCrankAxis, which the balance dialog's figure and a
// study's family against the crank use too); the cursor at the pose, a dashed line across each
// crank-angle plot and a dot on each curve, on a layer of its own with its own paint buffer, so
// that moving it repaints that layer only; the crank angle a press or drag on a plot asks for;
// and the figure written to a file (figures/figure_export.h) without the cursor.
#pragma once

#include <QPointF>
#include <QSize>
#include <QString>
#include <vector>

class QCustomPlot;
class QCPAxis;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPItemTracer;
class QCPLayer;

namespace linkage::ui {

// The crank-angle axis from 0 to `xMax` degrees (360 a turn), ticked at a divisor or multiple of
// a turn with at most `intervals` intervals (the narrower the plot, the fewer), labelled `label`
// (crankAxisLabel, figures/units.h; empty: no label), with room at its right end for half its
// last tick label, which is centred there.
void setCrankAxis(QCPAxis* x, double xMax, const QString& label, int intervals = 8);

// A crank angle `deg` (any number of turns) within [0, period): where the cursor is drawn.
double crankInPeriod(double deg, double period);
// Angle `deg` of [0, period] in the period the crank `current` is in: asked for by a drag on a
// plot, so that following it moves the mechanism the short way.
double crankNear(double deg, double current, double period);

class CrankFigure {
 public:
  explicit CrankFigure(QCustomPlot* plot);
  virtual ~CrankFigure() = default;
  CrankFigure(const CrankFigure&) = delete;
  CrankFigure& operator=(const CrankFigure&) = delete;

  QCustomPlot* plot() const { return plot_; }

  // Moves the cursor to a crank angle within the plotted range and repaints the cursor layer
  // only (the curves' layers keep their buffers). A curve's dot is hidden where the curve is
  // not (it stops early).
  void setCursor(double deg);
  double cursor() const { return cursorDeg_; }
  void setCursorVisible(bool on);

  // The crank angle under a pixel of one of the crank-angle plots (inside its axes), or NaN
  // elsewhere; `rect` receives the plot's index (in the order their cursor lines were added)
  // or -1.
  double crankAt(const QPointF& pixel, int* rect = nullptr) const;
  // The crank angle at a pixel column of crank-angle plot `rect`, inside its axes or not.
  double crankAtX(int rect, double pixelX) const;
  // The crank angle a press (`press`) or a drag with the button held asks for: the plot
  // pressed on gives the angle even outside its axes. NaN when the press was not on a plot.
  double crankDragged(const QPointF& pixel, bool press);
  bool dragging() const { return dragRect_ >= 0; }
  void endDrag() { dragRect_ = -1; }

  // Writes the figure as drawn, without the cursor: PNG, PDF or SVG by the path's suffix, at
  // `size` (exportPlot, figures/figure_export.h).
  bool exportFigure(const QString& path, QSize size, QString* error);

 protected:
  // A dashed line across `rect` at the cursor: the rect is a crank-angle plot (crankAt).
  void addCursorLine(QCPAxisRect* rect);
  // A dot on `graph` at the cursor, in its pen's colour.
  void addCursorDot(QCPGraph* graph);
  // The dots placed on their curves' new data (drawing places them too; a test reads them).
  void placeCursorDots();
  // Removes the plot's items and plottables, the cursor's with them (a figure built anew).
  void clearPlot();
  // The cursor moved: what a figure draws of it besides the lines and dots follows it.
  virtual void cursorMoved(double /*deg*/) {}
  QCPLayer* cursorLayer() const { return cursorLayer_; }

  QCustomPlot* plot_;

 private:
  QCPLayer* cursorLayer_;
  std::vector<QCPAxisRect*> crankRects_;
  std::vector<QCPItemStraightLine*> lines_;
  std::vector<QCPItemTracer*> dots_;
  double cursorDeg_ = 0;
  int dragRect_ = -1;
};

}  // namespace linkage::ui
