#include "design/sensitivity_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QTabWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <memory>

#include "design/tolerance_view.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/clearance_sensitivity.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/force_sensitivity.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/transmission_sensitivity.h"
#include "linkage/window_sensitivity.h"

namespace linkage::ui {

namespace {

constexpr int kShown = 12;          // bars drawn; the rest counted under the chart
constexpr double kCycleStep = 5;    // degrees between the turn's samples
constexpr int kStroke = 3;          // the quantity: the stroke (linkage/stroke_sensitivity.h)
constexpr int kLength = 2, kZ = 3;  // the components: x, y, the length of the change, z

// The chosen quantity's derivative in the world (a planar machine's z is 0): a component of it,
// or the length of the move.
double component(const Sensitivity& s, const Kinematics& k, PointId p, int dim, int quantity,
                 int which) {
  const Vec3 v = quantity == 0   ? s.point3(k, p, dim)
                 : quantity == 1 ? s.velocity3(k, p, dim)
                                 : s.acceleration3(k, p, dim);
  return which == kLength ? v.norm() : v[which == kZ ? 2 : which];
}

}  // namespace

SensitivityPanel::SensitivityPanel(Document* doc, QWidget* parent)
    : DockPanel(Redraw::Throttled, Behind::Rests, parent), doc_(doc) {
  setObjectName(QStringLiteral("sensitivityPanel"));
  point_ = new QComboBox;
  point_->setObjectName(QStringLiteral("sensPoint"));
  quantity_ = new QComboBox;
  quantity_->setObjectName(QStringLiteral("sensQuantity"));
  quantity_->addItems({tr("position"), tr("velocity"), tr("acceleration"), tr("stroke")});
  component_ = new QComboBox;
  component_->setObjectName(QStringLiteral("sensComponent"));
  component_->addItems({tr("x"), tr("y"), tr("length of the change")});
  component_->setCurrentIndex(1);
  for (QComboBox* c : {point_, quantity_, component_})
    connect(c, &QComboBox::activated, this, [this] { markStale(); });
  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Output:")));
  top->addWidget(point_, 2);
  top->addWidget(quantity_, 1);
  top->addWidget(component_, 1);
  plot_ = new QCustomPlot;
  plot_->setObjectName(QStringLiteral("sensPlot"));
  plot_->setMinimumHeight(220);
  summary_ = new QLabel;
  summary_->setObjectName(QStringLiteral("sensSummary"));
  summary_->setWordWrap(true);
  auto* ranking = new QWidget;
  auto* rankingLayout = new QVBoxLayout(ranking);
  rankingLayout->setContentsMargins(0, 0, 0, 0);
  rankingLayout->addWidget(plot_, 1);
  rankingLayout->addWidget(summary_);
  tolerances_ = new ToleranceView;
  tabs_ = new QTabWidget;
  tabs_->setObjectName(QStringLiteral("sensTabs"));
  tabs_->addTab(ranking, tr("Ranking"));
  tabs_->addTab(tolerances_, tr("Tolerances"));
  connect(tabs_, &QTabWidget::currentChanged, this, [this] { markStale(); });
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(tabs_, 1);
  connect(doc_, &Document::designChanged, this, [this] {
    toleranceStale_ = true;
    turnStale_ = true;
    markStale();
  });
  // A stroke, a closest approach, a window's end are of the design, not of the pose: only a
  // point's derivatives at the crank angle follow it.
  connect(doc_, &Document::poseChanged, this, [this] {
    const int at = point_->currentIndex(), points = static_cast<int>(points_.size());
    if ((at >= 0 && at < points && quantity_->currentIndex() != kStroke) ||
        at >= points + transmissionsFrom_)
      markStale();
  });
}

void SensitivityPanel::fillPoints() {
  const Mechanism& m = doc_->design();
  const QString was = point_->currentText();
  std::vector<PointId> ids(m.outputs.begin(), m.outputs.end());
  for (const Point& p : m.points)
    if (!m.body(p.body)->ground && std::find(ids.begin(), ids.end(), p.id) == ids.end())
      ids.push_back(p.id);
  QStringList watched;
  for (const ClearanceWatch& w : m.timing.clearances) {
    const ClearancePart& o = w.other;
    const std::string other = o.isSlot()      ? m.slotLabel(o.slot)
                              : o.isSegment() ? m.pointLabel(o.point) + "-" + m.point(o.end)->name
                                              : m.pointLabel(o.point);
    watched << tr("closest approach: %1 to %2")
                   .arg(QString::fromStdString(m.pointLabel(w.point)),
                        QString::fromStdString(other));
  }
  // Each window (in the world on a machine in space): its first interval's start, then its end.
  QStringList ends;
  for (const TimingWindow& w : m.timing.windows)
    for (const QString& which : {tr("start"), tr("end")})
      ends << tr("window %1: its %2").arg(QString::fromStdString(w.name), which);
  watched += ends;
  const int transmissionsFrom = static_cast<int>(watched.size());
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  for (size_t j = 0; j < js.size(); ++j)
    watched << tr("transmission angle %1: %2").arg(j).arg(QString::fromStdString(js[j].label));
  // What the frame feels, where something has a mass.
  const bool masses = std::any_of(m.bodies.begin(), m.bodies.end(), [](const Body& b) {
    return !b.ground && b.mass && b.mass->kg > 0;
  });
  shakingAt_ = masses ? static_cast<int>(watched.size()) : -1;
  if (masses) watched << tr("shaking force");
  // Each joint's reaction (named as linkage-cli dynamics names it): its force (in its plane
  // class's frame on a machine in space, as dynamics writes it).
  reactions_.clear();
  for (size_t j = 0; j < m.joints.size() && masses; ++j) {
    reactions_.push_back(j);
    watched << tr("reaction at %1:%2")
                   .arg(QString::fromUtf8(kindOf(m.joints[j]).name),
                        QString::fromStdString(m.pointLabel(m.joints[j].a)));
  }
  momentAt_ = masses ? static_cast<int>(watched.size()) : -1;
  if (momentAt_ >= 0) watched << tr("shaking moment");
  if (ids == points_ && watched == clearances_) return;
  points_ = ids;
  clearances_ = watched;
  windowsFrom_ = transmissionsFrom - static_cast<int>(ends.size());
  transmissionsFrom_ = transmissionsFrom;
  const QSignalBlocker block(point_);
  point_->clear();
  for (PointId p : points_) point_->addItem(QString::fromStdString(m.pointLabel(p)));
  point_->addItems(clearances_);
  const int again = point_->findText(was);
  point_->setCurrentIndex(again >= 0 ? again : 0);
}

void SensitivityPanel::showNothing(const QString& why) {
  bars_.clear();
  plot_->clearPlottables();
  plot_->replot();
  summary_->setText(why);
}

void SensitivityPanel::compute() {
  fillPoints();
  const int at = point_->currentIndex();
  if (!doc_->solved() || at < 0) {
    quantity_->setEnabled(true);
    showNothing(doc_->solved() ? tr("No moving point to follow")
                               : QString::fromStdString(doc_->solveStatus().message));
    return;
  }
  if (at >= static_cast<int>(points_.size())) {
    quantity_->setEnabled(false);
    component_->setEnabled(false);
    offerZ(isSpatial(doc_->design()));
    const int n = at - static_cast<int>(points_.size());
    if (n == momentAt_) {
      momentBars();
      return;
    }
    if (shakingAt_ >= 0 && n >= shakingAt_) {
      component_->setEnabled(true);
      if (n == shakingAt_)
        shakingBars(component_->currentIndex());
      else
        reactionBars(reactions_.at(n - shakingAt_ - 1), component_->currentIndex());
      return;
    }
    if (n < windowsFrom_)
      clearanceBars(n);
    else if (n < transmissionsFrom_)
      windowBars(n - windowsFrom_);
    else
      transmissionBars(n - transmissionsFrom_);
    return;
  }
  quantity_->setEnabled(true);
  const PointId p = points_[at];
  Kinematics k = doc_->kinematics();
  offerZ(isSpatial(k.mechanism()));
  const int quantity = quantity_->currentIndex(), which = component_->currentIndex();
  Sensitivity s;
  // The world's x, y, z (a machine in space's too).
  if (Status st = s.prepare(k, dimensions(k.mechanism()), Sensitivity::Space::World); !st.ok()) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(st.message)));
    return;
  }
  // A planar stroke is along its slot, else y; in space along the world's axis chosen.
  component_->setEnabled(quantity != kStroke || isSpatial(k.mechanism()));
  if (quantity == kStroke) {
    strokeBars(k, p, which);
    return;
  }
  const size_t n = s.dims().size();
  const std::pair<PointId, int> asked{p, which == kZ ? 2 : std::min(which, 1)};
  if (tabs_->currentWidget() == tolerances_ && (toleranceStale_ || asked != toleranceFor_)) {
    toleranceStale_ = false;
    toleranceFor_ = asked;
    // The tolerances' band follows a point's x, y or z (the length of a change has no band:
    // y's is shown).
    std::vector<std::string> names;
    for (const Dimension& d : s.dims()) names.push_back(d.name);
    tolerances_->update(doc_->design(), names, p, asked.second);
  }
  bars_.assign(n, Bar{});
  for (size_t d = 0; d < n; ++d) bars_[d].dimension = s.dims()[d].name;
  const bool here = s.at(k).ok();
  for (size_t d = 0; d < n && here; ++d)
    bars_[d].now = component(s, k, p, static_cast<int>(d), quantity, which);
  const std::vector<double>& peak = turnPeaks(
      {p, quantity, which}, s, k, [&](const Sensitivity& ss, const Kinematics& kk, int d) {
        return component(ss, kk, p, d, quantity, which);
      });
  for (size_t d = 0; d < n; ++d) bars_[d].peak = peak[d];
  for (Bar& b : bars_) b.peak = std::max(b.peak, std::abs(b.now));
  rank();
  deadHere_ = !here;
  draw();
}

