#include "plots/plots_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "document/document.h"
#include "export/figure_export.h"
#include "plots/harmonics_figure.h"
#include "plots/motion_figure.h"
#include "plots/qcp.h"

namespace linkage::ui {

namespace {

QString number(double v) {
  return std::isfinite(v) ? QString::number(v, 'g', 5) : QString::fromUtf8("—");
}

QString degrees(double v) {
  return QString::fromUtf8("%1°").arg(v, 0, 'f', 2);
}

QString titleOf(const Document* d) {
  const std::string& name = d->design().name;
  return name.empty() ? d->displayName() : QString::fromStdString(name);
}

}  // namespace

PlotsPanel::PlotsPanel(QWidget* parent) : QWidget(parent), units_(PlotUnits::fromSettings()) {
  buildControls();
  writeControls();
}

PlotsPanel::~PlotsPanel() = default;

void PlotsPanel::buildControls() {
  auto* top = new QVBoxLayout(this);
  top->setContentsMargins(4, 4, 4, 4);
  top->setSpacing(3);

  auto* row1 = new QHBoxLayout;
  target_ = new QComboBox;
  target_->setToolTip("The point (or body) whose motion is plotted");
  target_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  target_->setMinimumContentsLength(14);
  component_ = new QComboBox;
  component_->addItems({"x", "y", "magnitude", "along"});
  component_->setToolTip(
      "Component of the point's motion: x, y, the vectors' lengths, or along a direction");
  direction_ = new QDoubleSpinBox;
  direction_->setRange(-360, 360);
  direction_->setDecimals(1);
  direction_->setSuffix(QString::fromUtf8("°"));
  direction_->setToolTip("The direction, counter-clockwise from +x");
  row1->addWidget(new QLabel("Plot"));
  row1->addWidget(target_, 1);
  row1->addWidget(component_);
  row1->addWidget(direction_);
  top->addLayout(row1);

  auto* row2 = new QHBoxLayout;
  const char* names[] = {"Position", "Velocity", "Acceleration", "Jerk"};
  for (int o = 0; o < kOrders; ++o) {
    orders_[o] = new QCheckBox(names[o]);
    row2->addWidget(orders_[o]);
  }
  orders_[3]->setToolTip("Spectral derivative of the exact accelerations over one revolution");
  revs_ = new QSpinBox;
  revs_->setRange(1, 20);
  revs_->setSuffix(" rev");
  steps_ = new QSpinBox;
  steps_->setRange(12, 36000);
  steps_->setSingleStep(60);
  steps_->setSuffix(" steps/rev");
  row2->addStretch(1);
  row2->addWidget(revs_);
  row2->addWidget(steps_);
  top->addLayout(row2);

  auto* row3 = new QHBoxLayout;
  velocityUnit_ = new QComboBox;
  velocityUnit_->addItems({"mm/s", "m/s"});
  accelerationUnit_ = new QComboBox;
  accelerationUnit_->addItems({QString::fromUtf8("mm/s²"), QString::fromUtf8("m/s²"), "g"});
  accelerationUnit_->setToolTip("g = 9806.65 mm/s² (standard gravity)");
  compareBox_ = new QComboBox;
  compareBox_->addItems({"No comparison", "Overlay", "Side by side"});
  compareBox_->setToolTip("Curves of the other open documents");
  harmonicsButton_ = new QToolButton;
  harmonicsButton_->setText("Harmonics");
  harmonicsButton_->setCheckable(true);
  harmonicsButton_->setToolTip("Amplitude of each multiple of the crank frequency");
  row3->addWidget(new QLabel("Units"));
  row3->addWidget(velocityUnit_);
  row3->addWidget(accelerationUnit_);
  row3->addStretch(1);
  row3->addWidget(compareBox_);
  row3->addWidget(harmonicsButton_);
  top->addLayout(row3);

  status_ = new QLabel;
  status_->setWordWrap(true);
  status_->setStyleSheet("color: #962020");
  status_->hide();
  top->addWidget(status_);

  auto* split = new QSplitter(Qt::Vertical);
  stack_ = new QStackedWidget;
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(200, 200);
  plot_->setCursor(Qt::CrossCursor);
  harmonicsPlot_ = new QCustomPlot;
  stack_->addWidget(plot_);
  stack_->addWidget(harmonicsPlot_);
  figure_ = std::make_unique<MotionFigure>(plot_);
  harmonicsFigure_ = std::make_unique<HarmonicsFigure>(harmonicsPlot_);
  split->addWidget(stack_);
  auto* below = new QWidget;
  auto* belowLayout = new QVBoxLayout(below);
  belowLayout->setContentsMargins(0, 0, 0, 0);
  values_ = new QLabel;
  values_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  values_->setWordWrap(true);
  extremes_ = new QTreeWidget;
  extremes_->setRootIsDecorated(false);
  extremes_->setHeaderLabels({"Curve", "Max", "at", "Min", "at", "Range"});
  extremes_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  belowLayout->addWidget(values_);
  belowLayout->addWidget(extremes_, 1);
  split->addWidget(below);
  split->setStretchFactor(0, 4);
  split->setStretchFactor(1, 1);
  split->setSizes({640, 160});  // the plots first; the lists take what is left
  top->addWidget(split, 1);

  auto changed = [this] {
    if (!updatingControls_) readControls();
  };
  connect(target_, &QComboBox::currentIndexChanged, this, changed);
  connect(component_, &QComboBox::currentIndexChanged, this, changed);
  connect(direction_, &QDoubleSpinBox::editingFinished, this, changed);
  for (QCheckBox* c : orders_) connect(c, &QCheckBox::toggled, this, changed);
  connect(revs_, &QSpinBox::editingFinished, this, changed);
  connect(revs_, &QSpinBox::valueChanged, this, changed);
  connect(steps_, &QSpinBox::editingFinished, this, changed);
  auto unitsChanged = [this] {
    if (updatingControls_) return;
    PlotUnits u;
    u.velocity = static_cast<VelocityUnit>(velocityUnit_->currentIndex());
    u.acceleration = static_cast<AccelerationUnit>(accelerationUnit_->currentIndex());
    setUnits(u);
  };
  connect(velocityUnit_, &QComboBox::currentIndexChanged, this, unitsChanged);
  connect(accelerationUnit_, &QComboBox::currentIndexChanged, this, unitsChanged);
  connect(compareBox_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (!updatingControls_) setCompare(static_cast<Compare>(i));
  });
  connect(harmonicsButton_, &QToolButton::toggled, this, &PlotsPanel::setHarmonicsShown);

