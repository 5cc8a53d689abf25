#include "design/study_dialog.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

#include "design/study_plots.h"
#include "design/study_runner.h"
#include "design/study_table_model.h"
#include "document/document.h"
#include "linkage/io/atomic_file.h"
#include "linkage/io/numbers.h"
#include "linkage/tables/study_table.h"

namespace linkage::ui {

namespace {

// A number as the command line reads it (locale-independent): `field` names it in the reason.
bool readNumber(const QLineEdit* e, const QString& field, double& out, QString* why) {
  const std::optional<double> v = parseNumber(e->text().trimmed().toStdString());
  if (!v) {
    *why = QObject::tr("%1: \"%2\" is not a number").arg(field, e->text());
    return false;
  }
  out = *v;
  return true;
}

// "X,Y" as the command line reads it.
bool readPair(const QLineEdit* e, const QString& field, Vec2& out, QString* why) {
  const QStringList xy = e->text().split(',');
  std::optional<double> x, y;
  if (xy.size() == 2) {
    x = parseNumber(xy[0].trimmed().toStdString());
    y = parseNumber(xy[1].trimmed().toStdString());
  }
  if (!x || !y) {
    *why = QObject::tr("%1: \"%2\" is not two numbers X, Y").arg(field, e->text());
    return false;
  }
  out = Vec2(*x, *y);
  return true;
}

QString variants(int n) {
  return n == 1 ? QObject::tr("1 variant") : QObject::tr("%1 variants").arg(n);
}

}  // namespace

StudyDialog::StudyDialog(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
  setWindowTitle(tr("Parameter Study"));
  setModal(false);
  runner_ = new StudyRunner(this);
  model_ = new StudyTableModel(this);
  buildForm();
  connect(runner_, &StudyRunner::progress, this, [this](int done, int total) {
    progress_->setMaximum(total);
    progress_->setValue(done);
  });
  connect(runner_, &StudyRunner::finished, this, &StudyDialog::finished);
  if (doc_) connect(doc_, &Document::designChanged, this, &StudyDialog::offerPoints);
  offerPoints();
  resize(1180, 760);
}

StudyDialog::~StudyDialog() {
  // The run stops (and its threads are joined) while the dialog its signals go to is whole.
  delete runner_;
}

void StudyDialog::buildForm() {
  createFields();
  QFormLayout* form = fieldsForm();
  kindChanged();
  QHBoxLayout* buttons = runButtons();
  QWidget* left = formSide(form, buttons);
  QWidget* right = resultsSide();
  auto* split = new QSplitter;
  split->addWidget(left);
  split->addWidget(right);
  split->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(split);
}

void StudyDialog::createFields() {
  move_ = new QComboBox;
  move_->setToolTip(
      tr("The design point moved; the points pinned to it where they are drawn "
         "together move with it"));
  kind_ = new QComboBox;
  kind_->addItem(tr("Along a line"));
  kind_->addItem(tr("On an arc"));
  by_ = new QLineEdit(QStringLiteral("1, 0"));
  by_->setToolTip(tr("Moved by t \u00d7 (DX, DY) mm"));
  about_ = new QLineEdit;
  about_->setPlaceholderText(tr("X, Y"));
  about_->setToolTip(tr("The centre of the arc, mm"));
  angle_ = new QLineEdit(QStringLiteral("1"));
  angle_->setToolTip(tr("Turned by t \u00d7 DEG degrees counter-clockwise"));
  from_ = new QLineEdit(QStringLiteral("0"));
  to_ = new QLineEdit(QStringLiteral("1"));
  values_ = new QSpinBox;
  values_->setRange(1, 100000);
  values_->setValue(11);
  values_->setToolTip(tr("Values of t, both ends included"));
  point_ = new QComboBox;
  point_->setToolTip(tr("The point whose stroke, extremes, peaks and path are measured"));
  direction_ = new QLineEdit;
  direction_->setPlaceholderText(tr("default: its slot, else +y"));
  bodies_ = new QListWidget;
  bodies_->setToolTip(tr("Bodies whose swing (largest minus smallest angle) is measured"));
  bodies_->setMaximumHeight(90);
  steps_ = new QSpinBox;
  steps_->setRange(4, 1000000);
  steps_->setValue(360);
  steps_->setToolTip(tr("Samples per turn of the crank"));
  connect(kind_, &QComboBox::currentIndexChanged, this, &StudyDialog::kindChanged);
}

QFormLayout* StudyDialog::fieldsForm() {
  auto* form = new QFormLayout;
  form->addRow(tr("Move point"), move_);
  form->addRow(tr("How"), kind_);
  form->addRow(tr("By DX, DY [mm]"), by_);
  form->addRow(tr("About X, Y [mm]"), about_);
  form->addRow(tr("By DEG [\u00b0]"), angle_);
  form->addRow(tr("t from"), from_);
  form->addRow(tr("t to"), to_);
  form->addRow(tr("Values"), values_);
  form->addRow(tr("Measure point"), point_);
  form->addRow(tr("Along DX, DY"), direction_);
  form->addRow(tr("Swing of"), bodies_);
  form->addRow(tr("Crank steps"), steps_);
  return form;
}

QHBoxLayout* StudyDialog::runButtons() {
  runButton_ = new QPushButton(tr("&Run"));
  runButton_->setDefault(true);
  cancelButton_ = new QPushButton(tr("&Cancel Run"));
  cancelButton_->setEnabled(false);
  exportButton_ = new QPushButton(tr("&Export CSV..."));
  exportButton_->setEnabled(false);
  connect(runButton_, &QPushButton::clicked, this, &StudyDialog::run);
  connect(cancelButton_, &QPushButton::clicked, this, &StudyDialog::cancel);
  connect(exportButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Study Table"), QString(),
                                                      tr("CSV files (*.csv);;All files (*)"));
    QString why;
    if (!path.isEmpty() && !exportCsv(path, &why))
      QMessageBox::warning(this, tr("Export Study Table"), why);
  });
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(runButton_);
  buttons->addWidget(cancelButton_);
  buttons->addWidget(exportButton_);
  return buttons;
}

