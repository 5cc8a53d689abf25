#include "plots/plots_panel.h"

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QStackedWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "document/document.h"
#include "figures/figure_export.h"
#include "figures/qcp.h"
#include "plots/curve_lists.h"
#include "plots/harmonics_figure.h"
#include "plots/motion_figure.h"
#include "plots/plot_controls.h"

namespace linkage::ui {

namespace {

QString titleOf(const Document* d) {
  const std::string& name = d->design().name;
  return name.empty() ? d->displayName() : QString::fromStdString(name);
}

}  // namespace

PlotsPanel::PlotsPanel(QWidget* parent)
    : DockPanel(Redraw::Throttled, Behind::Works, parent), units_(PlotUnits::fromSettings()) {
  buildWidgets();
  writeControls();
}

PlotsPanel::~PlotsPanel() = default;

void PlotsPanel::buildWidgets() {
  auto* top = new QVBoxLayout(this);
  top->setContentsMargins(4, 4, 4, 4);
  top->setSpacing(3);
  controls_ = new PlotControls;
  top->addWidget(controls_);
  status_ = new QLabel;
  status_->setWordWrap(true);
  status_->setStyleSheet("color: #962020");
  status_->hide();
  top->addWidget(status_);

  auto* split = new QSplitter(Qt::Vertical);
  stack_ = new QStackedWidget;
  plot_ = new QCustomPlot;
  // Tall enough for a title, three rows of plots and the crank-angle axis, none clipped.
  plot_->setMinimumSize(200, 170);
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
  // However long a value, it does not widen the dock (nor the window).
  values_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  extremes_ = new QTreeWidget;
  extremes_->setRootIsDecorated(false);
  extremes_->setMinimumHeight(40);
  extremes_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
  belowLayout->addWidget(values_);
  belowLayout->addWidget(extremes_, 1);
  split->addWidget(below);
  split->setStretchFactor(0, 4);
  split->setStretchFactor(1, 1);
  split->setSizes({640, 160});  // the plots first; the lists take what is left
  top->addWidget(split, 1);

  connect(controls_, &PlotControls::requestChanged, this, &PlotsPanel::setRequest);
  connect(controls_, &PlotControls::unitsChanged, this, &PlotsPanel::setUnits);
  connect(controls_, &PlotControls::compareChanged, this,
          [this](int i) { setCompare(static_cast<Compare>(i)); });
  connect(controls_, &PlotControls::harmonicsToggled, this, &PlotsPanel::setHarmonicsShown);
  connect(controls_, &PlotControls::comparisonTargetChanged, this,
          &PlotsPanel::setComparisonTarget);

  plot_->setInteractions({});  // a drag moves the crank, not the axes
  connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* e) { mouseOnPlot(e, true); });
  connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* e) { mouseOnPlot(e, false); });
  connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent*) { figure_->endDrag(); });
}

// --- what is plotted ------------------------------------------------------------------------

void PlotsPanel::writeControls() {
  const bool others = std::any_of(others_.begin(), others_.end(),
                                  [this](const QPointer<Document>& d) { return d && d != doc_; });
  controls_->display(request_, units_, static_cast<int>(compare_), others, harmonics_);
}

void PlotsPanel::offerTargets() {
  // A target the design no longer has gives way to the default (the first output, else a
  // moving point): every set is stale.
  const Kinematics* k = doc_ && doc_->solved() ? &doc_->kinematics() : nullptr;
  if (controls_->offerTargets(doc_ ? &doc_->design() : nullptr, k, request_))
    for (auto& s : sets_) s.second.reset();
  writeControls();
}

void PlotsPanel::setRequest(const CurveRequest& r) {
  if (r == request_) return;
  request_ = r;
  writeControls();
  for (auto& s : sets_) s.second.reset();
  figureStale_ = true;
  markStale();
}

void PlotsPanel::setUnits(const PlotUnits& u) {
  if (u == units_) return;
  units_ = u;
  units_.toSettings();
  writeControls();
  // The curves are kept in the solver's units: only the figure changes.
  figureStale_ = true;
  if (shown())
    rebuildFigure();
  else
    markStale();
}

void PlotsPanel::setHarmonicsShown(bool on) {
  if (on == harmonics_) return;
  harmonics_ = on;
  writeControls();
  stack_->setCurrentIndex(on ? 1 : 0);
  figureStale_ = true;
  if (shown())
    rebuildFigure();
  else
    markStale();
}

// --- documents ------------------------------------------------------------------------------

void PlotsPanel::setDocument(Document* doc) {
  delete docContext_;
  docContext_ = new QObject(this);
  doc_ = doc;
  controls_->followDesign();
  if (doc) {
    // A design opened in its place plots its own point (issue 26: the last one's, by name).
    connect(doc, &Document::contentsReplaced, docContext_, [this] { controls_->followDesign(); });
    connect(doc, &Document::designChanged, docContext_, [this, doc] {
      offerTargets();
      resample(doc);
    });
    connect(doc, &Document::poseChanged, docContext_, [this] { updateCursor(); });
    connect(doc, &QObject::destroyed, docContext_, [this] { setDocument(nullptr); });
  }
  offerTargets();
  resample(doc);
}

void PlotsPanel::setComparisonDocuments(const QList<Document*>& docs) {
  delete othersContext_;
  othersContext_ = new QObject(this);
  others_.clear();
  for (Document* d : docs) {
    if (!d) continue;
    others_.push_back(d);
    connect(d, &Document::designChanged, othersContext_, [this, d] {
      offerComparisonTargets();
      resample(d);
    });
    connect(d, &QObject::destroyed, othersContext_, [this] { markStale(); });
  }
  writeControls();
  offerComparisonTargets();
  figureStale_ = true;
  markStale();
}

