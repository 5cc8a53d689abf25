// The harmonics of the motion curves as bar charts in a QCustomPlot: one row per order shown,
// the amplitude of each multiple of the crank frequency (k = 1 ... maxK) over one revolution,
// mechanisms side by side as grouped bars. A curve that does not repeat after one revolution
// has no harmonics: its row says why.
#pragma once

#include <vector>

#include "figures/units.h"
#include "plots/curve_set.h"

class QCustomPlot;
class QCPMarginGroup;

namespace linkage::ui {

class HarmonicsFigure {
 public:
  explicit HarmonicsFigure(QCustomPlot* plot);
  void build(const std::vector<const CurveSet*>& sets, const PlotUnits& units, int maxK = 20);

 private:
  QCustomPlot* plot_;
  QCPMarginGroup* group_ = nullptr;
};

}  // namespace linkage::ui
