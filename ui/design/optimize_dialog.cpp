#include "design/optimize_dialog.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
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

#include "design/optimize_targets.h"
#include "document/commands.h"
#include "document/document.h"
#include "document/shown_numbers.h"
#include "linkage/balance.h"
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

// "mm" of "crank.O-A (mm)": what a row measures in; the whole label where it names none.
QString unitInLabel(const QString& what) {
  const qsizetype open = what.lastIndexOf(QLatin1Char('('));
  return open >= 0 && what.endsWith(QLatin1Char(')')) ? what.mid(open) : what;
}

QString unitOf(Dimension::Unit u) {
  return u == Dimension::Unit::Deg  ? QStringLiteral("°")
         : u == Dimension::Unit::Mm ? QStringLiteral("mm")
                                    : QObject::tr("ratio");
}

}  // namespace

OptimizeDialog::OptimizeDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
  setObjectName(QStringLiteral("optimizeDialog"));
  setWindowTitle(tr("Find Dimensions"));
  buildVariables();
  targets_ = new OptimizeTargets(doc_);
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
  for (int c = 1; c < 4; ++c)  // the numbers whole, never elided
    result_table_->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
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
  summary_->setMinimumHeight(2 * summary_->fontMetrics().lineSpacing() + 4);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(new QLabel(tr("Dimensions and counterweights to vary")));
  layout->addWidget(variables_, 2);
  layout->addWidget(new QLabel(tr("Targets")));
  layout->addWidget(targets_, 1);
  layout->addLayout(buildTargetButtons());
  layout->addLayout(row);
  layout->addWidget(result_table_, 2);
  layout->addWidget(summary_);
  layout->addWidget(close);
  resize(720, 760);
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

// Add Target: the first output point's stroke as it is, ready to be typed over (its kind chosen
// in the row); Path Points: a path target from a CSV file; Remove Target: the current row.
QLayout* OptimizeDialog::buildTargetButtons() {
  auto* addTarget = new QPushButton(tr("Add &Target"));
  addTarget->setObjectName(QStringLiteral("optAddTarget"));
  addTarget->setStatusTip(
      tr("A target for the first output point: its stroke as it is now; "
         "choose its kind in the row"));
  auto* addPath = new QPushButton(tr("&Path Points..."));
  addPath->setObjectName(QStringLiteral("optAddPath"));
  addPath->setStatusTip(
      tr("A path target: points x,y (mm; x,y,z in the world on a machine in space) a line from "
         "a CSV file, the first "
         "output point's curve to pass near them"));
  auto* removeTarget = new QPushButton(tr("&Remove Target"));
  connect(addTarget, &QPushButton::clicked, this, [this] {
    const Mechanism& m = doc_->design();
    const QString p =
        !m.outputs.empty() ? QString::fromStdString(m.pointLabel(m.outputs.front())) : QString();
    if (targets_->addRow(OptTarget::Kind::Stroke, p, QString()))
      targets_->setKind(targets_->rowCount() - 1, OptTarget::Kind::Stroke);
  });
  connect(addPath, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Path Points"), QString(),
                                                      tr("Points x,y (*.csv);;All files (*)"));
    const Mechanism& m = doc_->design();
    const QString p =
        !m.outputs.empty() ? QString::fromStdString(m.pointLabel(m.outputs.front())) : QString();
    if (!file.isEmpty()) targets_->addRow(OptTarget::Kind::Path, p, file);
  });
  connect(removeTarget, &QPushButton::clicked, this, [this] {
    if (targets_->currentRow() >= 0) targets_->removeRow(targets_->currentRow());
  });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(addTarget);
  buttons->addWidget(addPath);
  buttons->addWidget(removeTarget);
  buttons->addStretch();
  return buttons;
}