void PlotsPanel::setComparisonTarget(const QString& target) {
  if (target == against_) return;
  against_ = target;
  for (auto& s : sets_)
    if (s.first != doc_) s.second.reset();
  offerComparisonTargets();
  figureStale_ = true;
  markStale();
}

void PlotsPanel::offerComparisonTargets() {
  QStringList labels;
  for (const QPointer<Document>& d : others_) {
    if (!d || d == doc_) continue;
    const Mechanism& m = d->design();
    QStringList points;
    for (PointId p : m.outputs) points << QString::fromStdString(m.pointLabel(p));
    for (const Point& p : m.points) points << QString::fromStdString(m.pointLabel(p.id));
    for (const QString& l : points)
      if (!labels.contains(l)) labels << l;
  }
  controls_->offerComparisonTargets(labels, against_);
}

CurveRequest PlotsPanel::requestFor(const Document* d) const {
  CurveRequest r = request_;
  if (d == doc_ || r.body) return r;
  const Mechanism& m = d->design();
  if (!against_.isEmpty() && m.findPoint(against_.toStdString())) {
    r.target = against_;
  } else if (!m.findPoint(r.target.toStdString())) {
    // No point of that name there: its first output, what that mechanism is about.
    if (!m.outputs.empty()) r.target = QString::fromStdString(m.pointLabel(m.outputs[0]));
  }
  return r;
}

void PlotsPanel::setCompare(Compare c) {
  if (c == compare_) return;
  compare_ = c;
  writeControls();
  figureStale_ = true;
  markStale();
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

std::vector<const CurveSet*> PlotsPanel::shownSets() const {
  std::vector<const CurveSet*> v;
  for (const auto& s : sets_)
    if (s.second) v.push_back(s.second.get());
  return v;
}

const CurveSet* PlotsPanel::curves(int i) const {
  return i >= 0 && i < static_cast<int>(sets_.size()) ? sets_[i].second.get() : nullptr;
}

// --- work -----------------------------------------------------------------------------------

void PlotsPanel::resample(Document* d) {
  // The curves are sampled again; the figure keeps its layout if the new curves fit it
  // (MotionFigure::refresh), which a drag that reshapes the design relies on.
  for (auto& s : sets_)
    if (s.first == d) s.second.reset();
  markStale();
}

void PlotsPanel::cameIntoView() {
  updateCursor();
}

void PlotsPanel::compute() {
  std::vector<std::pair<QPointer<Document>, std::unique_ptr<CurveSet>>> next;
  for (Document* d : shownDocuments()) {
    std::unique_ptr<CurveSet> set;
    for (auto& s : sets_)
      if (s.first == d && s.second) set = std::move(s.second);
    if (!set) {
      set =
          std::make_unique<CurveSet>(d->kinematics(), requestFor(d), titleOf(d), d->solveStatus());
      ++computations_;
    }
    next.emplace_back(d, std::move(set));
  }
  sets_ = std::move(next);
  rebuildFigure();
}

void PlotsPanel::rebuildFigure() {
  const std::vector<const CurveSet*> sets = shownSets();
  QStringList problems;
  if (!doc_)
    problems << "No document.";
  else if (!doc_->solved())
    problems << QString("Not solved: %1. No curves until the design can be solved.")
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
    // The same layout with new values (a drag reshaping the design): the data only.
    if (figureStale_ || !figure_->refresh(sets, o)) figure_->build(sets, o);
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
  if (!shown() || sets_.empty() || !doc_) return;
  CurveSet* main = sets_[0].second.get();
  if (!main) return;
  const double c = doc_->crankDeg(), period = 360.0 * request_.revs;
  // Periodic curves: the revolution window the crank is in; otherwise the angle itself.
  const double x = main->periodic() ? crankInPeriod(c, period) : c;
  if (!harmonics_) figure_->setCursor(x);
  std::vector<CurveSet*> sets;
  for (auto& s : sets_)
    if (s.second) sets.push_back(s.second.get());
  values_->setText(cursorValues(sets, x, units_));
}

QString PlotsPanel::cursorText() const {
  return values_->text();
}

void PlotsPanel::updateExtremes() {
  if (harmonics_)
    listHarmonics(extremes_, shownSets(), units_);
  else
    listExtremes(extremes_, shownSets(), units_);
}

QString PlotsPanel::statusText() const {
  return status_->isHidden() ? QString() : status_->text();
}

QString PlotsPanel::extremesText() const {
  return listText(extremes_, harmonics_);
}

void PlotsPanel::mouseOnPlot(QMouseEvent* e, bool press) {
  if (!(e->buttons() & Qt::LeftButton) || harmonics_) return;
  double deg = figure_->crankDragged(e->position(), press);
  if (std::isnan(deg)) return;
  const CurveSet* main = curves(0);
  double hi = figure_->xMax();
  if (main && !main->empty() && !main->periodic()) hi = std::min(hi, main->lastDeg());
  deg = std::clamp(deg, 0.0, hi);
  // Periodic curves: the angle in the revolution window the crank is in.
  if (doc_ && main && main->periodic()) deg = crankNear(deg, doc_->crankDeg(), figure_->xMax());
  Q_EMIT crankAngleRequested(deg);
}

// --- export ---------------------------------------------------------------------------------

bool PlotsPanel::exportFigure(const QString& path, QSize size, QString* error) {
  ensureComputed();
  if (shownSets().empty()) {
    if (error) *error = "No curves to export: no document is plotted.";
    return false;
  }
  if (harmonics_) return exportPlot(harmonicsPlot_, path, size, error);
  return figure_->exportFigure(path, size, error);
}

}  // namespace linkage::ui
