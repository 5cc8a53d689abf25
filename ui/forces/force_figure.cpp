#include "forces/force_figure.h"

#include <QFontMetrics>
#include <algorithm>
#include <cmath>
#include <limits>

#include "figures/qcp.h"
#include "figures/units.h"
#include "forces/force_plots.h"

namespace linkage::ui {

namespace {

std::vector<double> component(const std::vector<Vec2>& v, int c) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Vec2& f : v) out.push_back(c == 0 ? f.x() : c == 1 ? f.y() : std::hypot(f.x(), f.y()));
  return out;
}

// x, y, z, or (c 3) the magnitude.
std::vector<double> component(const std::vector<Vec3>& v, int c) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Vec3& f : v) out.push_back(c < 3 ? f[c] : std::hypot(f.x(), f.y(), f.z()));
  return out;
}

}  // namespace

ForceFigure::ForceFigure(QCustomPlot* plot) : CrankFigure(plot) {
  // Every draw lays the plots out first (on the screen, or at an export's size): the polar
  // diagram's scales are made equal for the size it is drawn at, before it is drawn.
  QObject::connect(plot_, &QCustomPlot::afterLayout, plot_, [this] {
    if (rects_[Polar]) {
      squarePolar();
      fitEqualScales(rects_[Polar]);
    }
    fitCrankLabels();
  });
}

int ForceFigure::columnsFor(QSize area) {
  // The room a plot's curves get in a cell, less its title, tick labels and axis labels.
  constexpr int kAxesWidth = 70, kAxesHeight = 60;
  int best = 4, most = std::numeric_limits<int>::min();
  for (int columns : {4, 2, 1}) {
    const int rows = kPlots / columns;
    const int least =
        std::min(area.width() / columns - kAxesWidth, area.height() / rows - kAxesHeight);
    if (least > most) best = columns, most = least;
  }
  return best;
}

int ForceFigure::leastHeightFor(int columns) {
  return kPlots / std::max(1, columns) * kLeastPlotHeight;
}

void ForceFigure::clear() {
  clearPlot();
  plot_->plotLayout()->clear();
  for (auto& r : rects_) r = nullptr;
  for (auto& c : cells_) c = nullptr;
  for (auto& c : curves_) c = nullptr;
  polar_ = nullptr;
  polarDot_ = nullptr;
  polarArrow_ = nullptr;
  samples_ = nullptr;
}

void ForceFigure::layOut(const QString& crankLabel, const JointChoice& joint,
                         const QString& stopNote, bool space) {
  QCPLayoutGrid* grid = plot_->plotLayout();
  if (!stopNote.isEmpty()) {
    // Why the curves end early, across the figure above the plots.
    auto* note = new QCPTextElement(plot_, stopNote, plot_->font());
    note->setTextColor(forceColours::kNote);
    note->setMargins(QMargins(4, 3, 4, 0));
    grid->addElement(0, 0, note);
    grid->setRowStretchFactor(0, 0.01);
    grid = new QCPLayoutGrid;
    plot_->plotLayout()->addElement(1, 0, grid);
  }
  grid->setRowSpacing(0);
  grid->setColumnSpacing(8);
  // In space the forces are the world's (the table's columns), said in the titles.
  QString reaction = joint.index < 0
                         ? QString("Joint reaction")
                         : QString("Reaction %1 (on %2)").arg(joint.label, joint.bodyName);
  if (space && joint.index >= 0)
    reaction = joint.shape == SpaceReaction::Tension ? QString("Tension of %1").arg(joint.label)
               : joint.shape == SpaceReaction::Couple
                   ? QString("Couple %1 (on %2)").arg(joint.label, joint.bodyName)
                   : reaction + ", world axes";
  const QString titles[kPlots] = {"Driver torque",
                                  space ? "Shaking force, world axes" : "Shaking force",
                                  "Polar diagram of the shaking force", reaction};
  auto* rowGroup = new QCPMarginGroup(plot_);
  for (int p = 0; p < kPlots; ++p) {
    const int row = 2 * (p / columns_), column = p % columns_;
    addTitle(grid, row, column, titles[p]);
    rects_[p] = p == Polar
                    ? addPolarRect(plot_)
                    : addCrankRect(plot_, crankLabel, p == Torque ? "Torque [N m]" : "Force [N]");
    cells_[p] = addPlotCell(grid, row + 1, column, rects_[p]);
    rects_[p]->setMarginGroup(QCP::msTop | QCP::msBottom, rowGroup);
    addZeroLines(rects_[p], p == Polar);
  }
  if (space)  // the world's x and y (a view along its z)
    for (auto [axis, label] : {std::pair{QCPAxis::atBottom, "Shaking fx (world) [N]"},
                               std::pair{QCPAxis::atLeft, "Shaking fy (world) [N]"}})
      rects_[Polar]->axis(axis)->setLabel(label);
  // Titles take their height, the plots the rest.
  for (int r = 0; r < grid->rowCount(); ++r) grid->setRowStretchFactor(r, r % 2 ? 1 : 0.01);
}