void SensitivityPanel::offerZ(bool space) {
  if (space == (component_->count() > kZ)) return;
  const QSignalBlocker block(component_);
  if (space) {
    component_->addItem(tr("z"));
    return;
  }
  if (component_->currentIndex() == kZ) component_->setCurrentIndex(1);
  component_->removeItem(kZ);
}

const std::vector<double>& SensitivityPanel::turnPeaks(const std::tuple<PointId, int, int>& key,
                                                       Sensitivity& s, Kinematics k,
                                                       const PerDimension& f) {
  if (!turnStale_ && key == turnFor_ && turnPeak_.size() == s.dims().size()) return turnPeak_;
  // Over a turn from here (the motion followed continuously), singular poses left out.
  std::vector<double> peak(s.dims().size(), 0.0);
  const double from = k.crankDeg();
  for (double t = kCycleStep; t <= 360 + 1e-9; t += kCycleStep) {
    if (!k.moveTo(from + t).ok()) break;
    if (!s.at(k).ok()) continue;
    for (size_t d = 0; d < peak.size(); ++d)
      peak[d] = std::max(peak[d], std::abs(f(s, k, static_cast<int>(d))));
  }
  turnPeak_ = std::move(peak);
  ++turnComputations_;
  turnFor_ = key;
  turnStale_ = false;
  return turnPeak_;
}

