#include "forces/balance_dialog.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

#include "document/commands.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "figures/qcp.h"
#include "figures/units.h"
#include "forces/balance_figure.h"
#include "forces/force_plots.h"
#include "linkage/elements.h"
#include "linkage/force_samples.h"
#include "linkage/space.h"

namespace linkage::ui {

namespace {

// The point where body b is pinned to the ground, as balanceShaking looks for it.
const Point* pivotOf(const Mechanism& m, BodyId b) {
  const Body* g = m.ground();
  if (!g) return nullptr;
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const Point *a = m.point(j.a), *o = m.point(j.b);
    if (!a || !o) continue;
    if (a->body == b && o->body == g->id) return a;
    if (o->body == b && a->body == g->id) return o;
  }
  return nullptr;
}

BodyId driven(const Mechanism& m) {
  if (m.driver)
    if (const Joint* j = m.joint(m.driver->joint))
      if (const Point* p = m.point(j->b)) return p->body;
  return {};
}

QString number(double v, int digits = 5) {
  return QString::number(v, 'g', digits);
}

}  // namespace

BalanceDialog::BalanceDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
  setWindowTitle(tr("Balance the Shaking Force"));
  buildWidgets();
  offerBodies();
  if (doc)
    connect(doc, &Document::designChanged, this, [this] {
      if (applying_) return;
      offerBodies();
      if (result_) forget(tr("The design changed: compute again."));
    });
  const QString crank = doc ? crankAxisLabel(doc->design()) : QString("crank angle [deg]");
  drawNoBalance(plot_, crank, tr("Choose the bodies, then Compute."));
  resize(1150, 640);
}

BalanceDialog::~BalanceDialog() = default;

QWidget* BalanceDialog::buildChoices() {
  auto* left = new QWidget;
  auto* column = new QVBoxLayout(left);
  column->setContentsMargins(0, 0, 0, 0);
  auto* group = new QGroupBox(tr("Counterweights on"));
  group->setToolTip(
      tr("Bodies pinned to the ground: a counterweight turns with its body about "
         "that pivot; its static moment s = m u is measured from it"));
  bodyBox_ = group;
  new QVBoxLayout(group);
  column->addWidget(group);
  auto* form = new QFormLayout;
  measure_ = new QComboBox;
  measure_->addItem(tr("|shaking force|"), int(BalanceMeasure::Force));
  measure_->addItem(tr("shaking fx"), int(BalanceMeasure::Fx));
  measure_->addItem(tr("shaking fy"), int(BalanceMeasure::Fy));
  measure_->addItem(tr("shaking fz (in space)"), int(BalanceMeasure::Fz));
  measure_->setToolTip(tr("The peak over the whole cycle of this is made as small as it can be"));
  form->addRow(tr("&Minimise the peak of"), measure_);
  auto* boundRow = new QHBoxLayout;
  bounded_ = new QCheckBox(tr("at most"));
  bound_ = new QDoubleSpinBox;
  bound_->setRange(0.001, 1e7);
  bound_->setDecimals(3);
  bound_->setValue(10);
  bound_->setSuffix(tr(" kg mm"));
  bound_->setEnabled(false);
  bound_->setToolTip(tr("Each counterweight's static moment |s| (mass times radius) within this"));
  connect(bounded_, &QCheckBox::toggled, bound_, &QWidget::setEnabled);
  boundRow->addWidget(bounded_);
  boundRow->addWidget(bound_, 1);
  form->addRow(tr("Each |s|"), boundRow);
  steps_ = new QSpinBox;
  steps_->setRange(8, 1000000);
  steps_->setValue(360);
  steps_->setToolTip(
      tr("Crank angles of the first linear programme; the exchange then finds the "
         "peaks between them exactly"));
  form->addRow(tr("&Samples per turn"), steps_);
  column->addLayout(form);
  compute_ = new QPushButton(tr("&Compute"));
  compute_->setDefault(true);
  connect(compute_, &QPushButton::clicked, this, &BalanceDialog::compute);
  column->addWidget(compute_);
  table_ = new QTableWidget(0, 5);
  table_->setHorizontalHeaderLabels(
      {tr("Body"), tr("|s| [kg mm]"), tr("Mass [kg]"), tr("At [mm]"), tr("Angle [°]")});
  table_->horizontalHeaderItem(1)->setToolTip(tr("Static moment: mass times radius"));
  table_->horizontalHeaderItem(3)->setToolTip(
      tr("Radius from the pivot: at most the body's farthest drawn point (less under gravity "
         "where a heavier mass nearer the pivot weighs in better)"));
  table_->horizontalHeaderItem(4)->setToolTip(
      tr("Direction of the counterweight from the pivot, in the body's drawing"));
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setMinimumHeight(90);
  column->addWidget(table_, 1);
  summary_ = new QLabel;
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  column->addWidget(summary_);
  message_ = new QLabel;
  message_->setWordWrap(true);
  message_->hide();
  column->addWidget(message_);
  return left;
}

