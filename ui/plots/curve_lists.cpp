#include "plots/curve_lists.h"

#include <QStringList>
#include <QTreeWidget>
#include <cmath>

#include "document/shown_numbers.h"

namespace linkage::ui {

namespace {

// "Position y", "Speed |v|", "Angular velocity": the axis label without its unit.
QString curveName(const CurveSet& set, Order o, const PlotUnits& u, bool several) {
  const CurveRequest& r = set.request();
  QString name = axisLabel(r.body, r.name(), o, u);
  name = name.left(name.indexOf(" ["));
  return several ? set.title() + ": " + name : name;
}

QString withUnit(double solverValue, Order o, bool body, const PlotUnits& u) {
  return formatValue(solverValue * u.scale(o, body)) + " " + u.name(o, body);
}

}  // namespace

QString formatValue(double v) {
  return std::isfinite(v) ? QString::number(v, 'g', 5) : QString::fromUtf8("—");
}

QString formatDegrees(double deg) {
  return std::isfinite(deg) ? angleText(deg, 2) + QString::fromUtf8("°") : QString::fromUtf8("—");
}

QString cursorValues(const std::vector<CurveSet*>& sets, double deg, const PlotUnits& u) {
  QStringList lines;
  for (CurveSet* set : sets) {
    const CurveRequest& r = set->request();
    const std::array<double, kOrders> v = set->valuesAt(deg);
    QStringList parts;
    for (int o = 0; o < kOrders; ++o) {
      if (!r.orders[o]) continue;
      const Order order = static_cast<Order>(o);
      const QString what = r.body ? QString::fromUtf8("angle,ω,α,dα/dt").split(',')[o]
                                  : componentLabel(r.name(), order);
      parts << what + " " + withUnit(v[o], order, r.body, u);
    }
    const QString who = sets.size() > 1 ? set->title() + ": " : QString();
    lines << QString("%1%2 at %3: %4").arg(who, r.target, formatDegrees(deg), parts.join(", "));
  }
  return lines.join("\n");
}

void listExtremes(QTreeWidget* list, const std::vector<const CurveSet*>& sets, const PlotUnits& u) {
  list->clear();
  list->setColumnCount(6);
  list->setHeaderLabels({"Curve", "Max", "at", "Min", "at", "Range"});
  for (const CurveSet* set : sets) {
    const bool body = set->request().body;
    for (int o = 0; o < kOrders; ++o) {
      const Order order = static_cast<Order>(o);
      const Extremes& e = set->extremes(order);
      if (!set->request().orders[o] || !e.status.ok()) continue;
      const QString name =
          curveName(*set, order, u, sets.size() > 1) + (o == 0 && !body ? " (stroke)" : "");
      auto* item = new QTreeWidgetItem(
          list,
          {name, withUnit(e.max.value, order, body, u), formatDegrees(e.max.crankDeg),
           withUnit(e.min.value, order, body, u), formatDegrees(e.min.crankDeg),
           formatValue(e.range() * std::abs(u.scale(order, body))) + " " + u.name(order, body)});
      item->setToolTip(2, !std::isfinite(e.max.crankDeg)
                              ? "none: the curve is a constant to rounding"
                          : e.max.method == Extreme::Method::Sample
                              ? "the largest sample"
                              : "between samples, from the exact derivative or value");
    }
  }
}

void listHarmonics(QTreeWidget* list, const std::vector<const CurveSet*>& sets, const PlotUnits& u,
                   int maxK) {
  list->clear();
  list->setColumnCount(4);
  list->setHeaderLabels({"Curve", "k", "Amplitude", "Phase"});
  for (const CurveSet* set : sets) {
    const bool body = set->request().body;
    for (int o = 0; o < kOrders; ++o) {
      if (!set->request().orders[o]) continue;
      const Order order = static_cast<Order>(o);
      const QString name = curveName(*set, order, u, sets.size() > 1);
      Status why;
      const Spectrum sp = set->harmonics(order, maxK, &why);
      if (!why.ok()) {
        new QTreeWidgetItem(list, {name, "", QString::fromStdString(why.message)});
        continue;
      }
      new QTreeWidgetItem(list, {name, "mean", withUnit(sp.mean, order, body, u)});
      double largest = 0;
      for (const Harmonic& h : sp.terms) largest = std::max(largest, h.amplitude);
      for (const Harmonic& h : sp.terms) {
        // Under 1e-10 of the largest is the samples' rounding: no amplitude, no phase.
        const bool noise = h.amplitude <= 1e-10 * largest;
        new QTreeWidgetItem(
            list, {name, QString::number(h.k),
                   noise ? QString::fromUtf8("≈ 0")
                         : formatValue(h.amplitude * std::abs(u.scale(order, body))) + " " +
                               u.name(order, body),
                   noise ? QString::fromUtf8("—") : formatDegrees(h.phase * 180 / M_PI)});
      }
    }
  }
}

QString listText(const QTreeWidget* list, bool harmonics) {
  QStringList lines;
  for (int i = 0; i < list->topLevelItemCount(); ++i) {
    const QTreeWidgetItem* it = list->topLevelItem(i);
    if (harmonics)
      lines << QString("%1: k=%2 %3 %4").arg(it->text(0), it->text(1), it->text(2), it->text(3));
    else
      lines << QString("%1: max %2 at %3, min %4 at %5, range %6")
                   .arg(it->text(0), it->text(1), it->text(2), it->text(3), it->text(4),
                        it->text(5));
  }
  return lines.join("\n");
}

}  // namespace linkage::ui
