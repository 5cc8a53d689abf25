#include "plots/plot_controls.h"

#include "linkage/space.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>

namespace linkage::ui {

PlotControls::PlotControls(QWidget* parent) : QWidget(parent) {
  rows_ = new QVBoxLayout(this);
  rows_->setContentsMargins(0, 0, 0, 0);
  rows_->setSpacing(3);
  addPlotRow();
  addOrdersRow();
  addUnitsRow();
  connectInputs();
}

void PlotControls::addPlotRow() {
  plotRow_ = new QWidget;
  auto* row1 = new QHBoxLayout(plotRow_);
  row1->setContentsMargins(0, 0, 0, 0);
  target_ = new QComboBox;
  target_->setObjectName("plotTarget");  // for scripts (the probe) and tests
  target_->setToolTip("The point (or body) whose motion is plotted");
  target_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  target_->setMinimumContentsLength(14);
  component_ = new QComboBox;
  component_->setObjectName("plotComponent");  // for scripts (the probe)
  // In Quantity::Component's order; z for a machine in space (0 in a planar one).
  component_->addItems({"x", "y", "magnitude", "along", "z", "distance"});
  component_->setToolTip(
      "Component of the point's motion: x, y, the vectors' lengths, along a direction, z, or "
      "its distance to another point (a machine in space: all in the world)");
  to_ = new QComboBox;
  to_->setObjectName("plotDistanceTo");  // for scripts (the probe)
  to_->setToolTip("The point the distance is measured to (in space on a machine in space)");
  to_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  to_->setMinimumContentsLength(10);
  direction_ = new QDoubleSpinBox;
  direction_->setRange(-360, 360);
  direction_->setDecimals(1);
  direction_->setSuffix(QString::fromUtf8("°"));
  direction_->setToolTip("The direction, counter-clockwise from +x");
  elevation_ = new QDoubleSpinBox;
  elevation_->setObjectName("plotElevation");
  elevation_->setRange(-90, 90);
  elevation_->setDecimals(1);
  elevation_->setSuffix(QString::fromUtf8("° up"));
  elevation_->setToolTip("The direction's angle above the world's x-y plane");
  row1->addWidget(new QLabel("Plot"));
  row1->addWidget(target_, 1);
  row1->addWidget(component_);
  row1->addWidget(to_, 1);
  row1->addWidget(direction_);
  row1->addWidget(elevation_);
  row1_ = new QHBoxLayout;
  row1_->setSpacing(12);
  row1_->addWidget(plotRow_, 1);
  rows_->addLayout(row1_);
}

void PlotControls::addOrdersRow() {
  auto* row2 = new QHBoxLayout;
  const char* names[] = {"Position", "Velocity", "Acceleration", "Jerk"};
  for (int o = 0; o < kOrders; ++o) {
    orders_[o] = new QCheckBox(names[o]);
    row2->addWidget(orders_[o]);
  }
  orders_[3]->setToolTip("Spectral derivative of the exact accelerations over one revolution");
  revs_ = new QSpinBox;
  revs_->setObjectName("plotRevs");  // for scripts (the probe)
  revs_->setRange(1, 20);
  revs_->setSuffix(" rev");
  steps_ = new QSpinBox;
  steps_->setObjectName("plotSteps");
  steps_->setRange(12, 36000);
  steps_->setSingleStep(60);
  steps_->setSuffix(" steps/rev");
  row2->addStretch(1);
  row2->addWidget(revs_);
  row2->addWidget(steps_);
  rows_->addLayout(row2);
}

void PlotControls::addUnitsRow() {
  unitsRow_ = new QWidget;
  auto* row3 = new QHBoxLayout(unitsRow_);
  row3->setContentsMargins(0, 0, 0, 0);
  velocityUnit_ = new QComboBox;
  velocityUnit_->addItems({"mm/s", "m/s"});
  accelerationUnit_ = new QComboBox;
  accelerationUnit_->addItems({QString::fromUtf8("mm/s²"), QString::fromUtf8("m/s²"), "g"});
  accelerationUnit_->setToolTip(QString::fromUtf8("g = 9806.65 mm/s² (standard gravity)"));
  compare_ = new QComboBox;
  compare_->setObjectName("compare");  // for scripts (the probe) and tests
  compare_->addItems({"No comparison", "Overlay", "Side by side"});
  compare_->setToolTip("Curves of the other open documents");
  against_ = new QComboBox;
  against_->setObjectName("against");
  against_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  against_->setMinimumContentsLength(10);
  against_->setToolTip(
      "The point of the other windows' mechanisms to compare with (by default the one of the "
      "same name, else their first output)");
  harmonics_ = new QToolButton;
  harmonics_->setText("Harmonics");
  harmonics_->setCheckable(true);
  harmonics_->setToolTip("Amplitude of each multiple of the crank frequency");
  row3->addWidget(new QLabel("Units"));
  row3->addWidget(velocityUnit_);
  row3->addWidget(accelerationUnit_);
  row3->addStretch(1);
  row3->addWidget(compare_);
  row3->addWidget(against_);
  row3->addWidget(harmonics_);
  rows_->addWidget(unitsRow_);
}

void PlotControls::connectInputs() {
  auto request = [this] {
    if (quiet_) return;
    const CurveRequest r = read();
    if (r == shown_) return;
    shown_ = r;
    Q_EMIT requestChanged(r);
  };
  connect(target_, &QComboBox::currentIndexChanged, this, request);
  connect(target_, &QComboBox::activated, this, [this] { autoTarget_ = false; });
  connect(component_, &QComboBox::currentIndexChanged, this, request);
  connect(direction_, &QDoubleSpinBox::editingFinished, this, request);
  connect(elevation_, &QDoubleSpinBox::editingFinished, this, request);
  connect(to_, &QComboBox::currentIndexChanged, this, request);
  for (QCheckBox* c : orders_) connect(c, &QCheckBox::toggled, this, request);
  connect(revs_, &QSpinBox::valueChanged, this, request);
  connect(steps_, &QSpinBox::editingFinished, this, request);
  auto units = [this] {
    if (quiet_) return;
    PlotUnits u;
    u.velocity = static_cast<VelocityUnit>(velocityUnit_->currentIndex());
    u.acceleration = static_cast<AccelerationUnit>(accelerationUnit_->currentIndex());
    Q_EMIT unitsChanged(u);
  };
  connect(velocityUnit_, &QComboBox::currentIndexChanged, this, units);
  connect(accelerationUnit_, &QComboBox::currentIndexChanged, this, units);
  connect(compare_, &QComboBox::currentIndexChanged, this, [this](int i) {
    if (!quiet_) Q_EMIT compareChanged(i);
  });
  connect(against_, &QComboBox::activated, this,
          [this] { Q_EMIT comparisonTargetChanged(against_->currentData().toString()); });
  connect(harmonics_, &QToolButton::toggled, this, [this](bool on) {
    if (!quiet_) Q_EMIT harmonicsToggled(on);
  });
}

void PlotControls::resizeEvent(QResizeEvent* e) {
  QWidget::resizeEvent(e);
  // A wide dock (under the canvas) puts the units and the comparison beside the point chosen:
  // a row more for the plots, which a laptop's screen needs. A narrow one (beside the canvas)
  // keeps three rows.
  const int need = plotRow_->sizeHint().width() + unitsRow_->sizeHint().width() + 24;
  const bool one = width() >= need;
  if (one == oneRow_) return;
  oneRow_ = one;
  if (one) {
    rows_->removeWidget(unitsRow_);
    row1_->addWidget(unitsRow_);
    // Not a minimum of its own: the dock can still be narrowed, and then it moves back.
    unitsRow_->setMinimumWidth(1);
  } else {
    row1_->removeWidget(unitsRow_);
    unitsRow_->setMinimumWidth(0);
    rows_->addWidget(unitsRow_);
  }
}

void PlotControls::display(const CurveRequest& r, const PlotUnits& u, int compare,
                           bool compareEnabled, bool harmonics) {
  quiet_ = true;
  shown_ = r;
  target_->setCurrentIndex(target_->findData(QStringList{r.target, r.body ? "body" : "point"}));
  component_->setCurrentIndex(static_cast<int>(r.component));
  component_->setEnabled(!r.body);
  direction_->setValue(r.directionDeg);
  const bool along = !r.body && r.component == Quantity::Component::Along;
  direction_->setEnabled(along);
  elevation_->setValue(r.elevationDeg);
  elevation_->setEnabled(along);
  elevation_->setVisible(spatial_);
  to_->setVisible(!r.body && r.component == Quantity::Component::Distance);
  to_->setCurrentIndex(to_->findData(r.other));
  for (int o = 0; o < kOrders; ++o) orders_[o]->setChecked(r.orders[o]);
  revs_->setValue(r.revs);
  steps_->setValue(r.steps);
  velocityUnit_->setCurrentIndex(static_cast<int>(u.velocity));
  accelerationUnit_->setCurrentIndex(static_cast<int>(u.acceleration));
  compare_->setCurrentIndex(compare);
  compare_->setEnabled(compareEnabled);
  against_->setVisible(compare != 0 && compareEnabled);
  harmonics_->setChecked(harmonics);
  quiet_ = false;
}

namespace {

// Whether point p is pinned to a point of body b.
bool pinnedTo(const Mechanism& m, PointId p, BodyId b) {
  for (const Joint& j : m.joints) {
    if (j.type != JointType::Pin || (j.a != p && j.b != p)) continue;
    const Point* other = m.point(j.a == p ? j.b : j.a);
    if (other && other->body == b) return true;
  }
  return false;
}

}  // namespace

std::optional<PointId> defaultPlotPoint(const Mechanism& m, const Kinematics* k) {
  if (!m.outputs.empty()) return m.outputs.front();
  const Body* ground = nullptr;
  for (const Body& b : m.bodies)
    if (b.ground) ground = &b;
  BodyId crank;
  if (m.driver)
    if (const Joint* j = m.joint(m.driver->joint))
      if (const Point* p = m.point(j->b)) crank = p->body;
  std::vector<BodyId> undetermined;
  if (k && k->valid()) undetermined = k->structure().freeBodies;
  std::optional<PointId> onCrank;
  for (const Point& p : m.points) {
    const Body* b = m.body(p.body);
    if (!b || b->ground || (ground && pinnedTo(m, p.id, ground->id))) continue;
    if (std::find(undetermined.begin(), undetermined.end(), p.body) != undetermined.end()) continue;
    if (m.driver && (p.body == crank || pinnedTo(m, p.id, crank))) {
      if (!onCrank) onCrank = p.id;
      continue;
    }
    return p.id;
  }
  return onCrank;
}

bool PlotControls::offerTargets(const Mechanism* m, const Kinematics* k, CurveRequest& r) {
  quiet_ = true;
  target_->clear();
  to_->clear();
  spatial_ = m && isSpatial(*m);
  elevation_->setVisible(spatial_);
  if (m) {
    auto add = [&](PointId p) {
      const QString l = QString::fromStdString(m->pointLabel(p));
      if (target_->findData(QStringList{l, "point"}) >= 0) return;
      target_->addItem(l, QStringList{l, "point"});
      to_->addItem(l, l);
    };
    for (PointId p : m->outputs) add(p);
    for (const Point& p : m->points) add(p.id);
    for (const Body& b : m->bodies) {
      if (b.ground) continue;
      const QString n = QString::fromStdString(b.name);
      target_->addItem(QString("%1 (rotation)").arg(n), QStringList{n, "body"});
    }
  }
  bool changed = false;
  int i = target_->findData(QStringList{r.target, r.body ? "body" : "point"});
  if ((i < 0 || autoTarget_) && target_->count() > 0) {
    const std::optional<PointId> p = defaultPlotPoint(*m, k);
    const int want = std::max(
        0,
        p ? target_->findData(QStringList{QString::fromStdString(m->pointLabel(*p)), "point"}) : 0);
    if (want != i) {
      i = want;
      const QStringList d = target_->itemData(i).toStringList();
      r.target = d.value(0);
      r.body = d.value(1) == "body";
      changed = true;
    }
  }
  target_->setCurrentIndex(i);
  // The distance's other point: as asked while the design has it, else the first other one.
  if (to_->findData(r.other) < 0 && to_->count() > 0) {
    const int first = to_->itemData(0).toString() == r.target && to_->count() > 1 ? 1 : 0;
    r.other = to_->itemData(first).toString();
    changed = changed || r.component == Quantity::Component::Distance;
  }
  to_->setCurrentIndex(to_->findData(r.other));
  quiet_ = false;
  return changed;
}

void PlotControls::offerComparisonTargets(const QStringList& labels, const QString& current) {
  QSignalBlocker b(against_);
  against_->clear();
  against_->addItem("against: same name", QString());
  for (const QString& l : labels) against_->addItem("against " + l, l);
  against_->setCurrentIndex(std::max(0, against_->findData(current)));
}

CurveRequest PlotControls::read() const {
  CurveRequest r = shown_;
  const QStringList d = target_->currentData().toStringList();
  r.target = d.value(0);
  r.body = d.value(1) == "body";
  r.component = static_cast<Quantity::Component>(std::max(0, component_->currentIndex()));
  r.directionDeg = direction_->value();
  r.elevationDeg = spatial_ ? elevation_->value() : 0;
  r.other = to_->currentData().toString();
  for (int o = 0; o < kOrders; ++o) r.orders[o] = orders_[o]->isChecked();
  r.revs = revs_->value();
  r.steps = steps_->value();
  return r;
}

}  // namespace linkage::ui
