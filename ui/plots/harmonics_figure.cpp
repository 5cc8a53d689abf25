#include "plots/harmonics_figure.h"

#include "figures/qcp.h"
#include "plots/motion_figure.h"

namespace linkage::ui {

namespace {

// The axes' tickers, shared by the rows: every multiple of the crank frequency (every fifth
// past 20) along, decades up.
struct Tickers {
  QSharedPointer<QCPAxisTickerFixed> k;
  QSharedPointer<QCPAxisTickerLog> amplitude;
};

Tickers makeTickers(int maxK) {
  Tickers t{QSharedPointer<QCPAxisTickerFixed>::create(),
            QSharedPointer<QCPAxisTickerLog>::create()};
  t.k->setTickStep(maxK > 20 ? 5 : 1);
  t.k->setScaleStrategy(QCPAxisTickerFixed::ssNone);
  t.amplitude->setLogBase(10);
  t.amplitude->setSubTickCount(0);
  return t;
}

// A row's plot: k = 1 ... maxK along, amplitudes up, the bottom row's axis labelled.
QCPAxisRect* addPlot(QCustomPlot* plot, QCPMarginGroup* group, int row, bool bottom, int maxK,
                     const Tickers& tickers, const QString& amplitudeLabel) {
  auto* rect = new QCPAxisRect(plot);
  plot->plotLayout()->addElement(row, 0, rect);
  rect->setMarginGroup(QCP::msLeft | QCP::msRight, group);
  QCPAxis* x = rect->axis(QCPAxis::atBottom);
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  x->setTicker(tickers.k);
  x->setRange(0.3, maxK + 0.7);
  if (bottom) x->setLabel("multiple of the crank frequency");
  y->setLabel(amplitudeLabel);
  // Logarithmic: a needle's higher harmonics are small but what a designer looks for.
  y->setScaleType(QCPAxis::stLogarithmic);
  y->setTicker(tickers.amplitude);
  return rect;
}

// Every set's harmonics of one order as bars on a plot, the sets side by side within each k,
// over ten decades below the largest; returns why sets have none.
QStringList addBars(QCPAxisRect* rect, const std::vector<const CurveSet*>& sets, Order order,
                    double scale, int maxK) {
  QCPAxis* x = rect->axis(QCPAxis::atBottom);
  QCPAxis* y = rect->axis(QCPAxis::atLeft);
  const double n = static_cast<double>(sets.size());
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
    for (const Harmonic& h : s.terms) hi = std::max(hi, h.amplitude * scale);
    spectra.emplace_back(bars, s);
  }
  // Ten decades below the largest: what is under that is rounding of the samples.
  const double lo = hi > 0 ? hi * 1e-10 : 1e-10, top = hi > 0 ? hi * 3 : 1;
  y->setRange(lo, top);
  for (size_t i = 0; i < spectra.size(); ++i) {
    auto& [bars, s] = spectra[i];
    bars->setBaseValue(lo);
    // Side by side within each k: set i at k - 0.4 + (i + 0.5) * 0.8 / n.
    for (const Harmonic& h : s.terms)
      bars->addData(h.k - 0.4 + (static_cast<double>(i) + 0.5) * 0.8 / n,
                    std::max(h.amplitude * scale, lo));
  }
  return notes;
}

// Text in the top left corner of a plot.
void addNote(QCustomPlot* plot, QCPAxisRect* rect, const QString& text) {
  auto* t = new QCPItemText(plot);
  t->setClipAxisRect(rect);
  t->position->setType(QCPItemPosition::ptAxisRectRatio);
  t->position->setAxisRect(rect);
  t->position->setCoords(0.01, 0.03);
  t->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
  t->setText(text);
  t->setColor(QColor(150, 20, 20));
}

}  // namespace

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
  const Tickers tickers = makeTickers(maxK);
  group_ = new QCPMarginGroup(plot_);
  for (int o = 0; o < kOrders; ++o) {
    if (!req.orders[o]) continue;
    const Order order = static_cast<Order>(o);
    QCPAxisRect* rect = addPlot(plot_, group_, row, row == shown, maxK, tickers,
                                QString("Amplitude [%1]").arg(units.name(order, req.body)));
    ++row;
    const QStringList notes =
        addBars(rect, sets, order, std::abs(units.scale(order, req.body)), maxK);
    if (!notes.isEmpty()) addNote(plot_, rect, notes.join("\n"));
  }
  plot_->replot();
}

}  // namespace linkage::ui
