// The forces panel's figure in a QCustomPlot: the driver's torque, the shaking force's fx and
// fy and a joint's reaction against the crank angle over one turn, and the polar diagram of the
// shaking force (fy against fx, equal scales); the cursor at the pose (figures/crank_figure.h:
// a line on each crank-angle plot, and the pose's point and force vector on the polar diagram).
// A machine in space: the columns of `linkage-cli dynamics` in the world's axes (the shaking
// force's fz too, a joint's force with what it bears along its plane's normal), a ball rod's
// tension, a bevel pair's couple; the polar diagram is of the world's x and y.
// Laid out as one row of four plots in a wide low dock, two by two in a squarer one, one column
// in a tall narrow one (columnsFor).
#pragma once

#include <QPointF>
#include <QSize>
#include <QString>
#include <vector>

#include "figures/crank_figure.h"
#include "linkage/force_samples.h"

class QCustomPlot;
class QCPAxisRect;
class QCPCurve;
class QCPGraph;
class QCPItemLine;
class QCPItemTracer;
class QCPLayoutGrid;

namespace linkage::ui {

class ForceFigure : public CrankFigure {
 public:
  enum Plot { Torque, Shaking, Polar, Reaction, kPlots };
  enum Curve {
    TorqueCurve,
    ShakingX,
    ShakingY,
    ReactionX,
    ReactionY,
    ReactionNorm,
    ShakingZ,        // in space
    ReactionZ,       // in space
    ReactionScalar,  // in space: a ball rod's tension or a bevel pair's couple
    kCurves
  };
  struct JointChoice {
    int index = -1;           // into the mechanism's joints; -1: none
    QString label, bodyName;  // "pin:rod.B" (the force table's name), the body it acts on
    bool undetermined = false;
    SpaceReaction shape = SpaceReaction::Force;  // what it is in space
  };

  explicit ForceFigure(QCustomPlot* plot);

  // Lays the figure out for the samples (which must outlive the next build and setCursor);
  // `stopNote`, when not empty, says why the curves end before the turn does; `sizeMm`, the
  // mechanism's size, scales what is rounding of a zero torque.
  // `crankLabel` and `crankBrief` (crankAxisLabel, briefCrankAxisLabel): the crank-angle axes'
  // label, the brief one where the plot is too narrow for the other.
  void build(const ForceSamples& s, const QString& crankLabel, const QString& crankBrief,
             const JointChoice& joint, const QString& stopNote, double sizeMm);
  // Nothing drawn (the panel shows a sentence instead).
  void clear();
  // Plots across a figure of `area` pixels: 4 in a row, 2 by 2 or 4 in a column, whichever
  // gives each plot the largest least side (a short wide dock: a row; a square one: 2 by 2),
  // so that the curves get a height to read and the polar diagram is drawn near square.
  static int columnsFor(QSize area);
  int columns() const { return columns_; }
  // The least height the figure needs with `columns` plots across (rows of plots of
  // kLeastPlotHeight): below it, the panel scrolls rather than squash the plots flat.
  static int leastHeightFor(int columns);
  static constexpr int kLeastPlotHeight = 170;  // a title, 100 px of curves, the axes' text
  // Lay the next builds out for this size rather than the plot's (an export); empty: the plot's.
  void setLayoutSize(QSize size) { layoutSize_ = size; }

  // For tests and tools.
  QCPAxisRect* rect(Plot p) const { return rects_[p]; }
  QCPGraph* curve(Curve c) const { return curves_[c]; }
  QCPCurve* polar() const { return polar_; }
  QPointF pixelAt(Plot p, double x, double y) const;
  // The pose's point on the polar diagram (N): the shaking force interpolated at the cursor.
  QPointF polarMark() const;
  // Replots with the polar diagram's scales made equal (the rects are laid out first).
  void replot();

 private:
  void layOut(const QString& crankLabel, const JointChoice& joint, const QString& stopNote,
              bool space);
  void addShaking(const ForceSamples& s);
  void addReactionInSpace(const ForceSamples& s, const JointChoice& joint);
  void addReaction(const ForceSamples& s, const JointChoice& joint);
  void fitRanges(const ForceSamples& s, double sizeMm);
  void fitCrankLabels();
  void squarePolar();
  void addCursor();
  void cursorMoved(double deg) override;

  const ForceSamples* samples_ = nullptr;
  int columns_ = 4;
  QSize layoutSize_;
  QString crankLabel_, crankBrief_;
  QCPAxisRect* rects_[kPlots] = {};
  QCPLayoutGrid* cells_[kPlots] = {};  // each rect's grid, with its legend beside it
  QCPGraph* curves_[kCurves] = {};
  QCPCurve* polar_ = nullptr;
  QCPItemTracer* polarDot_ = nullptr;
  QCPItemLine* polarArrow_ = nullptr;
};

}  // namespace linkage::ui
