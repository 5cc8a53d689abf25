// The balance dialog's figure: the minimised measure of the shaking force against the crank
// angle before and after the counterweights (fx or fy signed, with the peak after as a band the
// balanced curve touches where the optimum equioscillates; or |F|), and the polar diagrams of
// the shaking force before and after on equal scales.
#pragma once

#include <QString>
#include <vector>

#include "linkage/balance.h"

class QCustomPlot;

namespace linkage::ui {

struct BalanceCurves {
  std::vector<double> crankDeg;
  std::vector<Vec2> before, after;  // N; `after` without the counterweights' own weight
};

void drawBalance(QCustomPlot* plot, const BalanceCurves& c, BalanceMeasure measure,
                 const BalanceResult& r, const QString& crankLabel);
// An empty figure with the same axes (before a computation).
void drawNoBalance(QCustomPlot* plot, const QString& crankLabel, const QString& note);

}  // namespace linkage::ui
