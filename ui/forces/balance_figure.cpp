#include "forces/balance_figure.h"

#include <cmath>

#include "figures/qcp.h"
#include "forces/force_plots.h"

namespace linkage::ui {

namespace {

std::vector<double> measured(const std::vector<Vec3>& f, BalanceMeasure m) {
  std::vector<double> v;
  v.reserve(f.size());
  for (const Vec3& x : f)
    v.push_back(m == BalanceMeasure::Fx   ? x.x()
                : m == BalanceMeasure::Fy ? x.y()
                : m == BalanceMeasure::Fz ? x.z()
                                          : x.norm());
  return v;
}

std::vector<Vec2> inPlane(const std::vector<Vec3>& f) {
  std::vector<Vec2> v;
  v.reserve(f.size());
  for (const Vec3& x : f) v.push_back(x.head<2>());
  return v;
}

QString measureLabel(BalanceMeasure m) {
  return m == BalanceMeasure::Fx   ? "Shaking fx [N]"
         : m == BalanceMeasure::Fy ? "Shaking fy [N]"
         : m == BalanceMeasure::Fz ? "Shaking fz [N]"
                                   : "Shaking |F| [N]";
}

struct Plots {
  QCPAxisRect *curve, *polar;
  QCPLayoutGrid* curveCell;
};

// Two plots side by side under their titles: the measure, the polar diagram.
Plots layOut(QCustomPlot* plot, const QString& crankLabel, BalanceMeasure m, bool space) {
  plot->clearItems();
  plot->clearPlottables();
  plot->plotLayout()->clear();
  plot->setAutoAddPlottableToLegend(false);
  plot->plotLayout()->setRowSpacing(0);
  plot->plotLayout()->setColumnSpacing(10);
  addTitle(
      plot->plotLayout(), 0, 0,
      space ? "Shaking force (world axes), before and after" : "Shaking force, before and after");
  addTitle(plot->plotLayout(), 0, 1, space ? "Polar diagrams, world x and y" : "Polar diagrams");
  QCPAxisRect* curve = addCrankRect(plot, crankLabel, measureLabel(m));
  QCPAxisRect* polar = addPolarRect(plot);
  QCPLayoutGrid* cell = addPlotCell(plot->plotLayout(), 1, 0, curve);
  plot->plotLayout()->addElement(1, 1, polar);
  plot->plotLayout()->setRowStretchFactor(0, 0.01);
  auto* group = new QCPMarginGroup(plot);
  curve->setMarginGroup(QCP::msTop | QCP::msBottom, group);
  polar->setMarginGroup(QCP::msTop | QCP::msBottom, group);
  addZeroLines(curve, false);
  addZeroLines(polar, true);
  return {curve, polar, cell};
}

void replotEqual(QCustomPlot* plot, QCPAxisRect* polar) {
  // Every draw lays the plots out first (on the screen, or at an export's size): the polar
  // diagrams' scales made equal for the size they are drawn at, before they are drawn.
  delete plot->findChild<QObject*>("equalScales", Qt::FindDirectChildrenOnly);
  auto* context = new QObject(plot);
  context->setObjectName("equalScales");
  QObject::connect(plot, &QCustomPlot::afterLayout, context, [polar] { fitEqualScales(polar); });
  plot->replot();
}

}  // namespace

void drawNoBalance(QCustomPlot* plot, const QString& crankLabel, const QString& note) {
  auto [curve, polar, cell] = layOut(plot, crankLabel, BalanceMeasure::Force, false);
  addRectNote(curve, note);
  replotEqual(plot, polar);
}

void drawBalance(QCustomPlot* plot, const BalanceCurves& c, BalanceMeasure m,
                 const BalanceResult& r, const QString& crankLabel) {
  auto [curve, polar, cell] = layOut(plot, crankLabel, m, c.space);
  QCPGraph* before = addCurve(curve, c.crankDeg, measured(c.before, m), forceColours::kBefore,
                              "before", Qt::SolidLine);
  QCPGraph* after =
      addCurve(curve, c.crankDeg, measured(c.after, m), forceColours::kAfter, "after");
  after->setPen(QPen(forceColours::kAfter, 2));
  // The peak after: the balanced curve reaches it at several angles (equioscillation).
  std::vector<QCPAbstractPlottable*> legend{before, after};
  const std::vector<double> ends{0, 360};
  for (double sign : {1.0, -1.0}) {
    if (m == BalanceMeasure::Force && sign < 0) break;
    QCPGraph* band = addCurve(curve, ends, {sign * r.peakAfter, sign * r.peakAfter},
                              forceColours::kAfter, "peak after", Qt::DashLine);
    band->setPen(QPen(forceColours::kAfter.lighter(140), 1, Qt::DashLine));
    if (sign > 0) legend.push_back(band);
  }
  fitValues(curve, 1e-3 * r.peakBefore);
  addLegend(curve, legend, cell);
  QCPCurve* pb = addPolarCurve(polar, inPlane(c.before), forceColours::kBefore, "before");
  QCPCurve* pa = addPolarCurve(polar, inPlane(c.after), forceColours::kAfter, "after", 2);
  // The legend where the diagrams leave room (fitEqualScales centres them when drawn).
  QCPRange x, y;
  polarBox(polar, x, y);
  polar->axis(QCPAxis::atBottom)->setRange(x.lower - 0.1 * x.size(), x.upper + 0.1 * x.size());
  polar->axis(QCPAxis::atLeft)->setRange(y.lower - 0.1 * y.size(), y.upper + 0.1 * y.size());
  addLegend(polar, {pb, pa});
  replotEqual(plot, polar);
}

}  // namespace linkage::ui
