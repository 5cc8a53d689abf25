#include "plots/harmonics_figure.h"

#include "plots/motion_figure.h"
#include "plots/qcp.h"

namespace linkage::ui {

HarmonicsFigure::HarmonicsFigure(QCustomPlot* plot) : plot_(plot) {
  plot_->setAutoAddPlottableToLegend(false);
}

void HarmonicsFigure::build(const std::vector<const CurveSet*>& sets, const PlotUnits& units,
                            int maxK) {
  plot_->clearItems();
  plot_->clearPlottables();
  QCPLayoutGrid* layout = plot_->plotLayout();
  layout->clear();
  delete group_;
  group_ = nullptr;
  if (sets.empty()) {
    plot_->replot();
    return;
  }
  const CurveRequest& req = sets[0]->request();
  QFont titleFont = plot_->font();
  titleFont.setBold(true);
  layout->addElement(
      0, 0,
      new QCPTextElement(plot_,
                         QString("Harmonics of %1: amplitude of each multiple of the crank "
                                 "frequency over one revolution")
                             .arg(req.target),
                         titleFont));
  int row = 1, shown = 0;
  for (int o = 0; o < kOrders; ++o) shown += req.orders[o];
  auto ticker = QSharedPointer<QCPAxisTickerFixed>::create();
  ticker->setTickStep(maxK > 20 ? 5 : 1);
  ticker->setScaleStrategy(QCPAxisTickerFixed::ssNone);
  auto logTicker = QSharedPointer<QCPAxisTickerLog>::create();
  logTicker->setLogBase(10);
  logTicker->setSubTickCount(0);
  const double n = static_cast<double>(sets.size());
  auto* group = group_ = new QCPMarginGroup(plot_);
  for (int o = 0; o < kOrders; ++o) {
    if (!req.orders[o]) continue;
    const Order order = static_cast<Order>(o);
    auto* rect = new QCPAxisRect(plot_);
    layout->addElement(row++, 0, rect);
    rect->setMarginGroup(QCP::msLeft | QCP::msRight, group);
    QCPAxis* x = rect->axis(QCPAxis::atBottom);
    QCPAxis* y = rect->axis(QCPAxis::atLeft);
    x->setTicker(ticker);
    x->setRange(0.3, maxK + 0.7);
    if (row == shown + 1) x->setLabel("multiple of the crank frequency");
    y->setLabel(QString("Amplitude [%1]").arg(units.name(order, req.body)));
    // Logarithmic: a needle's higher harmonics are small but what a designer looks for.
    y->setScaleType(QCPAxis::stLogarithmic);
    y->setTicker(logTicker);
    double hi = 0;
    QStringList notes;
    std::vector<std::pair<QCPBars*, Spectrum>> spectra;
    for (size_t i = 0; i < sets.size(); ++i) {
      Status why;
      const Spectrum s = sets[i]->harmonics(order, maxK, &why);
      if (!why.ok()) {
        notes << QString("%1: %2").arg(sets[i]->title(), QString::fromStdString(why.message));
        continue;
      }
      auto* bars = new QCPBars(x, y);
      bars->setWidth(0.8 / n);
      bars->setPen(Qt::NoPen);
      bars->setBrush(MotionFigure::colour(static_cast<int>(i)));
      bars->setName(sets[i]->title());
      const double scale = std::abs(units.scale(order, req.body));
      for (const Harmonic& h : s.terms) hi = std::max(hi, h.amplitude * scale);
      spectra.emplace_back(bars, s);
    }
    // Ten decades below the largest: what is under that is rounding of the samples.
    const double lo = hi > 0 ? hi * 1e-10 : 1e-10, top = hi > 0 ? hi * 3 : 1;
    y->setRange(lo, top);
    for (size_t i = 0; i < spectra.size(); ++i) {
      auto& [bars, s] = spectra[i];
      bars->setBaseValue(lo);
      const double scale = std::abs(units.scale(order, req.body));
      // Side by side within each k: set i at k - 0.4 + (i + 0.5) * 0.8 / n.
      for (const Harmonic& h : s.terms)
        bars->addData(h.k - 0.4 + (static_cast<double>(i) + 0.5) * 0.8 / n,
                      std::max(h.amplitude * scale, lo));
    }
    if (!notes.isEmpty()) {
      auto* t = new QCPItemText(plot_);
      t->setClipAxisRect(rect);
      t->position->setType(QCPItemPosition::ptAxisRectRatio);
      t->position->setAxisRect(rect);
      t->position->setCoords(0.01, 0.03);
      t->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
      t->setText(notes.join("\n"));
      t->setColor(QColor(150, 20, 20));
    }
  }
  plot_->replot();
}

}  // namespace linkage::ui