  plot_->setInteractions({});  // a drag moves the crank, not the axes
  connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) { mouseOnPlot(e, true); });
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) { mouseOnPlot(e, false); });
  connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent*) { dragging_ = false; });
}

// --- what is plotted ------------------------------------------------------------------------

void PlotsPanel::writeControls() {
  updatingControls_ = true;
  const bool body = request_.body;
  component_->setCurrentIndex(static_cast<int>(request_.component));
  component_->setEnabled(!body);
  direction_->setValue(request_.directionDeg);
  direction_->setEnabled(!body && request_.component == Quantity::Component::Along);
  for (int o = 0; o < kOrders; ++o) orders_[o]->setChecked(request_.orders[o]);
  revs_->setValue(request_.revs);
  steps_->setValue(request_.steps);
  velocityUnit_->setCurrentIndex(static_cast<int>(units_.velocity));
  accelerationUnit_->setCurrentIndex(static_cast<int>(units_.acceleration));
  compareBox_->setCurrentIndex(static_cast<int>(compare_));
  compareBox_->setEnabled(
      std::any_of(others_.begin(), others_.end(),
                  [this](const QPointer<Document>& d) { return d && d != doc_; }));
  harmonicsButton_->setChecked(harmonics_);
  updatingControls_ = false;
}

void PlotsPanel::fillTargets() {
  updatingControls_ = true;
  target_->clear();
  if (doc_) {
    const Mechanism& m = doc_->design();
    auto add = [&](PointId p) {
      const QString l = QString::fromStdString(m.pointLabel(p));
      if (target_->findData(QStringList{l, "point"}) < 0)
        target_->addItem(l, QStringList{l, "point"});
    };
    for (PointId p : m.outputs) add(p);
    for (const Point& p : m.points) add(p.id);
    for (const Body& b : m.bodies) {
      if (b.ground) continue;
      const QString n = QString::fromStdString(b.name);
      target_->addItem(QString("%1 (rotation)").arg(n), QStringList{n, "body"});
    }
  }
  int i = target_->findData(QStringList{request_.target, request_.body ? "body" : "point"});
  if (i < 0 && target_->count() > 0) {
    // The first output, or the first point: what the document is about.
    i = 0;
    const QStringList d = target_->itemData(0).toStringList();
    request_.target = d.value(0);
    request_.body = d.value(1) == "body";
  }
  target_->setCurrentIndex(i);
  updatingControls_ = false;
}

