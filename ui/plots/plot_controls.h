// The controls above the plots: what is plotted (point or body, component, direction, orders,
// revolutions, steps), the units, the comparison mode and the harmonics switch. They show a
// state and report what the user changes; the panel decides what that means.
#pragma once

#include <QWidget>

#include "plots/curve_set.h"
#include "plots/units.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QSpinBox;
class QToolButton;
class QVBoxLayout;

namespace linkage::ui {

class PlotControls : public QWidget {
  Q_OBJECT

 public:
  explicit PlotControls(QWidget* parent = nullptr);

  // Shows these; emits nothing.
  void display(const CurveRequest& r, const PlotUnits& u, int compare, bool compareEnabled,
               bool harmonics);
  // The points (outputs first) and bodies of `m` as choices (none for nullptr). If r's target is
  // not among them, r becomes the first choice (the first output); returns whether r changed.
  bool offerTargets(const Mechanism* m, CurveRequest& r);
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
  // The target was chosen for the user (no output yet), not by them: it gives way to the
  // first output point when the design gets one.
  bool autoTarget_ = true;
  QComboBox *target_, *component_, *velocityUnit_, *accelerationUnit_, *compare_, *against_;
  QDoubleSpinBox* direction_;
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
