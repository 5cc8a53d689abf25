#include "design/optimize_dialog.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>
#include <map>

#include "document/commands.h"
#include "document/document.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"

namespace linkage::ui {

namespace {

enum VarColumn { Vary, Name, Value, Low, High };
enum TargetColumn { TargetKind, TargetPoint, TargetValue, TargetCrank };

QTableWidgetItem* fixed(const QString& text) {
  auto* i = new QTableWidgetItem(text);
  i->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
  return i;
}

QString number(double v) {
  return QString::number(v, 'g', 10);
}

}  // namespace

OptimizeDialog::OptimizeDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
  setObjectName(QStringLiteral("optimizeDialog"));
  setWindowTitle(tr("Find Dimensions"));
  buildVariables();
  QTableWidget* targets = buildTargets();
  starts_ = new QSpinBox;
  starts_->setObjectName(QStringLiteral("optStarts"));
  starts_->setRange(1, 1000);
  starts_->setValue(8);
  seed_ = new QSpinBox;
  seed_->setRange(1, 1 << 30);
  find_ = new QPushButton(tr("&Find"));
  find_->setObjectName(QStringLiteral("optFind"));
  apply_ = new QPushButton(tr("&Apply to the Design"));
  apply_->setObjectName(QStringLiteral("optApply"));
  apply_->setEnabled(false);
  connect(find_, &QPushButton::clicked, this, &OptimizeDialog::find);
  connect(apply_, &QPushButton::clicked, this, &OptimizeDialog::apply);
  result_table_ = new QTableWidget(0, 4);
  result_table_->setObjectName(QStringLiteral("optResult"));
  result_table_->setHorizontalHeaderLabels(
      {tr("Quantity"), tr("Before"), tr("After"), tr("Target")});
  result_table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  result_table_->verticalHeader()->setVisible(false);
  summary_ = new QLabel(tr("Tick the dimensions to vary, add a target, and Find"));
  summary_->setObjectName(QStringLiteral("optSummary"));
  summary_->setWordWrap(true);
  auto* row = new QHBoxLayout;
  row->addWidget(new QLabel(tr("Starts")));
  row->addWidget(starts_);
  row->addWidget(new QLabel(tr("Seed")));
  row->addWidget(seed_);
  row->addStretch();
  row->addWidget(find_);
  row->addWidget(apply_);
  auto* addTarget = new QPushButton(tr("Add &Target"));
  addTarget->setObjectName(QStringLiteral("optAddTarget"));
  addTarget->setStatusTip(tr("A target for the first output point: its stroke as it is now"));
  auto* removeTarget = new QPushButton(tr("&Remove Target"));
  connect(addTarget, &QPushButton::clicked, this, [this] {
    const Mechanism& m = doc_->design();
    const PointId p = !m.outputs.empty() ? m.outputs.front() : PointId{};
    const double now =
        p && doc_->solved()
            ? findLimits(doc_->kinematics(), LimitMeasure::along(p, defaultDirection(m, p))).stroke
            : 0.0;
    addTargetRow(0, p ? QString::fromStdString(m.pointLabel(p)) : QString(), number(now), 0);
  });
  connect(removeTarget, &QPushButton::clicked, this, [this] {
    if (targets_->currentRow() >= 0) targets_->removeRow(targets_->currentRow());
  });
  auto* targetButtons = new QHBoxLayout;
  targetButtons->addWidget(addTarget);
  targetButtons->addWidget(removeTarget);
  targetButtons->addStretch();
  summary_->setMinimumHeight(2 * summary_->fontMetrics().lineSpacing() + 4);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel(tr("Dimensions to vary")));
  layout->addWidget(variables_, 2);
  layout->addWidget(new QLabel(tr("Targets")));
  layout->addWidget(targets, 1);
  layout->addLayout(targetButtons);
  layout->addLayout(row);
  layout->addWidget(result_table_, 2);
  layout->addWidget(summary_);
  layout->addWidget(close);
  resize(640, 720);
  connect(doc_, &Document::designChanged, this, [this] {
    ++generation_;  // a search under way is of the design before: its result is dropped
    result_.reset();
    apply_->setEnabled(false);
    refresh();
  });
  refresh();
}

OptimizeDialog::~OptimizeDialog() {
  for (std::future<void>& f : jobs_)
    if (f.valid()) f.wait();  // a search reads only its own copies: waited for, not abandoned
}

void OptimizeDialog::buildVariables() {
  variables_ = new QTableWidget(0, 5);
  variables_->setObjectName(QStringLiteral("optVariables"));
  variables_->setHorizontalHeaderLabels(
      {tr("Vary"), tr("Dimension"), tr("Value"), tr("Low"), tr("High")});
  variables_->horizontalHeader()->setSectionResizeMode(Name, QHeaderView::Stretch);
  variables_->verticalHeader()->setVisible(false);
}