void PlotsPanel::readControls() {
  CurveRequest r = request_;
  const QStringList d = target_->currentData().toStringList();
  r.target = d.value(0);
  r.body = d.value(1) == "body";
  r.component = static_cast<Quantity::Component>(std::max(0, component_->currentIndex()));
  r.directionDeg = direction_->value();
  for (int o = 0; o < kOrders; ++o) r.orders[o] = orders_[o]->isChecked();
  r.revs = revs_->value();
  r.steps = steps_->value();
  setRequest(r);
}

void PlotsPanel::setRequest(const CurveRequest& r) {
  if (r == request_) return;
  request_ = r;
  writeControls();
  for (auto& s : sets_) s.second.reset();
  figureStale_ = true;
  schedule();
}

void PlotsPanel::setUnits(const PlotUnits& u) {
  if (u == units_) return;
  units_ = u;
  units_.toSettings();
  writeControls();
  // The curves are kept in the solver's units: only the figure changes.
  figureStale_ = true;
  if (isVisible()) rebuildFigure();
}

void PlotsPanel::setHarmonicsShown(bool on) {
  if (on == harmonics_) return;
  harmonics_ = on;
  writeControls();
  stack_->setCurrentIndex(on ? 1 : 0);
  figureStale_ = true;
  if (isVisible()) rebuildFigure();
}

// --- documents ------------------------------------------------------------------------------

void PlotsPanel::setDocument(Document* doc) {
  delete docContext_;
  docContext_ = new QObject(this);
  doc_ = doc;
  if (doc) {
    connect(doc, &Document::designChanged, docContext_, [this, doc] {
      fillTargets();
      markStale(doc);
    });
    connect(doc, &Document::poseChanged, docContext_, [this] { updateCursor(); });
    connect(doc, &QObject::destroyed, docContext_, [this] { setDocument(nullptr); });
  }
  fillTargets();
  writeControls();
  markStale(doc);
}

void PlotsPanel::setComparisonDocuments(const QList<Document*>& docs) {
  delete othersContext_;
  othersContext_ = new QObject(this);
  others_.clear();
  for (Document* d : docs) {
    if (!d) continue;
    others_.push_back(d);
    connect(d, &Document::designChanged, othersContext_, [this, d] { markStale(d); });
    connect(d, &QObject::destroyed, othersContext_, [this] { schedule(); });
  }
  writeControls();
  figureStale_ = true;
  schedule();
}

void PlotsPanel::setCompare(Compare c) {
  if (c == compare_) return;
  compare_ = c;
  writeControls();
  figureStale_ = true;
  schedule();
}

std::vector<Document*> PlotsPanel::shownDocuments() const {
  std::vector<Document*> v;
  if (!doc_) return v;
  v.push_back(doc_);
  if (compare_ != Compare::Off)
    for (const QPointer<Document>& d : others_)
      if (d && d != doc_) v.push_back(d);
  return v;
}

const CurveSet* PlotsPanel::curves(int i) const {
  return i >= 0 && i < static_cast<int>(sets_.size()) ? sets_[i].second.get() : nullptr;
}

// --- work -----------------------------------------------------------------------------------

void PlotsPanel::markStale(Document* d) {
  for (auto& s : sets_)
    if (s.first == d) s.second.reset();
  figureStale_ = true;
  schedule();
}

void PlotsPanel::schedule() {
  // Hidden: nothing now; showEvent does what is stale. Shown: once per burst of changes (an
  // edit dragged with the mouse changes the design many times between two paints).
  if (!isVisible() || pending_) return;
  pending_ = true;
  QTimer::singleShot(0, this, [this] {
    if (pending_) recompute();
  });
}

void PlotsPanel::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  ensureComputed();
  updateCursor();
}

