#include "design/tolerance_view.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "figures/crank_figure.h"
#include "figures/qcp.h"

namespace linkage::ui {

ToleranceView::ToleranceView(QWidget* parent) : QWidget(parent) {
  table_ = new QTableWidget(0, 2, this);
  table_->setObjectName(QStringLiteral("tolTable"));
  table_->setHorizontalHeaderLabels({tr("Dimension"), tr("± tolerance")});
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->verticalHeader()->setVisible(false);
  connect(table_, &QTableWidget::cellChanged, this, [this](int row, int column) {
    if (filling_ || column != 1) return;
    bool ok = false;
    const QString text = table_->item(row, 1)->text().trimmed();
    const double v = text.isEmpty() ? 0.0 : text.toDouble(&ok);
    if ((!text.isEmpty() && !ok) || !(v >= 0) || !std::isfinite(v)) {
      summary_->setText(tr("\"%1\" is not a tolerance: a number of 0 or more").arg(text));
      return;
    }
    tol_[names_[row]] = v;
    start();
  });
  samples_ = new QSpinBox;
  samples_->setObjectName(QStringLiteral("tolSamples"));
  samples_->setRange(0, 1000000);
  samples_->setSingleStep(1000);
  samples_->setSpecialValueText(tr("first order only"));
  samples_->setKeyboardTracking(false);
  samples_->setStatusTip(tr("Monte Carlo samples, each solved exactly over the cycle"));
  seed_ = new QSpinBox;
  seed_->setObjectName(QStringLiteral("tolSeed"));
  seed_->setRange(1, 1 << 30);
  seed_->setKeyboardTracking(false);
  for (QSpinBox* s : {samples_, seed_})
    connect(s, &QSpinBox::valueChanged, this, [this] { start(); });
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Samples")));
  row->addWidget(samples_);
  row->addWidget(new QLabel(tr("Seed")));
  row->addWidget(seed_);
  row->addStretch();
  plot_ = new QCustomPlot;
  plot_->setObjectName(QStringLiteral("tolPlot"));
  plot_->setMinimumHeight(200);
  summary_ = new QLabel;
  summary_->setObjectName(QStringLiteral("tolSummary"));
  summary_->setWordWrap(true);
  auto* split = new QSplitter(Qt::Horizontal);
  split->addWidget(table_);
  split->addWidget(plot_);
  split->setStretchFactor(1, 1);
  split->setSizes({260, 640});
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(row);
  layout->addWidget(split, 1);
  layout->addWidget(summary_);
}

ToleranceView::~ToleranceView() {
  // A computation under way reads only its own copies; it is waited for, not abandoned.
  for (std::future<void>& f : jobs_)
    if (f.valid()) f.wait();
}

void ToleranceView::fillTable(const std::vector<std::string>& dimensions) {
  if (dimensions == names_) return;
  names_ = dimensions;
  filling_ = true;
  table_->setRowCount(static_cast<int>(names_.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    auto* name = new QTableWidgetItem(QString::fromStdString(names_[r]));
    name->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    table_->setItem(r, 0, name);
    const auto t = tol_.find(names_[r]);
    table_->setItem(
        r, 1,
        new QTableWidgetItem(t != tol_.end() && t->second > 0 ? QString::number(t->second, 'g', 10)
                                                              : QString()));
  }
  filling_ = false;
}

void ToleranceView::update(const Mechanism& m, const std::vector<std::string>& dimensions,
                           PointId point, int component) {
  fillTable(dimensions);
  design_ = std::make_shared<const Mechanism>(m);
  point_ = point;
  component_ = component;
  start();
}

void ToleranceView::setTolerance(const std::string& dimension, double plusMinus) {
  for (size_t r = 0; r < names_.size(); ++r)
    if (names_[r] == dimension)
      table_->item(static_cast<int>(r), 1)->setText(QString::number(plusMinus, 'g', 12));
}

void ToleranceView::setSamples(int n) {
  samples_->setValue(n);
}

void ToleranceView::start() {
  if (!design_ || !point_) return;
  ToleranceSpec spec;
  spec.point = point_;
  for (const auto& [name, t] : tol_)
    if (t > 0 && std::find(names_.begin(), names_.end(), name) != names_.end())
      spec.tolerances.push_back({name, t, false});
  spec.samples = samples_->value();
  spec.seed = static_cast<std::uint64_t>(seed_->value());
  spec.steps = 360;
  const int generation = ++generation_;
  ++pending_;
  if (spec.tolerances.empty()) {
    --pending_;
    result_ = ToleranceResult{};
    summary_->setText(tr("Type a tolerance for any dimension: the band follows"));
    plot_->clearPlottables();
    plot_->replot();
    return;
  }
  summary_->setText(tr("Computing..."));
  QPointer<ToleranceView> self(this);
  jobs_.erase(std::remove_if(jobs_.begin(), jobs_.end(),
                             [](std::future<void>& f) {
                               return f.wait_for(std::chrono::seconds(0)) ==
                                      std::future_status::ready;
                             }),
              jobs_.end());
  jobs_.push_back(std::async(std::launch::async, [self, design = design_, spec, generation] {
    ToleranceResult r = tolerances(*design, spec);
    QMetaObject::invokeMethod(
        qApp,
        [self, r = std::move(r), generation]() mutable {
          if (!self) return;
          --self->pending_;
          if (generation != self->generation_) return;  // asked for something else since
          self->result_ = std::move(r);
          self->draw();
        },
        Qt::QueuedConnection);
  }));
}

void ToleranceView::draw() {
  plot_->clearPlottables();
  plot_->clearItems();
  const ToleranceResult& r = result_;
  if (!r.status.ok()) {
    summary_->setText(QString::fromStdString(r.status.message));
    plot_->replot();
    Q_EMIT shown();
    return;
  }
  const int c = component_;
  QVector<double> keys, worstHi, worstLo, rssHi, rssLo, mcHi, mcLo, odd, oddAt;
  for (const ToleranceRow& row : r.rows) {
    keys << row.crankDeg;
    const double w = row.firstOrder ? row.worst[c] : NAN, s = row.firstOrder ? row.rss[c] : NAN;
    worstHi << w;
    worstLo << -w;
    rssHi << s;
    rssLo << -s;
    mcHi << (r.used > 0 ? row.hi[c] - row.nominal[c] : NAN);
    mcLo << (r.used > 0 ? row.lo[c] - row.nominal[c] : NAN);
    if (row.nonlinear) {
      oddAt << row.crankDeg;
      odd << 0;
    }
  }
  auto band = [&](const QVector<double>& hi, const QVector<double>& lo, QColor fill) {
    QCPGraph* top = plot_->addGraph();
    QCPGraph* bottom = plot_->addGraph();
    top->setData(keys, hi, true);
    bottom->setData(keys, lo, true);
    top->setPen(QPen(fill.darker(140)));
    bottom->setPen(QPen(fill.darker(140)));
    top->setBrush(fill);
    top->setChannelFillGraph(bottom);
  };
  band(worstHi, worstLo, QColor(31, 119, 180, 50));
  band(rssHi, rssLo, QColor(31, 119, 180, 110));
  for (const QVector<double>* mc : {&mcHi, &mcLo}) {
    QCPGraph* g = plot_->addGraph();
    g->setData(keys, *mc, true);
    g->setPen(QPen(QColor(200, 0, 0), 1.5));
  }
  QCPGraph* marks = plot_->addGraph();
  marks->setData(oddAt, odd, true);
  marks->setLineStyle(QCPGraph::lsNone);
  marks->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QColor(200, 0, 0), 7));
  setCrankAxis(plot_->xAxis, 360, tr("crank angle (°)"));
  const QString axis = c == 0 ? QStringLiteral("x") : c == 1 ? QStringLiteral("y") : "z";
  plot_->yAxis->setLabel(r.space ? tr("%1 from the nominal, in the world (mm)").arg(axis)
                                 : tr("%1 from the nominal (mm)").arg(axis));
  plot_->rescaleAxes(true);
  setCrankAxis(plot_->xAxis, 360, tr("crank angle (°)"));
  const QCPRange y = plot_->yAxis->range();
  const double pad = std::max(1e-9, 0.1 * y.size());
  plot_->yAxis->setRange(y.lower - pad, y.upper + pad);
  plot_->replot();
  summary_->setText(summary());
  Q_EMIT shown();
}