bool SensitivityPanel::showValues(const std::vector<Dimension>& dims,
                                  const std::vector<double>& derivative, const QString& axis) {
  bars_.clear();
  for (size_t d = 0; d < dims.size(); ++d)
    bars_.push_back({dims[d].name, derivative[d], std::abs(derivative[d])});
  rank();
  deadHere_ = false;
  draw();
  plot_->xAxis->setLabel(axis);
  plot_->replot();
  return !bars_.empty();
}

void SensitivityPanel::rank() {
  std::stable_sort(bars_.begin(), bars_.end(),
                   [](const Bar& a, const Bar& b) { return a.peak > b.peak; });
}

void SensitivityPanel::strokeBars(const Kinematics& k, PointId p, int which) {
  // In space along x, y or z (the length of a change has no direction: y, as the command line).
  const bool axis = isSpatial(k.mechanism()) && which != kLength;
  const Vec3 along =
      axis ? Vec3(Vec3::Unit(which == kZ ? 2 : which)) : strokeDirection(k.mechanism(), p);
  const StrokeSensitivity s = strokeSensitivity(k, p, along, dimensions(k.mechanism()));
  if (!s.status.ok()) {
    showNothing(QString::fromStdString(s.status.message));
    return;
  }
  if (!showValues(s.dims, s.derivative,
                  tr("change of the stroke per unit of the dimension (mm, degree, ratio)")))
    return;
  const QString direction = axis ? tr(" along %1")
                                       .arg(which == kZ ? QStringLiteral("z")
                                            : which     ? QStringLiteral("y")
                                                        : QStringLiteral("x"))
                                 : QString();
  summary_->setText(tr("The stroke%6 (%1 mm, between crank %2° and %3°) changes most with %4 "
                       "(%5 per unit)")
                        .arg(s.limits.stroke, 0, 'f', 4)
                        .arg(s.limits.minDeg, 0, 'f', 1)
                        .arg(s.limits.maxDeg, 0, 'f', 1)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4)
                        .arg(direction));
}