void PlotsPanel::ensureComputed() {
  const std::vector<Document*> docs = shownDocuments();
  bool stale = figureStale_ || docs.size() != sets_.size();
  for (size_t i = 0; !stale && i < docs.size(); ++i)
    stale = sets_[i].first != docs[i] || !sets_[i].second;
  if (stale) recompute();
}

void PlotsPanel::recompute() {
  pending_ = false;
  std::vector<std::pair<QPointer<Document>, std::unique_ptr<CurveSet>>> next;
  for (Document* d : shownDocuments()) {
    std::unique_ptr<CurveSet> set;
    for (auto& s : sets_)
      if (s.first == d && s.second) set = std::move(s.second);
    if (!set) {
      set = std::make_unique<CurveSet>(d->kinematics(), request_, titleOf(d));
      ++computations_;
    }
    next.emplace_back(d, std::move(set));
  }
  sets_ = std::move(next);
  rebuildFigure();
}

void PlotsPanel::rebuildFigure() {
  std::vector<const CurveSet*> sets;
  for (auto& s : sets_)
    if (s.second) sets.push_back(s.second.get());
  QStringList problems;
  if (!doc_)
    problems << "No document.";
  else if (!doc_->solved())
    problems << QString(
                    "The design cannot be solved (%1): the curves are those of the last "
                    "design that could.")
                    .arg(QString::fromStdString(doc_->solveStatus().message));
  if (doc_ && request_.target.isEmpty()) problems << "The mechanism has no point to plot.";
  status_->setText(problems.join(" "));
  status_->setVisible(!problems.isEmpty());
  if (harmonics_) {
    harmonicsFigure_->build(sets, units_);
  } else {
    MotionFigure::Options o;
    o.layout = compare_ == Compare::SideBySide ? MotionFigure::Layout::SideBySide
                                               : MotionFigure::Layout::Overlay;
    o.units = units_;
    figure_->build(sets, o);
  }
  figureStale_ = false;
  updateExtremes();
  updateCursor();
}

// --- cursor and extremes --------------------------------------------------------------------

double PlotsPanel::cursorDeg() const {
  return figure_->cursor();
}

void PlotsPanel::updateCursor() {
  if (!isVisible() || sets_.empty() || !doc_) return;
  CurveSet* main = sets_[0].second.get();
  if (!main) return;
  const double c = doc_->crankDeg(), period = 360.0 * request_.revs;
  // Periodic curves: the revolution window the crank is in; otherwise the angle itself.
  const double x = main->periodic() ? c - period * std::floor(c / period) : c;
  if (!harmonics_) figure_->setCursor(x);
  QStringList lines;
  for (auto& [d, set] : sets_) {
    if (!set) continue;
    const std::array<double, kOrders> v = set->valuesAt(x);
    QStringList parts;
    for (int o = 0; o < kOrders; ++o) {
      if (!request_.orders[o]) continue;
      const Order order = static_cast<Order>(o);
      const QString what = request_.body
                               ? QString("angle,ω,α,dα/dt").split(',')[o]
                               : componentLabel(request_.component, request_.directionDeg, order);
      parts << QString("%1 %2 %3")
                   .arg(what, number(v[o] * units_.scale(order, request_.body)),
                        units_.name(order, request_.body));
    }
    const QString who = sets_.size() > 1 ? set->title() + ": " : QString();
    lines << QString("%1%2 at %3: %4").arg(who, request_.target, degrees(x), parts.join(", "));
  }
  values_->setText(lines.join("\n"));
}

QString PlotsPanel::cursorText() const {
  return values_->text();
}