void OptimizeDialog::addVariableRow(int r, const QString& name, const QString& value, double lo,
                                    double hi) {
  auto* vary = new QTableWidgetItem;
  vary->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
  vary->setCheckState(Qt::Unchecked);
  variables_->setItem(r, Vary, vary);
  variables_->setItem(r, Name, fixed(name));
  variables_->setItem(r, Value, fixed(value));
  variables_->setItem(r, Low, new QTableWidgetItem(number(lo)));
  variables_->setItem(r, High, new QTableWidgetItem(number(hi)));
}

// The dimensions' rows again, then two for each body pinned to the ground (its counterweight's
// static moment, x and y in its drawing, 0 as drawn), keeping what was ticked and the bounds
// typed, by name.
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
  const Mechanism& m = doc_->design();
  const std::vector<Dimension> dims = dimensions(m);
  std::vector<std::string> weights;
  for (const Body& b : m.bodies)
    if (Counterweight c; !b.ground && counterweightOn(m, b.id, c).ok())
      for (const char* axis : {".counterweight.x", ".counterweight.y"})
        weights.push_back(b.name + axis);
  variables_->setRowCount(static_cast<int>(dims.size() + weights.size()));
  int r = 0;
  for (const Dimension& d : dims) {
    const double span =
        std::max(0.1 * std::abs(d.value), d.unit == Dimension::Unit::Deg ? 5.0 : 1.0);
    addVariableRow(r++, QString::fromStdString(d.name),
                   number(d.value) + QStringLiteral(" ") + unitOf(d.unit), d.value - span,
                   d.value + span);
  }
  for (const std::string& w : weights)
    addVariableRow(r++, QString::fromStdString(w), tr("0 kg mm"), -50, 50);
  for (r = 0; r < variables_->rowCount(); ++r)
    if (const auto k = kept.find(variables_->item(r, Name)->text()); k != kept.end()) {
      variables_->item(r, Vary)->setCheckState(k->second.vary ? Qt::Checked : Qt::Unchecked);
      variables_->item(r, Low)->setText(k->second.lo);
      variables_->item(r, High)->setText(k->second.hi);
    }
  targets_->refreshChoices();
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
  return addTarget(OptTarget::Kind::Stroke, QString::fromStdString(point), number(strokeMm));
}

bool OptimizeDialog::addPositionTarget(const std::string& point, double crankDeg, Vec2 at) {
  return addTarget(OptTarget::Kind::Position, QString::fromStdString(point),
                   QStringLiteral("%1, %2").arg(number(at.x()), number(at.y())), crankDeg);
}