void ForceFigure::addReaction(const ForceSamples& s, const JointChoice& joint) {
  if (joint.index < 0 || joint.index >= static_cast<int>(s.reactionN.size())) {
    addRectNote(rects_[Reaction], "No joint chosen.");
    return;
  }
  if (joint.undetermined) {
    addRectNote(rects_[Reaction],
                wrapped(QString("Not determined: %1 is a redundant joint; the joints share its "
                                "reaction in more than one way, and the rigid-body model cannot "
                                "tell how.")
                            .arg(joint.label),
                        30));
    return;
  }
  if (s.inSpace) return addReactionInSpace(s, joint);
  const std::vector<Vec2>& r = s.reactionN[joint.index];
  curves_[ReactionX] =
      addCurve(rects_[Reaction], s.crankDeg, component(r, 0), forceColours::kX, "fx");
  curves_[ReactionY] =
      addCurve(rects_[Reaction], s.crankDeg, component(r, 1), forceColours::kY, "fy");
  curves_[ReactionNorm] = addCurve(rects_[Reaction], s.crankDeg, component(r, 2),
                                   forceColours::kNorm, "|F|", Qt::DashLine);
}

// A machine in space: the joint's force in the world (x, y, z and its magnitude), or a ball
// rod's tension, or a bevel pair's couple (its tooth force is not computed).
void ForceFigure::addReactionInSpace(const ForceSamples& s, const JointChoice& joint) {
  QCPAxisRect* rect = rects_[Reaction];
  if (joint.shape != SpaceReaction::Force) {
    const bool couple = joint.shape == SpaceReaction::Couple;
    curves_[ReactionScalar] = addCurve(rect, s.crankDeg, s.axialOrCouple[joint.index],
                                       forceColours::kX, couple ? "couple" : "tension");
    if (couple) rect->axis(QCPAxis::atLeft)->setLabel("Couple [N m]");
    return;
  }
  const std::vector<Vec3>& r = s.reaction3N[joint.index];
  curves_[ReactionX] = addCurve(rect, s.crankDeg, component(r, 0), forceColours::kX, "fx");
  curves_[ReactionY] = addCurve(rect, s.crankDeg, component(r, 1), forceColours::kY, "fy");
  curves_[ReactionZ] = addCurve(rect, s.crankDeg, component(r, 2), forceColours::kZ, "fz");
  curves_[ReactionNorm] =
      addCurve(rect, s.crankDeg, component(r, 3), forceColours::kNorm, "|F|", Qt::DashLine);
}

void ForceFigure::fitRanges(const ForceSamples& s, double sizeMm) {
  // What is rounding of zero next to the figure's largest force (and its moment) is drawn flat:
  // the value axes span at least a thousandth of it.
  double force = s.inSpace ? peakOf(s.shaking3N) : peakOf(s.shakingN);
  for (size_t j = 0; j < s.reactionN.size(); ++j)
    force = std::max(force, s.inSpace ? peakOf(s.reaction3N[j]) : peakOf(s.reactionN[j]));
  const double torque = std::max(peakOf(s.driverTorqueNm), force * sizeMm * 1e-3);
  constexpr double kFlat = 1e-3;
  fitValues(rects_[Torque], kFlat * torque);
  fitValues(rects_[Shaking], kFlat * force);
  if (curves_[ReactionX]) fitValues(rects_[Reaction], kFlat * force);
  if (QCPGraph* scalar = curves_[ReactionScalar]) {
    // A couple is next to the couples and the driver's torque (a product of the forces and the
    // machine's size would flatten a real one); a tension next to the forces.
    bool found = false;
    const QCPRange own = scalar->getValueRange(found);
    const double peak = found ? std::max(std::abs(own.lower), std::abs(own.upper)) : 0;
    const bool couple = scalar->name() == "couple";
    fitValues(rects_[Reaction], kFlat * std::max(peak, couple ? peakOf(s.driverTorqueNm) : force));
  }
}

// The shaking force's components against the crank angle: the world's in space, with fz.
void ForceFigure::addShaking(const ForceSamples& s) {
  QCPAxisRect* rect = rects_[Shaking];
  curves_[ShakingX] = addCurve(rect, s.crankDeg, component(s.shakingN, 0), forceColours::kX, "fx");
  curves_[ShakingY] = addCurve(rect, s.crankDeg, component(s.shakingN, 1), forceColours::kY, "fy");
  if (s.inSpace)
    curves_[ShakingZ] =
        addCurve(rect, s.crankDeg, component(s.shaking3N, 2), forceColours::kZ, "fz");
}