void PlotsPanel::updateExtremes() {
  extremes_->clear();
  if (harmonics_) {
    // The numbers behind the bars: each harmonic's amplitude and phase (the term
    // amplitude cos(k phi + phase) of the crank angle phi).
    extremes_->setColumnCount(4);
    extremes_->setHeaderLabels({"Curve", "k", "Amplitude", "Phase"});
    for (auto& [d, set] : sets_) {
      if (!set) continue;
      for (int o = 0; o < kOrders; ++o) {
        if (!request_.orders[o]) continue;
        const Order order = static_cast<Order>(o);
        Status why;
        const Spectrum sp = set->harmonics(order, 20, &why);
        const double k = std::abs(units_.scale(order, request_.body));
        QString name =
            axisLabel(request_.body, request_.component, request_.directionDeg, order, units_);
        name = name.left(name.indexOf(" ["));
        if (sets_.size() > 1) name = set->title() + ": " + name;
        if (!why.ok()) {
          new QTreeWidgetItem(extremes_, {name, "", QString::fromStdString(why.message)});
          continue;
        }
        new QTreeWidgetItem(extremes_, {name, "mean",
                                        number(sp.mean * units_.scale(order, request_.body)) + " " +
                                            units_.name(order, request_.body)});
        double largest = 0;
        for (const Harmonic& h : sp.terms) largest = std::max(largest, h.amplitude);
        for (const Harmonic& h : sp.terms) {
          // Under 1e-10 of the largest is the samples' rounding: no amplitude, no phase.
          const bool noise = h.amplitude <= 1e-10 * largest;
          new QTreeWidgetItem(
              extremes_, {name, QString::number(h.k),
                          noise ? QString::fromUtf8("≈ 0")
                                : number(h.amplitude * k) + " " + units_.name(order, request_.body),
                          noise ? QString::fromUtf8("—") : degrees(h.phase * 180 / M_PI)});
        }
      }
    }
    return;
  }
  extremes_->setColumnCount(6);
  extremes_->setHeaderLabels({"Curve", "Max", "at", "Min", "at", "Range"});
  for (auto& [d, set] : sets_) {
    if (!set) continue;
    for (int o = 0; o < kOrders; ++o) {
      if (!request_.orders[o]) continue;
      const Order order = static_cast<Order>(o);
      const Extremes& e = set->extremes(order);
      if (!e.status.ok()) continue;
      const double k = units_.scale(order, request_.body);
      const QString unit = units_.name(order, request_.body);
      QString name =
          axisLabel(request_.body, request_.component, request_.directionDeg, order, units_);
      name = name.left(name.indexOf(" [")) + (o == 0 && !request_.body ? " (stroke)" : "");
      if (sets_.size() > 1) name = set->title() + ": " + name;
      auto* item = new QTreeWidgetItem(
          extremes_, {name, number(e.max.value * k) + " " + unit, degrees(e.max.crankDeg),
                      number(e.min.value * k) + " " + unit, degrees(e.min.crankDeg),
                      number(e.range() * std::abs(k)) + " " + unit});
      item->setToolTip(2, e.max.method == Extreme::Method::Sample
                              ? "the largest sample"
                              : "between samples, from the exact derivative or value");
    }
  }
}

QString PlotsPanel::extremesText() const {
  QStringList lines;
  for (int i = 0; i < extremes_->topLevelItemCount(); ++i) {
    const QTreeWidgetItem* it = extremes_->topLevelItem(i);
    if (harmonics_) {
      lines << QString("%1: k=%2 %3 %4").arg(it->text(0), it->text(1), it->text(2), it->text(3));
      continue;
    }
    lines << QString("%1: max %2 at %3, min %4 at %5, range %6")
                 .arg(it->text(0), it->text(1), it->text(2), it->text(3), it->text(4), it->text(5));
  }
  return lines.join("\n");
}

void PlotsPanel::mouseOnPlot(QMouseEvent* e, bool press) {
  if (!(e->buttons() & Qt::LeftButton) || harmonics_) return;
  if (press) dragging_ = !std::isnan(figure_->crankAt(e->position(), &dragRect_));
  if (!dragging_) return;
  // While dragging, the plot pressed on gives the angle even outside its axes.
  double deg = figure_->crankAtX(dragRect_, e->position().x());
  const CurveSet* main = curves(0);
  double hi = figure_->xMax();
  if (main && !main->empty() && !main->periodic()) hi = std::min(hi, main->lastDeg());
  deg = std::clamp(deg, 0.0, hi);
  double base = 0;
  if (doc_ && main && main->periodic()) {
    const double period = figure_->xMax();
    base = period * std::floor(doc_->crankDeg() / period);
  }
  Q_EMIT crankAngleRequested(base + deg);
}

// --- export ---------------------------------------------------------------------------------

bool PlotsPanel::exportFigure(const QString& path, QSize size, QString* error) {
  ensureComputed();
  if (harmonics_) return exportPlot(harmonicsPlot_, path, size, error);
  figure_->setCursorVisible(false);
  const bool ok = exportPlot(plot_, path, size, error);
  figure_->setCursorVisible(true);
  return ok;
}

}  // namespace linkage::ui