QWidget* StudyDialog::formSide(QFormLayout* form, QHBoxLayout* buttons) {
  progress_ = new QProgressBar;
  progress_->setValue(0);
  status_ = new QLabel;
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* close = new QDialogButtonBox(QDialogButtonBox::Close);
  connect(close, &QDialogButtonBox::rejected, this, &QDialog::close);

  auto* left = new QWidget;
  auto* l = new QVBoxLayout(left);
  l->addLayout(form);
  l->addLayout(buttons);
  l->addWidget(progress_);
  l->addWidget(status_);
  l->addStretch();
  l->addWidget(close);
  return left;
}

QWidget* StudyDialog::resultsSide() {
  table_ = new QTableView;
  table_->setModel(model_);
  table_->verticalHeader()->setDefaultSectionSize(20);
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  plots_ = new StudyPlots;
  auto* right = new QSplitter(Qt::Vertical);
  right->addWidget(table_);
  right->addWidget(plots_);
  right->setStretchFactor(0, 2);
  right->setStretchFactor(1, 3);
  return right;
}

void StudyDialog::kindChanged() {
  const bool line = kind_->currentIndex() == 0;
  by_->setEnabled(line);
  about_->setEnabled(!line);
  angle_->setEnabled(!line);
}

void StudyDialog::offerPoints() {
  // The same choices by name after an edit.
  const QString move = move_->currentText(), point = point_->currentText();
  QStringList checked;
  for (int i = 0; i < bodies_->count(); ++i)
    if (bodies_->item(i)->checkState() == Qt::Checked) checked << bodies_->item(i)->text();
  move_->clear();
  point_->clear();
  bodies_->clear();
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  for (PointId p : m.outputs) point_->addItem(QString::fromStdString(m.pointLabel(p)));
  for (const Point& p : m.points) {
    const QString label = QString::fromStdString(m.pointLabel(p.id));
    move_->addItem(label);
    if (point_->findText(label) < 0) point_->addItem(label);
  }
  for (const Body& b : m.bodies) {
    if (b.ground) continue;
    auto* item = new QListWidgetItem(QString::fromStdString(b.name), bodies_);
    item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
    item->setCheckState(checked.contains(item->text()) ? Qt::Checked : Qt::Unchecked);
  }
  if (move_->findText(move) >= 0) move_->setCurrentIndex(move_->findText(move));
  if (point_->findText(point) >= 0) point_->setCurrentIndex(point_->findText(point));
}