void ForceFigure::build(const ForceSamples& s, const QString& crankLabel, const QString& crankBrief,
                        const JointChoice& joint, const QString& stopNote, double sizeMm) {
  clear();
  samples_ = &s;
  crankLabel_ = crankLabel;
  crankBrief_ = crankBrief;
  const QSize size = layoutSize_.isEmpty() ? plot_->size() : layoutSize_;
  columns_ = columnsFor(size);
  // A legend beside its plot where the cell has the room; in its emptiest corner where the
  // column beside would leave the curves too narrow to read their crank angles.
  const bool beside = size.width() / columns_ >= 320;
  layOut(crankLabel, joint, stopNote, s.inSpace);
  curves_[TorqueCurve] =
      addCurve(rects_[Torque], s.crankDeg, s.driverTorqueNm, forceColours::kX, "torque");
  addShaking(s);
  addReaction(s, joint);
  polar_ = addPolarCurve(rects_[Polar], s.shakingN, forceColours::kPolar, "shaking force");
  fitRanges(s, sizeMm);
  // A legend of the curves there are, in the order of the enum's (x, y, then z and |F|).
  auto legend = [&](Plot p, std::initializer_list<Curve> which) {
    std::vector<QCPAbstractPlottable*> items;
    for (Curve c : which)
      if (curves_[c]) items.push_back(curves_[c]);
    if (!items.empty()) addLegend(rects_[p], items, beside ? cells_[p] : nullptr);
  };
  legend(Shaking, {ShakingX, ShakingY, ShakingZ});
  legend(Reaction, {ReactionX, ReactionY, ReactionZ, ReactionNorm, ReactionScalar});
  addCursor();
  setCursor(cursor());
  replot();
}

void ForceFigure::addCursor() {
  for (Plot p : {Torque, Shaking, Reaction}) addCursorLine(rects_[p]);
  for (QCPGraph* g : curves_)
    if (g) addCursorDot(g);
  QCPAxisRect* polar = rects_[Polar];
  polarArrow_ = new QCPItemLine(plot_);
  polarDot_ = new QCPItemTracer(plot_);
  polarArrow_->setHead(QCPLineEnding(QCPLineEnding::esSpikeArrow, 9, 11));
  polarArrow_->setPen(QPen(QColor(40, 40, 40), 1.2));
  polarDot_->setStyle(QCPItemTracer::tsCircle);
  polarDot_->setSize(7);
  polarDot_->setPen(QPen(QColor(40, 40, 40)));
  polarDot_->setBrush(QColor(255, 200, 40));
  for (QCPAbstractItem* i :
       {static_cast<QCPAbstractItem*>(polarArrow_), static_cast<QCPAbstractItem*>(polarDot_)}) {
    i->setLayer(cursorLayer());
    i->setClipAxisRect(polar);
    for (QCPItemPosition* p : i->positions())
      p->setAxes(polar->axis(QCPAxis::atBottom), polar->axis(QCPAxis::atLeft));
  }
  polarArrow_->start->setCoords(0, 0);
}

QPointF ForceFigure::polarMark() const {
  if (!samples_ || samples_->size() == 0) return {NAN, NAN};
  const ForceSamples& s = *samples_;
  const double step = 360.0 / static_cast<double>(s.steps);
  const double at = cursor() / step;
  const size_t i = static_cast<size_t>(std::max(0.0, std::floor(at)));
  if (i + 1 >= s.size()) {
    // At the last sample exactly, or past where the sweep stopped (nothing known there).
    if (i + 1 == s.size() && std::abs(at - static_cast<double>(i)) < 1e-9)
      return {s.shakingN[i].x(), s.shakingN[i].y()};
    return {NAN, NAN};
  }
  const double t = at - static_cast<double>(i);
  const Vec2 f = (1 - t) * s.shakingN[i] + t * s.shakingN[i + 1];
  return {f.x(), f.y()};
}

void ForceFigure::cursorMoved(double) {
  if (!polarDot_) return;
  const QPointF f = polarMark();
  const bool known = std::isfinite(f.x());
  polarDot_->position->setCoords(f);
  polarArrow_->end->setCoords(f);
  polarDot_->setVisible(known);
  polarArrow_->setVisible(known);
}

void ForceFigure::replot() {
  plot_->replot();
}

// The polar diagram's axes as wide as they are high, in the middle of its cell: on equal scales
// in a cell much wider than high it was a flat strip with its curve in the middle. Set on each
// layout, after it (the next layout sets the cell's rect again).
void ForceFigure::squarePolar() {
  QCPAxisRect* polar = rects_[Polar];
  const int extra = polar->rect().width() - polar->rect().height();
  if (extra <= 0) return;
  polar->setOuterRect(polar->outerRect().adjusted(extra / 2, 0, -(extra - extra / 2), 0));
}

// Four plots in a row are narrower than "armshaft angle [deg], counter-clockwise": side by
// side, such labels ran into each other. Set as each layout is made, before it is drawn.
void ForceFigure::fitCrankLabels() {
  for (int p : {Torque, Shaking, Reaction}) {
    if (!rects_[p]) continue;
    QCPAxis* x = rects_[p]->axis(QCPAxis::atBottom);
    const QFontMetrics fm(x->labelFont());
    const bool fits = fm.horizontalAdvance(crankLabel_) + 8 <= rects_[p]->outerRect().width();
    x->setLabel(fits ? crankLabel_ : crankBrief_);
  }
}

QPointF ForceFigure::pixelAt(Plot p, double x, double y) const {
  QCPAxisRect* r = rects_[p];
  return {r->axis(QCPAxis::atBottom)->coordToPixel(x), r->axis(QCPAxis::atLeft)->coordToPixel(y)};
}

}  // namespace linkage::ui
