// The controls above the plots: what is plotted (point or body, component, direction, orders,
// revolutions, steps), the units, the comparison mode and the harmonics switch. They show a
// state and report what the user changes; the panel decides what that means.
#pragma once

#include <QWidget>
#include <optional>

#include "figures/units.h"
#include "plots/curve_set.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QSpinBox;
class QToolButton;
class QVBoxLayout;

namespace linkage::ui {

// What a plot shows before the user chooses: the first output point; else the first point
// that moves, one on the bodies the crank drives (the coupler's, the rocker's: a curve worth
// reading) before one on the crank or pinned to it (a circle); else none (the first point is
// taken). A point on the ground or pinned to it, or on a body the driver does not determine
// (`k`, when given, says which), does not move: three flat lines say nothing.
std::optional<PointId> defaultPlotPoint(const Mechanism& m, const Kinematics* k);

class PlotControls : public QWidget {
  Q_OBJECT

 public:
  explicit PlotControls(QWidget* parent = nullptr);

  // Shows these; emits nothing.
  void display(const CurveRequest& r, const PlotUnits& u, int compare, bool compareEnabled,
               bool harmonics);
  // The points (outputs first) and bodies of `m` as choices (none for nullptr). If r's target is
  // not among them, or the user has not chosen one, r becomes the default (defaultPlotPoint);
  // returns whether r changed. `k`: m solved (nullptr when it is not), to leave out the points
  // the driver does not move.
  bool offerTargets(const Mechanism* m, const Kinematics* k, CurveRequest& r);
  // The target follows the design again, as if the user had not chosen one (another design:
  // its own default, not a point of the last one's name).
  void followDesign() { autoTarget_ = true; }
  // The points of the other windows' mechanisms to compare with ("body.point"), after the
  // first choice, the point of the same name; `current` chosen ("" for the same name).
  void offerComparisonTargets(const QStringList& labels, const QString& current);

 Q_SIGNALS:
  void requestChanged(const CurveRequest& r);
  void unitsChanged(const PlotUnits& u);
  void compareChanged(int mode);
  // "" for the point of the same name.
  void comparisonTargetChanged(const QString& target);
  void harmonicsToggled(bool on);

 protected:
  void resizeEvent(QResizeEvent* e) override;

 private:
  // The rows of inputs: the point plotted; the orders and the range; the units, comparison
  // and harmonics. Then their signals.
  void addPlotRow();
  void addOrdersRow();
  void addUnitsRow();
  void connectInputs();
  CurveRequest read() const;

  CurveRequest shown_;
  bool quiet_ = false;  // while showing a state: no signals
  // The target was chosen for the user, not by them: it follows the design (the default of
  // each edit: a moving point as one is drawn, the first output once there is one).
  bool autoTarget_ = true;
  QComboBox *target_, *component_, *velocityUnit_, *accelerationUnit_, *compare_, *against_;
  QComboBox* to_;  // Distance: the second point
  QDoubleSpinBox *direction_, *elevation_;
  bool spatial_ = false;  // the design is a machine in space: the elevation is offered
  QCheckBox* orders_[kOrders];
  QSpinBox *revs_, *steps_;
  QToolButton* harmonics_;
  QVBoxLayout* rows_;
  QHBoxLayout* row1_;  // the point chosen (plotRow_), then unitsRow_ when it fits
  QWidget *plotRow_,
      *unitsRow_;  // units, comparison, harmonics: a row of their own, or row 1's end
  bool oneRow_ = false;
};

}  // namespace linkage::ui