QTableWidget* OptimizeDialog::buildTargets() {
  targets_ = new QTableWidget(0, 4);
  targets_->setObjectName(QStringLiteral("optTargets"));
  targets_->setHorizontalHeaderLabels(
      {tr("Kind"), tr("Point"), tr("Target (mm; x, y)"), tr("At crank (°)")});
  targets_->horizontalHeader()->setSectionResizeMode(TargetPoint, QHeaderView::Stretch);
  targets_->verticalHeader()->setVisible(false);
  return targets_;
}

// The dimensions' rows again, keeping what was ticked and the bounds typed, by name.
void OptimizeDialog::refresh() {
  struct Kept {
    bool vary;
    QString lo, hi;
  };
  std::map<QString, Kept> kept;
  for (int r = 0; r < variables_->rowCount(); ++r)
    kept[variables_->item(r, Name)->text()] = {
        variables_->item(r, Vary)->checkState() == Qt::Checked, variables_->item(r, Low)->text(),
        variables_->item(r, High)->text()};
  const std::vector<Dimension> dims = dimensions(doc_->design());
  variables_->setRowCount(static_cast<int>(dims.size()));
  for (int r = 0; r < variables_->rowCount(); ++r) {
    const Dimension& d = dims[r];
    const QString name = QString::fromStdString(d.name);
    const auto k = kept.find(name);
    const double span =
        std::max(0.1 * std::abs(d.value), d.unit == Dimension::Unit::Deg ? 5.0 : 1.0);
    auto* vary = new QTableWidgetItem;
    vary->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    vary->setCheckState(k != kept.end() && k->second.vary ? Qt::Checked : Qt::Unchecked);
    variables_->setItem(r, Vary, vary);
    variables_->setItem(r, Name, fixed(name));
    variables_->setItem(r, Value, fixed(number(d.value)));
    variables_->setItem(
        r, Low, new QTableWidgetItem(k != kept.end() ? k->second.lo : number(d.value - span)));
    variables_->setItem(
        r, High, new QTableWidgetItem(k != kept.end() ? k->second.hi : number(d.value + span)));
  }
}

void OptimizeDialog::addTargetRow(int kind, const QString& point, const QString& value,
                                  double crankDeg) {
  const int r = targets_->rowCount();
  targets_->insertRow(r);
  auto* kinds = new QComboBox;
  kinds->addItems({tr("stroke"), tr("position")});
  kinds->setCurrentIndex(kind);
  targets_->setCellWidget(r, TargetKind, kinds);
  auto* points = new QComboBox;
  const Mechanism& m = doc_->design();
  for (const Point& p : m.points)
    if (!m.body(p.body)->ground) points->addItem(QString::fromStdString(m.pointLabel(p.id)));
  points->setCurrentText(point);
  targets_->setCellWidget(r, TargetPoint, points);
  targets_->setItem(r, TargetValue, new QTableWidgetItem(value));
  targets_->setItem(r, TargetCrank, new QTableWidgetItem(number(crankDeg)));
}

bool OptimizeDialog::vary(const std::string& dimension, double lo, double hi) {
  for (int r = 0; r < variables_->rowCount(); ++r)
    if (variables_->item(r, Name)->text() == QString::fromStdString(dimension)) {
      variables_->item(r, Vary)->setCheckState(Qt::Checked);
      variables_->item(r, Low)->setText(number(lo));
      variables_->item(r, High)->setText(number(hi));
      return true;
    }
  return false;
}

bool OptimizeDialog::addStrokeTarget(const std::string& point, double strokeMm) {
  if (!doc_->design().findPoint(point)) return false;
  addTargetRow(0, QString::fromStdString(point), number(strokeMm), 0);
  return true;
}

bool OptimizeDialog::addPositionTarget(const std::string& point, double crankDeg, Vec2 at) {
  if (!doc_->design().findPoint(point)) return false;
  addTargetRow(1, QString::fromStdString(point),
               QStringLiteral("%1, %2").arg(number(at.x()), number(at.y())), crankDeg);
  return true;
}

bool OptimizeDialog::readSpec(OptimizeSpec& spec, QString* why) const {
  auto value = [](const QTableWidgetItem* i, double& out) {
    bool ok = false;
    out = i ? i->text().toDouble(&ok) : NAN;
    return ok && std::isfinite(out);
  };
  for (int r = 0; r < variables_->rowCount(); ++r) {
    if (variables_->item(r, Vary)->checkState() != Qt::Checked) continue;
    OptVariable v{variables_->item(r, Name)->text().toStdString(), 0, 0};
    if (!value(variables_->item(r, Low), v.lo) || !value(variables_->item(r, High), v.hi) ||
        !(v.lo < v.hi))
      return *why = tr("%1: its bounds are two numbers, low below high")
                        .arg(QString::fromStdString(v.name)),
             false;
    spec.variables.push_back(v);
  }
  const Mechanism& m = doc_->design();
  for (int r = 0; r < targets_->rowCount(); ++r) {
    OptTarget t;
    const auto* kind = qobject_cast<QComboBox*>(targets_->cellWidget(r, TargetKind));
    const auto* point = qobject_cast<QComboBox*>(targets_->cellWidget(r, TargetPoint));
    const std::optional<PointId> p = m.findPoint(point->currentText().toStdString());
    if (!p) return *why = tr("target %1: no point %2").arg(r + 1).arg(point->currentText()), false;
    t.point = *p;
    const QStringList parts = targets_->item(r, TargetValue)->text().split(QLatin1Char(','));
    bool ok = !parts.isEmpty();
    std::vector<double> v;
    for (const QString& s : parts)
      v.push_back(s.trimmed().toDouble(&ok)), ok = ok && std::isfinite(v.back());
    if (kind->currentIndex() == 0 && ok && v.size() == 1) {
      t.kind = OptTarget::Kind::Stroke;
      t.stroke = v[0];
    } else if (kind->currentIndex() == 1 && ok && v.size() == 2 &&
               value(targets_->item(r, TargetCrank), t.crankDeg)) {
      t.kind = OptTarget::Kind::Position;
      t.at = Vec2(v[0], v[1]);
    } else {
      return *why = tr("target %1: a stroke is one number (mm), a position two (x, y) and a crank "
                       "angle")
                        .arg(r + 1),
             false;
    }
    spec.targets.push_back(t);
  }
  if (spec.variables.empty() || spec.targets.empty())
    return *why = tr("Tick a dimension to vary and add a target"), false;
  spec.starts = starts_->value();
  spec.seed = static_cast<std::uint64_t>(seed_->value());
  return true;
}