bool OptimizeDialog::addTarget(OptTarget::Kind kind, const QString& of, const QString& value,
                               double crankDeg, double weight) {
  return !of.isEmpty() && targets_->addRow(kind, of, value, crankDeg, weight);
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
  if (!targets_->read(spec.targets, why)) return false;
  if (spec.variables.empty() || spec.targets.empty())
    return *why = tr("Tick a dimension or a counterweight to vary and add a target"), false;
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
  spec_ = spec;
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

// Each variable with its unit, each target's measures (design/optimize_targets.h), each
// counterweight's mass, the objective: before and after.
void OptimizeDialog::showResult() {
  const OptimizeResult& r = *result_;
  result_table_->setRowCount(0);
  if (!r.status.ok()) {
    summary_->setText(QString::fromStdString(r.status.message));
    return;
  }
  std::vector<MeasureRow> rows;
  auto add = [&rows](const QString& what, double before, double after, const QString& target) {
    rows.push_back({what, before, after, target});
  };
  const Mechanism& m = doc_->design();
  std::map<std::string, Dimension::Unit> units;
  for (const Dimension& d : dimensions(m)) units[d.name] = d.unit;
  for (size_t i = 0; i < r.before.size() && i < spec_.variables.size(); ++i) {
    const std::string& name = spec_.variables[i].name;
    const auto u = units.find(name);
    add(QStringLiteral("%1 (%2)").arg(QString::fromStdString(name),
                                      u != units.end() ? unitOf(u->second) : tr("kg mm")),
        r.before[i], r.after[i], QString());
  }
  for (size_t t = 0; t < spec_.targets.size() && t < r.atAfter.measures.size(); ++t) {
    const Measure& b = r.atBefore.measures.size() > t ? r.atBefore.measures[t] : Measure{};
    for (const MeasureRow& row : measureRows(m, spec_.targets[t], b, r.atAfter.measures[t]))
      add(row.what, row.before, row.after, row.target);
  }
  for (const Counterweight& c : r.counterweights)
    add(tr("counterweight on %1 (kg, at %2 mm)")
            .arg(QString::fromStdString(m.body(c.body) ? m.body(c.body)->name : std::string()))
            .arg(number(c.radiusMm())),
        0, c.kg, QString());
  add(tr("objective (weighted sum of squares)"), r.atBefore.objective, r.atAfter.objective,
      QStringLiteral("0"));
  showRows(rows);
  summary_->setText(resultSummary());
  apply_->setEnabled(r.atAfter.feasible);
}

// The rows' numbers for people (document/shown_numbers.h resultText): each next to the largest
// of its quantity's unit (as its label ends) before and after; the columns as wide as they are.
void OptimizeDialog::showRows(const std::vector<MeasureRow>& rows) {
  std::map<QString, double> scale;
  for (const MeasureRow& row : rows) {
    double& s = scale[unitInLabel(row.what)];
    for (double v : {row.before, row.after})
      if (std::isfinite(v)) s = std::max(s, std::abs(v));
  }
  for (const MeasureRow& row : rows) {
    const double s = scale[unitInLabel(row.what)];
    const int r = result_table_->rowCount();
    result_table_->insertRow(r);
    result_table_->setItem(r, 0, fixed(row.what));
    result_table_->setItem(r, 1, fixed(resultText(row.before, s)));
    result_table_->setItem(r, 2, fixed(resultText(row.after, s)));
    result_table_->setItem(r, 3, fixed(row.target));
  }
}

QString OptimizeDialog::summary() const {
  return summary_->text();
}

QString OptimizeDialog::resultSummary() const {
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

namespace linkage::ui {

QStringList OptimizeDialog::probeLines() const {
  QStringList out;
  out << QStringLiteral("optimize summary: ") + summary_->text().simplified();
  for (const QPushButton* b : findChildren<QPushButton*>()) {
    if (b->objectName().isEmpty() || !b->isVisible()) continue;
    const QPoint c = b->mapToGlobal(b->rect().center());
    out << QStringLiteral("at optimize button %1: %2 %3 %4")
               .arg(b->objectName())
               .arg(c.x())
               .arg(c.y())
               .arg(b->isEnabled() ? "enabled" : "disabled");
  }
  // The Vary boxes of the rows in sight (a script scrolls to the others).
  const QRect seen = variables_->viewport()->rect();
  for (int r = 0; r < variables_->rowCount(); ++r) {
    const QRect cell = variables_->visualItemRect(variables_->item(r, Vary));
    const QString name = variables_->item(r, Name)->text();
    out << QStringLiteral("optimize vary %1: %2")
               .arg(name)
               .arg(variables_->item(r, Vary)->checkState() == Qt::Checked ? 1 : 0);
    if (!seen.contains(cell.center())) continue;
    // The box at the cell's left, where a click ticks it.
    const QPoint c =
        variables_->viewport()->mapToGlobal(QPoint(cell.left() + 10, cell.center().y()));
    out << QStringLiteral("at optimize vary %1: %2 %3").arg(name).arg(c.x()).arg(c.y());
  }
  out << targets_->probeLines();
  for (int r = 0; r < result_table_->rowCount(); ++r) {
    QStringList cells;
    for (int c = 0; c < result_table_->columnCount(); ++c)
      cells << (result_table_->item(r, c) ? result_table_->item(r, c)->text() : QString());
    out << QStringLiteral("optimize result: ") + cells.join(QStringLiteral(" | "));
  }
  return out;
}

}  // namespace linkage::ui