void SensitivityPanel::clearanceBars(int n) {
  const Mechanism& m = doc_->design();
  const ClearanceSensitivity s =
      clearanceSensitivity(doc_->kinematics(), m.timing.clearances.at(n), dimensions(m));
  if (!s.status.ok()) {
    showNothing(QString::fromStdString(s.status.message));
    return;
  }
  if (!showValues(
          s.dims, s.derivative,
          tr("change of the closest approach per unit of the dimension (mm, degree, ratio)")))
    return;
  summary_->setText(tr("The closest approach (%1 mm at crank %2°) changes most with %3 (%4 per "
                       "unit)")
                        .arg(s.clearance.closest.distance, 0, 'f', 4)
                        .arg(s.clearance.closest.crankDeg, 0, 'f', 1)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4));
}

void SensitivityPanel::windowBars(int n) {
  // The n-th end listed: window n / 2, its start or its end.
  const Mechanism& m = doc_->design();
  const TimingWindow& w = m.timing.windows.at(static_cast<size_t>(n / 2));
  const bool end = n % 2;
  const WindowSensitivity s = windowSensitivity(doc_->kinematics(), w.name, dimensions(m));
  if (!s.status.ok() || s.intervals.empty()) {
    showNothing(s.status.ok() ? tr("The window is never open")
                              : QString::fromStdString(s.status.message));
    return;
  }
  const WindowEndSensitivity& i = s.intervals.front();
  if (!showValues(s.dims, end ? i.dTo : i.dFrom,
                  tr("degrees of crank the window's %1 moves per unit of the dimension")
                      .arg(end ? tr("end") : tr("start"))))
    return;
  summary_->setText(tr("Window %1 %2 at crank %3°; it moves most with %4 (%5° per unit)")
                        .arg(QString::fromStdString(w.name))
                        .arg(end ? tr("closes") : tr("opens"))
                        .arg(end ? i.toDeg : i.fromDeg, 0, 'f', 2)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4));
}

void SensitivityPanel::transmissionBars(int n) {
  const Mechanism& m = doc_->design();
  const TransmissionJoint j = transmissionJoints(m).at(n);
  Kinematics k = doc_->kinematics();
  Sensitivity s;
  // In space each angle lies in its plane class's frame, which the world's sensitivities give.
  if (Status st = s.prepare(k, dimensions(k.mechanism()), Sensitivity::Space::World); !st.ok()) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(st.message)));
    return;
  }
  const bool here = s.at(k).ok();
  const std::vector<double> now =
      here ? transmissionAngleDerivatives(k, j, s) : std::vector<double>(s.dims().size(), 0.0);
  const std::vector<double>& peak =
      turnPeaks({PointId{}, -1, n}, s, k, [&j](const Sensitivity& ss, const Kinematics& kk, int d) {
        double v = 0;
        transmissionAngleSensitivity(kk, j, &ss, d, &v);
        return v;
      });
  bars_.clear();
  for (size_t d = 0; d < now.size(); ++d)
    bars_.push_back({s.dims()[d].name, now[d], std::max(peak[d], std::abs(now[d]))});
  rank();
  deadHere_ = !here;
  draw();
  plot_->xAxis->setLabel(
      tr("degrees of the transmission angle per unit of the dimension (mm, degree, ratio):"
         " blue at this crank angle, grey the largest over a turn"));
  plot_->replot();
  if (!here || bars_.empty()) return;
  summary_->setText(tr("%1 is %2° here; it changes most with %3 (%4° per unit here, up to %5° "
                       "over a turn)")
                        .arg(QString::fromStdString(j.label))
                        .arg(transmissionAngleSensitivity(k, j, nullptr, 0, nullptr), 0, 'f', 2)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4)
                        .arg(bars_[0].peak, 0, 'g', 4));
}

