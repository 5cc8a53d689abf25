#include "design/study_plots.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include "design/study_table_model.h"
#include "figures/crank_figure.h"
#include "figures/qcp.h"
#include "figures/units.h"

namespace linkage::ui {

namespace {

// Blue (the first t) through green to orange (the last): distinct on white, no pale yellow.
QCPColorGradient tGradient() {
  QCPColorGradient g;
  g.clearColorStops();
  g.setColorStopAt(0, QColor(33, 102, 172));
  g.setColorStopAt(0.5, QColor(27, 158, 119));
  g.setColorStopAt(1, QColor(217, 95, 2));
  g.setColorInterpolation(QCPColorGradient::ciRGB);
  return g;
}

QCustomPlot* makePlot() {
  auto* p = new QCustomPlot;
  p->setMinimumSize(260, 220);
  p->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
  return p;
}

QWidget* withBox(const QString& label, QComboBox* box, QCustomPlot* plot) {
  auto* w = new QWidget;
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(label));
  row->addWidget(box, 1);
  auto* v = new QVBoxLayout(w);
  v->setContentsMargins(0, 0, 0, 0);
  v->addLayout(row);
  v->addWidget(plot, 1);
  return w;
}

}  // namespace

StudyPlots::StudyPlots(QWidget* parent) : QWidget(parent) {
  measureBox_ = new QComboBox;
  measureBox_->setToolTip(tr("The measure plotted against t"));
  familyBox_ = new QComboBox;
  familyBox_->addItem(tr("Path of the point"), static_cast<int>(Family::Paths));
  familyBox_->addItem(tr("Position along the stroke against crank angle"),
                      static_cast<int>(Family::AgainstCrank));
  measure_ = makePlot();
  family_ = makePlot();
  family_->installEventFilter(this);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(withBox(tr("Measure"), measureBox_, measure_), 1);
  layout->addWidget(withBox(tr("Family"), familyBox_, family_), 1);
  connect(measureBox_, &QComboBox::currentIndexChanged, this, &StudyPlots::plotMeasure);
  connect(familyBox_, &QComboBox::currentIndexChanged, this, &StudyPlots::plotFamily);
  connect(familyBox_, &QComboBox::activated, this, [this] { familyChosen_ = true; });
}

void StudyPlots::setStudy(const Mechanism& m, const StudySpec& spec, const Study& s,
                          const StudyTableModel* model) {
  model_ = model;
  study_ = s;
  spec_ = spec;
  direction_ = spec.direction.value_or(defaultDirection(m, spec.point)).normalized();
  pointLabel_ = QString::fromStdString(m.pointLabel(spec.point));
  crankLabel_ = crankAxisLabel(m);
  const QString was = measureBox_->currentText();
  {
    QSignalBlocker block(measureBox_);
    measureBox_->clear();
    // Every column but t and turns.
    for (int c = 2; c < model->columns().size(); ++c) measureBox_->addItem(model->columns()[c], c);
    int i = measureBox_->findText(was);
    if (i < 0) i = measureBox_->findText(pointLabel_ + QStringLiteral(".stroke_mm"));
    measureBox_->setCurrentIndex(std::max(i, 0));
  }
  plotMeasure();
  if (!familyChosen_) {
    // A point that runs on a line (a needle bar in its guide) draws one segment for every
    // variant: its position against the crank angle tells them apart.
    double across = 0, along = 0;
    for (const StudyRow& r : study_.rows)
      for (const Vec2& q : r.path) {
        const Vec2 d = q - study_.rows.front().path.front();
        across = std::max(across, std::abs(cross(direction_, d)));
        along = std::max(along, std::abs(direction_.dot(d)));
      }
    const Family f = across <= 1e-9 * along ? Family::AgainstCrank : Family::Paths;
    QSignalBlocker block(familyBox_);
    familyBox_->setCurrentIndex(familyBox_->findData(static_cast<int>(f)));
  }
  plotFamily();
}

void StudyPlots::clear() {
  model_ = nullptr;
  study_ = Study{};
  measureBox_->clear();
  plotMeasure();
  plotFamily();
}

int StudyPlots::familyCurves() const {
  return family_->plottableCount();
}

void StudyPlots::plotMeasure() {
  measure_->clearPlottables();
  if (!model_ || measureBox_->currentIndex() < 0) {
    measure_->replot();
    return;
  }
  const int column = measureBox_->currentData().toInt();
  QCPGraph* g = measure_->addGraph();
  g->setPen(QPen(QColor(33, 102, 172), 1.5));
  g->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5));
  for (int r = 0; r < model_->rowCount(); ++r) {
    const std::optional<double> t = model_->value(r, 0), v = model_->value(r, column);
    // A row without the measure leaves a gap.
    g->addData(*t, v ? *v : std::numeric_limits<double>::quiet_NaN());
  }
  measure_->xAxis->setLabel(QStringLiteral("t"));
  measure_->yAxis->setLabel(measureBox_->currentText());
  measure_->rescaleAxes();
  // Every value of t, with the rows that have no measure (the crank stops) as gaps.
  if (model_->rowCount() > 0)
    measure_->xAxis->setRange(
        QCPRange(*model_->value(0, 0), *model_->value(model_->rowCount() - 1, 0)));
  for (QCPAxis* a : {measure_->xAxis, measure_->yAxis}) a->scaleRange(1.1, a->range().center());
  measure_->replot();
}