QString ToleranceView::summary() const {
  const ToleranceResult& r = result_;
  if (!r.status.ok() || r.rows.empty()) return summary_->text();
  QStringList out;
  const StrokeSpread& s = r.stroke;
  QString stroke = r.space ? tr("Stroke of the world's y %1 mm").arg(s.nominal, 0, 'f', 4)
                           : tr("Stroke %1 mm").arg(s.nominal, 0, 'f', 4);
  if (s.firstOrder)
    stroke += tr(": first order ±%1 worst, ±%2 root sum of squares")
                  .arg(s.worst, 0, 'f', 4)
                  .arg(s.rss, 0, 'f', 4);
  if (r.used > 0)
    stroke += tr("; samples %1 to %2 (%3 of %4 solved)")
                  .arg(s.lo, 0, 'f', 4)
                  .arg(s.hi, 0, 'f', 4)
                  .arg(r.used)
                  .arg(r.samples);
  out << stroke + tr(". Filled: first order, worst case (light) and root sum of squares; "
                     "red: the samples' extremes");
  if (!r.nonlinearDeg.empty())
    out << tr("First order is not enough near %1° to %2° (crosses): the samples say so")
               .arg(r.nonlinearDeg.front(), 0, 'f', 0)
               .arg(r.nonlinearDeg.back(), 0, 'f', 0);
  if (r.failed > 0)
    out << tr("%1 samples did not assemble or turn: %2")
               .arg(r.failed)
               .arg(QString::fromStdString(r.firstFailure));
  return out.join(QLatin1Char('\n'));
}

}  // namespace linkage::ui