void SensitivityPanel::shakingBars(int which) {
  Kinematics k = doc_->kinematics();
  k.setAccelerations(true);
  // On a machine in space the world's force, its z the fourth component.
  const bool space = isSpatial(k.mechanism());
  Sensitivity s;
  if (Status st = s.prepare(k, dimensions(k.mechanism()),
                            space ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
      !st.ok()) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(st.message)));
    return;
  }
  const int w = std::min(which, space ? 3 : 2);
  auto part = [w, space](const Sensitivity& ss, const Kinematics& kk, int d) {
    const Vec2 p = space ? Vec2::Zero() : shakingForceSensitivity(kk, ss, d);
    const Vec3 f = space ? shakingForceSensitivity3(kk, ss, d) : Vec3(p.x(), p.y(), 0);
    return w == 2 ? f.norm() : f[w == 3 ? 2 : w];
  };
  const bool here = s.at(k).ok();
  const std::vector<double>& peak = turnPeaks({PointId{}, -2, w}, s, k, part);
  turnBars(
      s.dims(), here, [&](int d) { return part(s, k, d); }, peak, tr("N"));
  if (!here || bars_.empty()) return;
  Vec3 F, moment;
  if (space) {
    shaking(k, F, moment);
  } else {
    Vec2 planar;
    double m = 0;
    shaking(k, planar, m);
    F = Vec3(planar.x(), planar.y(), 0);
  }
  summary_->setText(tr("The frame feels %1 N here (fx %2, fy %3); %4 changes it most (%5 N per "
                       "unit here, up to %6 N over a turn)")
                        .arg(F.norm(), 0, 'g', 4)
                        .arg(F.x(), 0, 'g', 4)
                        .arg(F.y(), 0, 'g', 4)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4)
                        .arg(bars_[0].peak, 0, 'g', 4));
}

void SensitivityPanel::momentBars() {
  Kinematics k = doc_->kinematics();
  k.setAccelerations(true);
  // In space the moment is the world's: its x, y, z or the length of its change.
  const bool space = isSpatial(k.mechanism());
  offerZ(space);
  component_->setEnabled(space);
  const int which = space ? component_->currentIndex() : kZ;
  Sensitivity s;
  if (Status st = s.prepare(k, dimensions(k.mechanism()),
                            space ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
      !st.ok()) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(st.message)));
    return;
  }
  // A planar machine's moment is about z (shakingMomentSensitivity3's (0, 0, dM) there).
  auto part = [which](const Sensitivity& ss, const Kinematics& kk, int d) {
    const Vec3 m = shakingMomentSensitivity3(kk, ss, d);
    return which == kLength ? m.norm() : m[which == kZ ? 2 : which];
  };
  const bool here = s.at(k).ok();
  // The shaking force's key (-2) with components it has not (9 on): the reactions' are -3 - j.
  const std::vector<double>& peak = turnPeaks({PointId{}, -2, 9 + which}, s, k, part);
  turnBars(
      s.dims(), here, [&](int d) { return part(s, k, d); }, peak, tr("N m"));
  if (!here || bars_.empty()) return;
  Vec3 F, moment;
  if (space) {
    shaking(k, F, moment);
  } else {
    Vec2 planar;
    shaking(k, planar, moment.z());
  }
  const QString about =
      space ? tr("%1 N m here (about the world's origin; mx %2, my %3, mz %4)")
                  .arg(moment.norm(), 0, 'g', 4)
                  .arg(moment.x(), 0, 'g', 4)
                  .arg(moment.y(), 0, 'g', 4)
                  .arg(moment.z(), 0, 'g', 4)
            : tr("%1 N m here (about the drawing's origin)").arg(moment.z(), 0, 'g', 4);
  summary_->setText(tr("The frame feels a moment of %1; %2 changes it most (%3 N m per unit "
                       "here, up to %4 N m over a turn)")
                        .arg(about)
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4)
                        .arg(bars_[0].peak, 0, 'g', 4));
}

