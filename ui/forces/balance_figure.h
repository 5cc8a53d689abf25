// The balance dialog's figure: the minimised measure of the shaking force against the crank
// angle before and after the counterweights (fx or fy signed, with the peak after as a band the
// balanced curve touches where the optimum equioscillates; or |F|), and the polar diagrams of
// the shaking force before and after on equal scales. A machine in space: the world's
// components and |F| in 3D; the polar diagrams of the world's x and y.
#pragma once

#include <QString>
#include <vector>

#include "linkage/balance.h"

class QCustomPlot;

namespace linkage::ui {

struct BalanceCurves {
  std::vector<double> crankDeg;
  std::vector<Vec3> before, after;  // N; the world's (a planar machine's in its plane, z 0)
  bool space = false;               // a machine in space: |F| in 3D, the world's axes
};

void drawBalance(QCustomPlot* plot, const BalanceCurves& c, BalanceMeasure measure,
                 const BalanceResult& r, const QString& crankLabel);
// An empty figure with the same axes (before a computation).
void drawNoBalance(QCustomPlot* plot, const QString& crankLabel, const QString& note);

}  // namespace linkage::ui
