#include "forces/forces_panel.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QScrollArea>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "document/document.h"
#include "document/file_folder.h"
#include "document/shown_numbers.h"
#include "export/table_size_dialog.h"
#include "figures/qcp.h"
#include "figures/units.h"
#include "forces/force_plots.h"
#include "forces/force_table_export.h"
#include "linkage/elements.h"

namespace linkage::ui {

namespace {

// "pin:rod.B": a joint as the force table's columns name it.
QString jointName(const Mechanism& m, const Joint& j) {
  return QString("%1:%2").arg(kindOf(j).name, QString::fromStdString(m.pointLabel(j.a)));
}

bool anyMassOrLoad(const Mechanism& m) {
  if (!m.loads.empty()) return true;
  return std::any_of(m.bodies.begin(), m.bodies.end(), [](const Body& b) {
    return !b.ground && b.mass && (b.mass->kg > 0 || b.mass->jKgMm2 > 0);
  });
}

QString number(double v) {
  return QString::number(v, 'g', 5);
}

}  // namespace

ForcesPanel::ForcesPanel(Document* doc, QWidget* parent)
    : DockPanel(Redraw::Throttled, Behind::Works, parent), doc_(doc) {
  buildWidgets();
  if (doc) {
    connect(doc, &Document::designChanged, this, [this] {
      offerJoints();
      markStale();
    });
    connect(doc, &Document::poseChanged, this, &ForcesPanel::updateCursor);
    connect(doc, &QObject::destroyed, this, [this] { markStale(); });
  }
  offerJoints();
}

ForcesPanel::~ForcesPanel() = default;

void ForcesPanel::buildWidgets() {
  auto* top = new QVBoxLayout(this);
  top->setContentsMargins(4, 4, 4, 4);
  top->setSpacing(3);
  auto* row = new QHBoxLayout;
  auto* jointLabel = new QLabel(tr("Reaction at &joint:"));
  joints_ = new QComboBox;
  joints_->setToolTip(
      tr("The joint whose reaction is plotted: the force on the body of its first point"));
  joints_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  jointLabel->setBuddy(joints_);
  values_ = new QLabel;
  values_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  values_->setWordWrap(true);
  values_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  row->addWidget(jointLabel);
  row->addWidget(joints_);
  row->addSpacing(12);
  row->addWidget(values_, 1);
  top->addLayout(row);

  stack_ = new QStackedWidget;
  plot_ = new QCustomPlot;
  plot_->setMinimumSize(240, 160);
  plot_->setCursor(Qt::CrossCursor);
  plot_->setInteractions({});  // a drag turns the crank, not the axes
  figure_ = std::make_unique<ForceFigure>(plot_);
  sentence_ = new QLabel;
  sentence_->setWordWrap(true);
  sentence_->setAlignment(Qt::AlignCenter);
  sentence_->setMargin(16);
  sentence_->setStyleSheet("color: #962020");
  // In a low dock the plots keep a height to read (ForceFigure::leastHeightFor) and the dock
  // scrolls: at 1280 x 800 they were 40 px high, the polar diagram a flat strip.
  scroll_ = new QScrollArea;
  scroll_->setWidget(plot_);
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  stack_->addWidget(scroll_);
  stack_->addWidget(sentence_);
  top->addWidget(stack_, 1);

  connect(joints_, &QComboBox::activated, this, [this](int i) { setJoint(i); });
  connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) { mouseOnPlot(e, true); });
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) { mouseOnPlot(e, false); });
  connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent*) { figure_->endDrag(); });
}

// --- the joint ------------------------------------------------------------------------------

void ForcesPanel::offerJoints() {
  const QSignalBlocker block(joints_);
  joints_->clear();
  if (!doc_) return;
  const Mechanism& m = doc_->design();
  for (const Joint& j : m.joints) joints_->addItem(jointName(m, j));
  int at = joints_->findText(jointName_);
  if (at < 0 && joints_->count() > 0) at = 0;
  joints_->setCurrentIndex(at);
  jointName_ = joints_->currentText();
}