void SensitivityPanel::reactionBars(size_t j, int which) {
  Kinematics k = doc_->kinematics();
  k.setAccelerations(true);
  const Mechanism& m = k.mechanism();
  const JointId id = m.joints.at(j).id;
  const std::vector<Dimension> dims = dimensions(m);
  const JointForceSensitivity here = jointForceSensitivity(k, id, dims);
  if (here.status.code == StatusCode::BadModel) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(here.status.message)));
    return;
  }
  // In space in the joint's plane class's frame; its z the normal force its bearing takes. A
  // ball rod's reaction is its tension, one number.
  const bool space = isSpatial(m), rod = kindOf(m.joints.at(j)).role == Role::Distance;
  component_->setEnabled(!rod);
  offerZ(space && !rod && bearsOutOfPlane(k, id));  // z: what only a bearing takes
  which = component_->currentIndex();
  auto part = [which, rod](const JointReaction& c) {
    return rod                ? c.axialN
           : which == kZ      ? c.normalN
           : which == kLength ? c.force.norm()
                              : c.force[which];
  };
  // The turn's largest: all the dimensions' derivatives at once at each angle, read one by one.
  struct Memo {
    double deg = NAN;
    JointForceSensitivity f;
  };
  auto memo = std::make_shared<Memo>();
  Sensitivity s;
  if (Status st =
          s.prepare(k, dims, space ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
      !st.ok()) {
    showNothing(tr("Not yet: %1").arg(QString::fromStdString(st.message)));
    return;
  }
  const std::vector<double>& peak =
      turnPeaks({PointId{}, -3 - static_cast<int>(j), which}, s, k,
                [&, memo](const Sensitivity&, const Kinematics& kk, int d) {
                  if (memo->deg != kk.crankDeg()) memo->f = jointForceSensitivity(kk, id, dims);
                  memo->deg = kk.crankDeg();
                  return memo->f.status.ok() ? part(memo->f.change[d]) : 0.0;
                });
  const bool ok = here.status.ok();
  turnBars(
      dims, ok, [&](int d) { return part(here.change[d]); }, peak, tr("N"));
  if (!ok || bars_.empty()) return;
  summary_->setText(reactionSummary(k, m.joints.at(j), here.reaction, rod) +
                    tr("; %1 changes it most (%2 N per unit here, up to %3 N over a turn)")
                        .arg(QString::fromStdString(bars_[0].dimension))
                        .arg(bars_[0].now, 0, 'g', 4)
                        .arg(bars_[0].peak, 0, 'g', 4));
}

QString SensitivityPanel::reactionSummary(const Kinematics& k, const Joint& joint,
                                          const JointReaction& r, bool rod) const {
  const QString kind = QString::fromUtf8(kindOf(joint).name);
  if (rod) return tr("The %1's tension is %2 N").arg(kind).arg(r.axialN, 0, 'g', 4);
  // Rounding of an exact 0 (a part under 1e-12 of the force) shown as 0.
  const double size = r.force.norm() + std::abs(r.normalN);
  auto shown = [size](double v) { return std::abs(v) < 1e-12 * size ? 0.0 : v; };
  if (!isSpatial(k.mechanism()))
    return tr("The %1 bears %2 N here (fx %3, fy %4)")
        .arg(kind)
        .arg(r.force.norm(), 0, 'g', 4)
        .arg(shown(r.force.x()), 0, 'g', 4)
        .arg(shown(r.force.y()), 0, 'g', 4);
  const QString out = bearsOutOfPlane(k, joint.id)
                          ? tr(", and fn %1 N out of the plane").arg(shown(r.normalN), 0, 'g', 4)
                          : QString();
  return tr("The %1 bears %2 N in its plane here (fx %3, fy %4)%5")
      .arg(kind)
      .arg(r.force.norm(), 0, 'g', 4)
      .arg(shown(r.force.x()), 0, 'g', 4)
      .arg(shown(r.force.y()), 0, 'g', 4)
      .arg(out);
}