void StudyPlots::plotFamily() {
  // The layout holds the colour scale beside the axes: built anew each time.
  family_->clearPlottables();
  family_->plotLayout()->clear();
  auto* rect = new QCPAxisRect(family_);
  family_->plotLayout()->addElement(0, 0, rect);
  family_->xAxis = rect->axis(QCPAxis::atBottom);
  family_->yAxis = rect->axis(QCPAxis::atLeft);
  if (study_.rows.empty()) {
    family_->replot();
    return;
  }
  const bool paths = familyBox_->currentData().toInt() == static_cast<int>(Family::Paths);
  const double t0 = study_.rows.front().t, t1 = study_.rows.back().t;
  QCPColorGradient gradient = tGradient();
  const QCPRange tRange(std::min(t0, t1), t0 == t1 ? t0 + 1 : std::max(t0, t1));
  for (const StudyRow& r : study_.rows) {
    if (r.path.empty()) continue;
    QColor c = QColor::fromRgb(gradient.color(r.t, tRange));
    QPen pen(c, 1.3, r.turns ? Qt::SolidLine : Qt::DashLine);
    if (paths) {
      auto* curve = new QCPCurve(family_->xAxis, family_->yAxis);
      for (size_t i = 0; i < r.path.size(); ++i)
        curve->addData(static_cast<double>(i), r.path[i].x(), r.path[i].y());
      curve->setPen(pen);
    } else {
      QCPGraph* g = family_->addGraph(family_->xAxis, family_->yAxis);
      for (size_t i = 0; i < r.path.size(); ++i)
        g->addData(static_cast<double>(i) * 360.0 / spec_.steps, r.path[i].dot(direction_));
      g->setPen(pen);
    }
  }
  auto* scale = new QCPColorScale(family_);
  family_->plotLayout()->addElement(0, 1, scale);
  scale->setGradient(gradient);
  scale->setDataRange(tRange);
  scale->axis()->setLabel(QStringLiteral("t"));
  scale->setBarWidth(10);
  auto* margins = new QCPMarginGroup(family_);
  rect->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
  scale->setMarginGroup(QCP::msBottom | QCP::msTop, margins);
  if (paths) {
    family_->xAxis->setLabel(pointLabel_ + QStringLiteral(" x [mm]"));
    family_->yAxis->setLabel(pointLabel_ + QStringLiteral(" y [mm]"));
  } else {
    setCrankAxis(family_->xAxis, 360, crankLabel_);
    family_->yAxis->setLabel(QStringLiteral("%1 along (%2, %3) [mm]")
                                 .arg(pointLabel_)
                                 .arg(direction_.x(), 0, 'g', 3)
                                 .arg(direction_.y(), 0, 'g', 3));
  }
  fitFamily();
}

void StudyPlots::fitFamily() {
  if (family_->plottableCount() == 0) {
    family_->replot();
    return;
  }
  if (familyBox_->currentData().toInt() != static_cast<int>(Family::Paths)) {
    // Against the crank angle: one turn, as every crank-angle figure shows it.
    family_->yAxis->rescale();
    family_->yAxis->scaleRange(1.08, family_->yAxis->range().center());
    family_->replot();
    return;
  }
  family_->rescaleAxes();
  for (QCPAxis* a : {family_->xAxis, family_->yAxis}) a->scaleRange(1.08, a->range().center());
  // Equal millimetres on both axes: the paths' shapes as they are. Widen whichever axis
  // would otherwise squeeze the other.
  family_->plotLayout()->update(QCPLayoutElement::upLayout);
  QCPAxis *x = family_->xAxis, *y = family_->yAxis;
  const double xPer = x->range().size() / std::max(1, x->axisRect()->width());
  const double yPer = y->range().size() / std::max(1, y->axisRect()->height());
  if (xPer > yPer)
    y->setScaleRatio(x, 1.0);
  else
    x->setScaleRatio(y, 1.0);
  family_->replot();
}

bool StudyPlots::eventFilter(QObject* o, QEvent* e) {
  // After the plot has laid itself out at its new size.
  if (o == family_ && e->type() == QEvent::Resize)
    QMetaObject::invokeMethod(this, &StudyPlots::fitFamily, Qt::QueuedConnection);
  return QWidget::eventFilter(o, e);
}

}  // namespace linkage::ui