void ForcesPanel::setJoint(int index) {
  if (index < 0 || index >= joints_->count()) index = -1;
  joints_->setCurrentIndex(index);
  const QString name = joints_->currentText();
  if (name == jointName_ && !stale()) return;
  jointName_ = name;
  // The samples hold every joint's reaction: only the figure changes.
  if (shown() && !stale()) rebuildFigure();
}

int ForcesPanel::joint() const {
  return joints_->currentIndex();
}

// --- work -----------------------------------------------------------------------------------

void ForcesPanel::cameIntoView() {
  updateCursor();
}

void ForcesPanel::resizeEvent(QResizeEvent* e) {
  QWidget::resizeEvent(e);
  // A row of plots in a wide low dock, two by two in a squarer one: laid out again when that
  // changes.
  if (!stale() && samples() && ForceFigure::columnsFor(room()) != figure_->columns())
    rebuildFigure();
}

QSize ForcesPanel::room() const {
  // The scroll area's, less the panel's other rows once it is laid out; the panel's before.
  const QSize view = scroll_->maximumViewportSize();
  return view.isValid() && view.height() > 0 ? view : size();
}

QString ForcesPanel::whyNoForces() const {
  if (!doc_) return tr("No document.");
  if (!doc_->solved())
    return tr("The design is not solved (%1): no forces are shown.")
        .arg(QString::fromStdString(doc_->solveStatus().message));
  if (Status s = doc_->motionStatus(); !s.ok())
    return tr("No forces: %1; forces are those of a motion the driver determines.")
        .arg(QString::fromStdString(s.message));
  if (!anyMassOrLoad(doc_->design()))
    return tr("No masses or loads: the forces are all zero; give bodies masses in Properties.");
  return {};
}

void ForcesPanel::compute() {
  samples_ = ForceSamples{};
  why_ = whyNoForces();
  if (why_.isEmpty()) {
    Kinematics k = doc_->kinematics();  // the document's pose and branch; not moved
    k.setAccelerations(true);
    samples_ = sampleForces(k);
    ++computations_;
    if (samples_.size() == 0)
      why_ = tr("No forces: %1.").arg(QString::fromStdString(samples_.status.message));
    forceScale_ = samples_.inSpace ? peakOf(samples_.shaking3N) : peakOf(samples_.shakingN);
    for (const std::vector<Vec2>& r : samples_.reactionN)
      forceScale_ = std::max(forceScale_, peakOf(r));
    for (const std::vector<Vec3>& r : samples_.reaction3N)
      forceScale_ = std::max(forceScale_, peakOf(r));
    torqueScale_ = std::max(peakOf(samples_.driverTorqueNm), forceScale_ * k.size() * 1e-3);
    if (why_.isEmpty()) why_ = beyondThePlots();
  }
  rebuildFigure();
}

QString ForcesPanel::beyondThePlots() const {
  // QCustomPlot takes no axis range past 1e250 (QCPRange::maxRange): forces of a load of 1e300
  // N filled the plots solid, and a scale that overflowed made every value read 0. Such forces
  // are said in numbers instead; the force table has each of them.
  const double kDrawable = QCPRange::maxRange * 1e-3;
  if (forceScale_ <= kDrawable && peakOf(samples_.driverTorqueNm) <= kDrawable) return {};
  return tr("The forces reach %1 N and the driver's torque %2 N m: too large to plot (beyond "
            "%3); File > Export > Force Table writes every value.")
      .arg(number(forceScale_), number(peakOf(samples_.driverTorqueNm)), number(kDrawable));
}

const ForceSamples* ForcesPanel::samples() const {
  return why_.isEmpty() && samples_.size() > 0 ? &samples_ : nullptr;
}

QString ForcesPanel::message() const {
  return why_;
}