bool StudyDialog::readSpec(StudySpec& spec, QString* why) const {
  if (!doc_) return false;
  const Mechanism& m = doc_->design();
  spec = StudySpec{};
  const std::optional<PointId> move = m.findPoint(move_->currentText().toStdString());
  const std::optional<PointId> point = m.findPoint(point_->currentText().toStdString());
  if (!move || !point) {
    *why = tr("Choose the point to move and the point to measure.");
    return false;
  }
  spec.move.point = *move;
  if (kind_->currentIndex() == 0) {
    if (!readPair(by_, tr("By"), spec.move.by, why)) return false;
  } else {
    spec.move.kind = PointMove::Kind::Arc;
    if (!readPair(about_, tr("About"), spec.move.centre, why) ||
        !readNumber(angle_, tr("By DEG"), spec.move.angleDeg, why))
      return false;
  }
  if (!readNumber(from_, tr("t from"), spec.from, why) ||
      !readNumber(to_, tr("t to"), spec.to, why))
    return false;
  spec.values = values_->value();
  spec.point = *point;
  if (!direction_->text().trimmed().isEmpty()) {
    Vec2 d;
    if (!readPair(direction_, tr("Along"), d, why)) return false;
    if (d == Vec2::Zero()) {
      *why = tr("Along: the direction must not be 0, 0");
      return false;
    }
    spec.direction = d;
  }
  for (int i = 0; i < bodies_->count(); ++i)
    if (bodies_->item(i)->checkState() == Qt::Checked)
      spec.bodies.push_back(m.bodyNamed(bodies_->item(i)->text().toStdString())->id);
  spec.steps = steps_->value();
  spec.keepPaths = true;
  return true;
}

bool StudyDialog::run() {
  if (runner_->running()) return false;
  StudySpec spec;
  QString why;
  if (!readSpec(spec, &why)) {
    showStatus(why, true);
    return false;
  }
  if (!doc_->design().driver) {
    showStatus(tr("The mechanism has no driver: nothing turns."), true);
    return false;
  }
  model_->clear();
  plots_->clear();
  exportButton_->setEnabled(false);
  progress_->setRange(0, spec.values);
  progress_->setValue(0);
  showStatus(tr("Running %1...").arg(variants(spec.values)), false);
  runner_->start(doc_->design(), spec);
  setRunning(true);
  return true;
}

void StudyDialog::cancel() {
  runner_->cancel();
}

void StudyDialog::setRunning(bool on) {
  runButton_->setEnabled(!on);
  cancelButton_->setEnabled(on);
}

void StudyDialog::showStatus(const QString& text, bool warning) {
  status_->setText(text);
  QPalette p = status_->palette();
  p.setColor(QPalette::WindowText,
             warning ? QColor(200, 30, 20) : palette().color(QPalette::WindowText));
  status_->setPalette(p);
}

QString StudyDialog::statusText() const {
  return status_->text();
}

void StudyDialog::finished() {
  setRunning(false);
  const Study& s = runner_->study();
  if (!s.status.ok()) {
    showStatus(QString::fromStdString(s.status.message), true);
    emit runEnded();
    return;
  }
  model_->setStudy(runner_->mechanism(), runner_->spec(), s);
  plots_->setStudy(runner_->mechanism(), runner_->spec(), s, model_);
  exportButton_->setEnabled(!s.rows.empty());
  int locked = 0;
  for (const StudyRow& r : s.rows) locked += !r.turns;
  QString text = runner_->cancelled()
                     ? tr("Cancelled: %1 of %2 variants computed.")
                           .arg(s.rows.size())
                           .arg(runner_->spec().values)
                     : tr("%1 computed.").arg(variants(static_cast<int>(s.rows.size())));
  if (locked > 0)
    text +=
        tr(" In %1 of them the crank does not turn fully (lock_deg: where it stops).").arg(locked);
  showStatus(text, locked > 0);
  emit runEnded();
}

bool StudyDialog::exportCsv(const QString& path, QString* error) const {
  if (runner_->running() || runner_->study().rows.empty()) {
    if (error) *error = tr("There is no finished study to export.");
    return false;
  }
  const WriteResult w = writeFileAtomically(
      path.toStdString(), studyTableCsv(runner_->mechanism(), runner_->spec(), runner_->study()));
  if (!w.ok && error) *error = QString::fromStdString(w.error);
  return w.ok;
}

void StudyDialog::closeEvent(QCloseEvent* e) {
  // A run does not outlive the dialog's view of it: closing cancels it.
  runner_->cancel();
  QDialog::closeEvent(e);
}

}  // namespace linkage::ui