void OptimizeDialog::find() {
  OptimizeSpec spec;
  QString why;
  if (busy_ || !readSpec(spec, &why)) {
    if (!why.isEmpty()) summary_->setText(why);
    return;
  }
  busy_ = true;
  find_->setEnabled(false);
  apply_->setEnabled(false);
  summary_->setText(tr("Searching..."));
  const int generation = ++generation_;
  auto design = std::make_shared<const Mechanism>(doc_->design());
  QPointer<OptimizeDialog> self(this);
  jobs_.push_back(std::async(std::launch::async, [self, design, spec, generation] {
    Kinematics k;
    OptimizeResult r;
    if (Status s = k.load(*design); !s.ok())
      r.status = s;
    else
      r = optimize(k, spec);
    QMetaObject::invokeMethod(
        qApp,
        [self, r = std::move(r), generation]() mutable {
          if (!self) return;
          self->busy_ = false;
          self->find_->setEnabled(true);
          if (generation == self->generation_) {
            self->result_ = std::move(r);
            self->showResult();
          }
          Q_EMIT self->finished();
        },
        Qt::QueuedConnection);
  }));
}

void OptimizeDialog::showResult() {
  const OptimizeResult& r = *result_;
  result_table_->setRowCount(0);
  if (!r.status.ok()) {
    summary_->setText(QString::fromStdString(r.status.message));
    return;
  }
  OptimizeSpec spec;
  QString why;
  readSpec(spec, &why);
  auto add = [this](const QString& what, double before, double after, const QString& target) {
    const int row = result_table_->rowCount();
    result_table_->insertRow(row);
    result_table_->setItem(row, 0, fixed(what));
    result_table_->setItem(row, 1, fixed(number(before)));
    result_table_->setItem(row, 2, fixed(number(after)));
    result_table_->setItem(row, 3, fixed(target));
  };
  for (size_t i = 0; i < r.before.size() && i < spec.variables.size(); ++i)
    add(QString::fromStdString(spec.variables[i].name), r.before[i], r.after[i], QString());
  const Mechanism& m = doc_->design();
  for (size_t t = 0; t < spec.targets.size() && t < r.atAfter.measures.size(); ++t) {
    const OptTarget& g = spec.targets[t];
    const QString p = QString::fromStdString(m.pointLabel(g.point));
    const Measure& b = r.atBefore.measures.size() > t ? r.atBefore.measures[t] : Measure{};
    const Measure& a = r.atAfter.measures[t];
    if (g.kind == OptTarget::Kind::Stroke)
      add(tr("stroke of %1 (mm)").arg(p), b.empty() ? NAN : b[0], a[0], number(g.stroke));
    else
      for (int c = 0; c < 2; ++c)
        add(tr("%1 of %2 at crank %3°").arg(c ? "y" : "x", p).arg(g.crankDeg),
            b.size() > 1 ? b[c] : NAN, a[c], number(g.at[c]));
  }
  add(tr("objective (mm²)"), r.atBefore.objective, r.atAfter.objective, QStringLiteral("0"));
  summary_->setText(summary());
  apply_->setEnabled(r.atAfter.feasible);
}

QString OptimizeDialog::summary() const {
  if (!result_) return summary_->text();
  const OptimizeResult& r = *result_;
  if (!r.status.ok()) return QString::fromStdString(r.status.message);
  return tr("%1 of %2 starts found the best (%3 could not assemble or turn), %4 designs tried. "
            "Apply to the Design makes it one undo step.")
      .arg(r.foundBest)
      .arg(r.starts)
      .arg(r.infeasibleStarts)
      .arg(r.evaluations);
}

bool OptimizeDialog::apply() {
  if (!result_ || !result_->status.ok() || !result_->atAfter.feasible) return false;
  commitEdit(doc_, tr("Find Dimensions"), result_->design);
  return true;
}

}  // namespace linkage::ui