void ForcesPanel::rebuildFigure() {
  if (!samples()) {
    figure_->clear();
    plot_->replot();
    sentence_->setText(why_);
    stack_->setCurrentWidget(sentence_);
    values_->clear();
    return;
  }
  stack_->setCurrentWidget(scroll_);
  const Mechanism& m = doc_->design();
  ForceFigure::JointChoice choice;
  choice.index = joint();
  if (choice.index >= 0 && choice.index < static_cast<int>(m.joints.size())) {
    const Joint& j = m.joints[choice.index];
    choice.label = jointName(m, j);
    if (const Point* a = m.point(j.a))
      if (const Body* b = m.body(a->body)) choice.bodyName = QString::fromStdString(b->name);
    choice.undetermined = std::find(samples_.undetermined.begin(), samples_.undetermined.end(),
                                    j.id) != samples_.undetermined.end();
    if (samples_.inSpace) choice.shape = spaceReactionOf(m, j);
  } else {
    choice.index = -1;
  }
  QString stop;
  if (!samples_.complete)
    stop = tr("Ends at %1°: %2")
               .arg(samples_.crankDeg.back(), 0, 'f', 1)
               .arg(QString::fromStdString(samples_.status.message));
  figure_->setLayoutSize(exportSize_.isEmpty() ? room() : exportSize_);
  figure_->build(samples_, crankAxisLabel(m), briefCrankAxisLabel(m), choice, stop,
                 doc_->kinematics().size());
  if (exportSize_.isEmpty())
    plot_->setMinimumHeight(ForceFigure::leastHeightFor(figure_->columns()));
  updateCursor();
}

void ForcesPanel::updateCursor() {
  if (!shown() || !doc_ || !samples()) return;
  const double c = doc_->crankDeg();
  figure_->setCursor(crankInPeriod(c, 360));
  // The values at the pose exactly, not read off the curves: a solver of its own on a copy (a
  // solver works on the kinematics it was prepared with; about as long as a kinematic step).
  Kinematics k = doc_->kinematics();
  k.setAccelerations(true);
  const Forces f = computeForces(k);
  if (!f.status.ok()) {
    values_->setText(tr("At %1°: no forces (%2)")
                         .arg(c, 0, 'f', 1)
                         .arg(QString::fromStdString(f.status.message)));
    return;
  }
  if (samples_.inSpace) return values_->setText(valuesInSpace(c, k, f));
  auto force = [this](double v) { return number(cleaned(v, forceScale_)); };
  QString text = tr("At %1°: torque %2 N m; shaking force (%3, %4) N, |F| %5 N")
                     .arg(c, 0, 'f', 1)
                     .arg(number(cleaned(f.driverTorqueNm, torqueScale_)),
                          force(f.shakingForceN.x()), force(f.shakingForceN.y()),
                          force(std::hypot(f.shakingForceN.x(), f.shakingForceN.y())));
  const int j = joint();
  const bool undetermined =
      j >= 0 && j < static_cast<int>(f.joints.size()) && !std::isfinite(f.joints[j].force.x());
  if (j >= 0 && j < static_cast<int>(f.joints.size()) && !undetermined)
    text +=
        tr("; %1 (%2, %3) N")
            .arg(joints_->itemText(j), force(f.joints[j].force.x()), force(f.joints[j].force.y()));
  values_->setText(text);
}