void BalanceDialog::buildWidgets() {
  auto* top = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  QWidget* left = buildChoices();
  left->setFixedWidth(400);
  row->addWidget(left);
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(500, 300);
  row->addWidget(plot_, 1);
  top->addLayout(row, 1);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Apply | QDialogButtonBox::Close);
  applyButton()->setEnabled(false);
  applyButton()->setToolTip(tr("Add the counterweights to the bodies' masses (one undo step)"));
  connect(applyButton(), &QPushButton::clicked, this, &BalanceDialog::apply);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  top->addWidget(buttons_);
}

QPushButton* BalanceDialog::applyButton() const {
  return buttons_->button(QDialogButtonBox::Apply);
}

void BalanceDialog::offerBodies() {
  std::vector<BodyId> ticked;
  for (auto& [id, box] : bodies_)
    if (box->isChecked()) ticked.push_back(id);
  const bool first = bodies_.empty();
  QLayout* box = bodyBox_->layout();
  while (QLayoutItem* item = box->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  bodies_.clear();
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  for (const Body& b : m.bodies) {
    const Point* pivot = b.ground ? nullptr : pivotOf(m, b.id);
    if (!pivot) continue;
    auto* check = new QCheckBox(
        tr("%1 (about %2)")
            .arg(QString::fromStdString(b.name), QString::fromStdString(m.pointLabel(pivot->id))));
    const bool on =
        first ? b.id == driven(m) : std::find(ticked.begin(), ticked.end(), b.id) != ticked.end();
    check->setChecked(on);
    box->addWidget(check);
    bodies_.emplace_back(b.id, check);
  }
  if (bodies_.empty()) {
    auto* none =
        new QLabel(tr("No moving body is pinned to the ground: a counterweight turns "
                      "with its body about a fixed pivot."));
    none->setWordWrap(true);
    box->addWidget(none);
  }
}

std::vector<BodyId> BalanceDialog::offeredBodies() const {
  std::vector<BodyId> v;
  for (const auto& b : bodies_) v.push_back(b.first);
  return v;
}

void BalanceDialog::setBodyChecked(BodyId b, bool on) {
  for (auto& [id, box] : bodies_)
    if (id == b) box->setChecked(on);
}

void BalanceDialog::setMeasure(BalanceMeasure m) {
  measure_->setCurrentIndex(measure_->findData(int(m)));
}

void BalanceDialog::setBound(std::optional<double> kgMm) {
  bounded_->setChecked(kgMm.has_value());
  if (kgMm) bound_->setValue(*kgMm);
}

void BalanceDialog::setSteps(int steps) {
  steps_->setValue(steps);
}

void BalanceDialog::say(const QString& text, bool error) {
  message_->setText(text);
  message_->setStyleSheet(error ? "color: #962020" : "");
  message_->setVisible(!text.isEmpty());
}

QString BalanceDialog::message() const {
  return message_->isHidden() ? QString() : message_->text();
}

QString BalanceDialog::summary() const {
  return summary_->text();
}

void BalanceDialog::forget(const QString& why) {
  result_.reset();
  table_->setRowCount(0);
  summary_->clear();
  applyButton()->setEnabled(false);
  say(why, false);
}

// --- compute and apply ----------------------------------------------------------------------

namespace {

// The shaking force before and after over a turn, after with the counterweights as Apply adds
// them (their weight included, as the balance counts it).
BalanceCurves curvesOf(const Kinematics& k, const BalanceResult& r) {
  BalanceCurves c;
  const ForceSamples before = sampleForces(k);
  Mechanism m = k.mechanism();
  addCounterweights(m, r.counterweights);
  Kinematics balanced = k;
  if (!balanced.edit(m).ok()) return c;
  const ForceSamples after = sampleForces(balanced);
  const size_t n = std::min(before.size(), after.size());
  // In space the world's force in 3D; a planar machine's in its plane (a gz's weight is not in
  // the balance's measures).
  c.space = before.inSpace;
  auto world = [&](const ForceSamples& s, size_t i) {
    return c.space ? s.shaking3N[i] : Vec3(s.shakingN[i].x(), s.shakingN[i].y(), 0);
  };
  for (size_t i = 0; i < n; ++i) {
    c.crankDeg.push_back(before.crankDeg[i]);
    c.before.push_back(world(before, i));
    c.after.push_back(world(after, i));
  }
  return c;
}

}  // namespace

bool BalanceDialog::compute() {
  forget({});
  if (!doc_ || !doc_->solved()) {
    say(tr("The design is not solved: nothing to balance."), true);
    return false;
  }
  if (Status s = doc_->motionStatus(); !s.ok()) {
    say(tr("No balance: %1.").arg(QString::fromStdString(s.message)), true);
    return false;
  }
  BalanceOptions o;
  for (auto& [id, box] : bodies_)
    if (box->isChecked()) o.bodies.push_back(id);
  if (o.bodies.empty()) {
    say(tr("Tick a body to put a counterweight on."), true);
    return false;
  }
  o.measure = static_cast<BalanceMeasure>(measure_->currentData().toInt());
  if (bounded_->isChecked()) o.maxKgMm = bound_->value();
  o.steps = steps_->value();
  Kinematics k = doc_->kinematics();  // a copy: the document's pose stays
  k.setAccelerations(true);
  QApplication::setOverrideCursor(Qt::WaitCursor);
  BalanceResult r = balanceShaking(k, o);
  QApplication::restoreOverrideCursor();
  if (!r.status.ok()) {
    say(tr("No balance: %1.").arg(QString::fromStdString(r.status.message)), true);
    return false;
  }
  result_ = r;
  const BalanceCurves curves = curvesOf(k, r);
  drawBalance(plot_, curves, o.measure, r, crankAxisLabel(doc_->design()));
  showResult();
  return true;
}

void BalanceDialog::showResult() {
  const BalanceResult& r = *result_;
  const Mechanism& m = doc_->design();
  table_->setRowCount(static_cast<int>(r.counterweights.size()));
  int placed = 0;
  for (int i = 0; i < table_->rowCount(); ++i) {
    const Counterweight& c = r.counterweights[i];
    const Body* b = m.body(c.body);
    placed += !c.none();
    const QString cells[5] = {b ? QString::fromStdString(b->name) : QString("?"),
                              number(c.kgMm(), 4), number(c.kg, 4), number(c.radiusMm(), 4),
                              c.kgMm() > 0 ? QString::number(c.angleDeg(), 'f', 2) : "\u2013"};
    for (int col = 0; col < 5; ++col) {
      auto* item = new QTableWidgetItem(cells[col]);
      if (col > 0) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      table_->setItem(i, col, item);
    }
  }
  summary_->setText(headline(r));
  // The programme may keep the peak as it is (no counterweight, or one that changes nothing
  // worth a part): then nothing is offered as an improvement.
  const bool better = placed > 0 && r.peakAfter < r.peakBefore - kRoundingFraction * r.peakBefore;
  applyButton()->setEnabled(better);
  if (!better) say(tr("Balanced as it is: no counterweight lowers the peak."), false);
}

QString BalanceDialog::headline(const BalanceResult& r) const {
  const QString what = measure_->currentText();
  // A peak after that is rounding next to the peak before is an exact cancellation: 0, at no
  // angle in particular.
  const bool cancelled = r.peakAfter <= kRoundingFraction * r.peakBefore;
  const double drop = r.peakBefore > 0 ? 100 * (1 - r.peakAfter / r.peakBefore) : 0;
  const QString after = cancelled
                            ? tr("<b>0 N</b>: cancelled over the whole cycle")
                            : tr("<b>%1 N</b> at %2° (%3 % lower)")
                                  .arg(number(r.peakAfter), QString::number(r.peakAfterDeg, 'f', 2),
                                       QString::number(drop, 'f', 1));
  const bool weighs = doc_->design().gravity.has_value();
  return tr("Peak of %1 before: <b>%2 N</b> at %3°<br>after, applied%4: %5<br>Certified gap %6 "
            "N: no counterweights%7 do better than %8 N.")
             .arg(what, number(r.peakBefore), QString::number(r.peakBeforeDeg, 'f', 2),
                  weighs ? tr(" (their weight included)") : QString(), after,
                  number(std::max(0.0, r.gap()), 2),
                  bounded_->isChecked() ? tr(" within the bounds") : QString(),
                  number(cleaned(r.lowerBound, r.peakBefore))) +
         leftOut(r);
}

// What the counterweights cannot reach (docs/balancing.md, "Machines in space"): on a machine in
// space the force along the normal of their planes when these are parallel; on a planar one the
// weight along the drawing's normal, when gravity has a z.
QString BalanceDialog::leftOut(const BalanceResult& r) const {
  const bool space = isSpatial(doc_->design());
  if (space && !r.unreached)
    return tr(
        "<br>Their planes are not all parallel: every direction of the shaking force is "
        "within their reach.");
  if (!r.unreached || (!space && r.unreachedPeak == 0 && r.unreachedPeakBefore == 0)) return {};
  const Vec3& n = *r.unreached;
  return tr("<br>Beyond their reach, along (%1, %2, %3), the normal of their planes: peak %4 N "
            "(before %5 N).")
      .arg(number(cleaned(n.x(), 1), 4), number(cleaned(n.y(), 1), 4), number(cleaned(n.z(), 1), 4),
           number(cleaned(r.unreachedPeak, r.peakBefore)),
           number(cleaned(r.unreachedPeakBefore, r.peakBefore)));
}

bool BalanceDialog::apply() {
  if (!doc_ || !result_ || !applyButton()->isEnabled()) return false;
  Mechanism m = doc_->design();
  addCounterweights(m, result_->counterweights);
  int n = 0;
  for (const Counterweight& c : result_->counterweights) n += !c.none();
  applying_ = true;
  commitEdit(doc_,
             n == 1 ? tr("Balance: 1 counterweight") : tr("Balance: %1 counterweights").arg(n), m);
  applying_ = false;
  applyButton()->setEnabled(false);
  say(tr("Applied as one edit (Edit > Undo takes it back). The counterweights are now part of "
         "the bodies' masses."),
      false);
  return true;
}

}  // namespace linkage::ui