void SensitivityPanel::turnBars(const std::vector<Dimension>& dims, bool here,
                                const std::function<double(int)>& now,
                                const std::vector<double>& peak, const QString& unit) {
  bars_.clear();
  for (size_t d = 0; d < dims.size(); ++d) {
    const double v = here ? now(static_cast<int>(d)) : 0.0;
    bars_.push_back({dims[d].name, v, std::max(peak[d], std::abs(v))});
  }
  rank();
  deadHere_ = !here;
  draw();
  plot_->xAxis->setLabel(tr("%1 per unit of the dimension (mm, degree, ratio): blue at this "
                            "crank angle, grey the largest over a turn")
                             .arg(unit));
  plot_->replot();
}

void SensitivityPanel::draw() {
  plot_->clearPlottables();
  const int shown = std::min<int>(kShown, static_cast<int>(bars_.size()));
  QVector<double> keys, now, peak;
  QVector<QString> names;
  for (int i = 0; i < shown; ++i) {
    keys << shown - i;  // the largest at the top
    now << bars_[i].now;
    peak << bars_[i].peak;
    names << QString::fromStdString(bars_[i].dimension);
  }
  auto* grey = new QCPBars(plot_->yAxis, plot_->xAxis);
  grey->setData(keys, peak, true);
  grey->setWidth(0.8);
  grey->setPen(Qt::NoPen);
  grey->setBrush(QColor(200, 200, 200));
  grey->setName(tr("largest over a turn"));
  auto* blue = new QCPBars(plot_->yAxis, plot_->xAxis);
  blue->setData(keys, now, true);
  blue->setWidth(0.45);
  blue->setPen(Qt::NoPen);
  blue->setBrush(QColor(31, 119, 180));
  blue->setName(tr("at this crank angle"));
  auto ticker = QSharedPointer<QCPAxisTickerText>::create();
  ticker->addTicks(keys, names);
  plot_->yAxis->setTicker(ticker);
  plot_->yAxis->setRange(0.4, shown + 0.6);
  plot_->xAxis->setLabel(
      tr("change of the output per unit of the dimension (mm, degree, ratio):"
         " blue at this crank angle, grey the largest over a turn"));
  double reach = 1e-12;
  for (int i = 0; i < shown; ++i) reach = std::max({reach, peak[i], std::abs(now[i])});
  const double left = *std::min_element(now.begin(), now.end()) < 0 ? -1.05 * reach : 0;
  plot_->xAxis->setRange(left, 1.05 * reach);
  plot_->replot();
  if (bars_.empty()) return;
  QString text = tr("Matters most: %1 (%2 at this angle, up to %3 over a turn)")
                     .arg(QString::fromStdString(bars_[0].dimension))
                     .arg(bars_[0].now, 0, 'g', 4)
                     .arg(bars_[0].peak, 0, 'g', 4);
  if (static_cast<int>(bars_.size()) > shown)
    text += tr("; %1 more dimensions below these").arg(bars_.size() - shown);
  summary_->setText(deadHere_ ? tr("A dead point of the output here: its derivatives are "
                                   "unbounded (the grey bars are the turn's)")
                              : text);
}

QString SensitivityPanel::summary() const {
  return summary_->text();
}

QStringList SensitivityPanel::probeLines() const {
  QStringList out;
  out << QStringLiteral("sensitivity: ") + summary_->text();
  for (const Bar& b : bars_)
    out << QStringLiteral("sensitivity bar %1: %2 %3")
               .arg(QString::fromStdString(b.dimension))
               .arg(b.now, 0, 'g', 6)
               .arg(b.peak, 0, 'g', 6);
  return out;
}

}  // namespace linkage::ui