// The values at the pose on a machine in space: in the world's axes, as the plots draw them; a
// joint in a plane with what its bearing takes about the plane's axes, a rod's tension, a bevel
// pair's couple.
QString ForcesPanel::valuesInSpace(double deg, const Kinematics& k, const Forces& f) const {
  auto force = [this](double v) { return number(cleaned(v, forceScale_)); };
  const Vec3& F = f.shakingForce3N;
  QString text = tr("At %1°, world axes: torque %2 N m; shaking force (%3, %4, %5) N, |F| %6 N")
                     .arg(deg, 0, 'f', 1)
                     .arg(number(cleaned(f.driverTorqueNm, torqueScale_)), force(F.x()),
                          force(F.y()), force(F.z()), force(std::hypot(F.x(), F.y(), F.z())));
  const int j = joint();
  if (j < 0 || j >= static_cast<int>(f.joints.size())) return text;
  const JointReaction& r = f.joints[j];
  Vec3 w;
  double scalar;
  reactionInSpace(k, j, r, w, scalar);
  const QString name = joints_->itemText(j);
  switch (spaceReactionOf(k.mechanism(), k.mechanism().joints[j])) {
    case SpaceReaction::Tension:
      if (std::isfinite(scalar)) text += tr("; %1 tension %2 N").arg(name, force(scalar));
      break;
    case SpaceReaction::Couple:
      if (std::isfinite(scalar))
        text += tr("; %1 couple %2 N m").arg(name, number(cleaned(scalar, torqueScale_)));
      break;
    case SpaceReaction::Force:
      if (!w.allFinite()) break;
      text += tr("; %1 (%2, %3, %4) N").arg(name, force(w.x()), force(w.y()), force(w.z()));
      if (r.tiltNm.allFinite() && r.tiltNm != Vec2::Zero())
        text += tr(", about its plane's x and y %1, %2 N m")
                    .arg(number(cleaned(r.tiltNm.x(), torqueScale_)),
                         number(cleaned(r.tiltNm.y(), torqueScale_)));
      break;
  }
  return text;
}

QString ForcesPanel::cursorText() const {
  return values_->text();
}

void ForcesPanel::mouseOnPlot(QMouseEvent* e, bool press) {
  if (!(e->buttons() & Qt::LeftButton) || !samples()) return;
  const double deg = figure_->crankDragged(e->position(), press);
  if (std::isnan(deg)) return;
  const double hi = samples_.complete ? 360.0 : samples_.crankDeg.back();
  Q_EMIT crankAngleRequested(
      crankNear(std::clamp(deg, 0.0, hi), doc_ ? doc_->crankDeg() : 0.0, 360));
}

// --- export ---------------------------------------------------------------------------------

bool ForcesPanel::exportFigure(const QString& path, QSize size, QString* error) {
  ensureComputed();
  if (!samples()) {
    if (error) *error = why_.isEmpty() ? tr("No forces to export.") : why_;
    return false;
  }
  // Laid out for the figure's size (one row of plots in a wide one), then back as shown.
  const bool relayout = ForceFigure::columnsFor(size) != figure_->columns();
  if (relayout) {
    exportSize_ = size;
    rebuildFigure();
  }
  const bool ok = figure_->exportFigure(path, size, error);
  if (relayout) {
    exportSize_ = QSize();
    rebuildFigure();
  }
  return ok;
}

bool ForcesPanel::exportTable(const QString& path, long long steps, double revs, QString* error) {
  if (!doc_) {
    if (error) *error = tr("No document.");
    return false;
  }
  return exportForceTable(*doc_, path, steps, revs, error);
}

// --- the window's actions -------------------------------------------------------------------

void ForcesPanel::saveFigureAs() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Force Figure"), suggestedFile(doc_, QStringLiteral("-forces.svg")),
      tr("SVG (*.svg);;PDF (*.pdf);;PNG (*.png)"));
  if (path.isEmpty()) return;
  QString why;
  if (!exportFigure(path, QSize(1600, 700), &why))
    QMessageBox::warning(this, tr("Export Force Figure"), why);
}

void ForcesPanel::saveTableAs() {
  TableSize size;
  if (!askTableSize(this, tr("Export Force Table"), &size)) return;
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export Force Table"), suggestedFile(doc_, QStringLiteral("-forces.csv")),
      tr("CSV tables (*.csv)"));
  if (path.isEmpty()) return;
  QString why;
  if (!exportTable(path, size.stepsPerRev, size.revs, &why))
    QMessageBox::warning(this, tr("Export Force Table"), why);
}

}  // namespace linkage::ui
