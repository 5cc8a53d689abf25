#include "document/document.h"

#include <QFileInfo>
#include <algorithm>
#include <cmath>

#include "linkage/io/model_file.h"

namespace linkage::ui {

namespace {

Mechanism emptyDesign() {
  Mechanism m;
  m.name = "untitled";
  m.addBody("ground", true);
  return m;
}

// A design the solver takes or, when it cannot, the reason, with the solver left empty.
DocumentState solvedFresh(Mechanism m) {
  DocumentState s;
  s.status = s.kinematics.load(m);
  s.design = std::move(m);
  return s;
}

}  // namespace

Document::Document(QObject* parent) : QObject(parent) {
  connect(&undo_, &QUndoStack::cleanChanged, this, &Document::fileStateChanged);
  clear();
}

Document::~Document() = default;

void Document::clear() {
  replace(solvedFresh(emptyDesign()), QString(), QString());
}

bool Document::open(const QString& path, QString* error) {
  LoadResult r = loadMechanismFile(path.toStdString());
  if (!r.mechanism) {
    if (error) *error = QString::fromStdString(r.error);
    return false;
  }
  setContents(std::move(*r.mechanism), path);
  return true;
}

void Document::setContents(Mechanism m, const QString& path, const QString& title) {
  replace(solvedFresh(std::move(m)), path, title);
}

void Document::replace(DocumentState s, const QString& path, const QString& title) {
  state_ = std::move(s);
  applyWants();
  path_ = path;
  title_ = title;
  poseStatus_ = Status::success();
  undo_.clear();
  icFresh_ = false;
  forcesFresh_ = forcesPrepared_ = false;
  emit contentsReplaced();
  emit designChanged();
  emit poseChanged();
  emit fileStateChanged();
}

bool Document::save(const QString& path, QString* error) {
  WriteResult w = saveMechanismFile(state_.design, path.toStdString());
  if (!w.ok) {
    if (error) *error = QString::fromStdString(w.error);
    return false;
  }
  path_ = path;
  title_.clear();
  undo_.setClean();
  emit fileStateChanged();
  emit saved();
  return true;
}

QString Document::displayName() const {
  if (!path_.isEmpty()) return QFileInfo(path_).fileName();
  return title_.isEmpty() ? QStringLiteral("untitled") : title_;
}

void Document::setDesign(const Mechanism& m) {
  state_.design = m;
  state_.status = state_.kinematics.edit(m);
  applyWants();
  poseStatus_ = Status::success();
  icFresh_ = false;
  forcesFresh_ = forcesPrepared_ = false;
  emit designChanged();
  emit poseChanged();
}

void Document::restore(const DocumentState& s) {
  const double deg = crankDeg();
  state_ = s;
  applyWants();
  poseStatus_ = Status::success();
  // The view's crank angle, if the restored state can turn there; if not (it was the angle of
  // the edit being undone, which this state cannot reach: a start angle of 1e300), the state
  // stays exactly as it was kept: it is still solved, and the pose says why it did not turn.
  if (state_.kinematics.valid() && std::isfinite(deg) && state_.kinematics.crankDeg() != deg) {
    Kinematics moved = state_.kinematics;
    poseStatus_ = moved.moveTo(deg);
    if (poseStatus_.ok()) state_.kinematics = std::move(moved);
  }
  icFresh_ = false;
  forcesFresh_ = forcesPrepared_ = false;
  emit designChanged();
  emit poseChanged();
}

Status Document::motionStatus() const {
  if (!state_.status.ok()) return state_.status;
  const Kinematics& k = state_.kinematics;
  if (!k.valid()) return Status::failure(StatusCode::BadModel, "the mechanism is not solved");
  for (const Note& n : k.notes())
    if (n.kind == Note::Kind::FreedomsHeld) {
      Status s =
          Status::failure(StatusCode::Underconstrained, "the motion is not determined: " + n.text);
      s.bodies = n.bodies;
      return s;
    }
  return Status::success();
}

double Document::crankDeg() const {
  return state_.kinematics.valid() ? state_.kinematics.crankDeg() : 0.0;
}

Status Document::setCrankDeg(double deg) {
  if (!state_.kinematics.valid())
    return Status::failure(StatusCode::BadModel, "the mechanism is not solved");
  poseStatus_ = state_.kinematics.moveTo(deg);
  icFresh_ = false;
  forcesFresh_ = false;
  emit poseChanged();
  return poseStatus_;
}

Kinematics::DragResult Document::dragTo(PointId p, const Vec2& target) {
  Kinematics::DragResult r;
  if (!state_.kinematics.valid()) {
    r.status = Status::failure(StatusCode::BadModel, "the mechanism is not solved");
    return r;
  }
  r = state_.kinematics.dragTo(p, target);
  poseStatus_ = r.status;
  icFresh_ = false;
  forcesFresh_ = false;
  emit poseChanged();
  return r;
}

void Document::setAccelerationsWanted(bool on) {
  wantAccelerations_ = on;
  applyWants();
}

void Document::setForcesWanted(const void* who, bool on) {
  auto at = std::find(forcesWanted_.begin(), forcesWanted_.end(), who);
  if (on && at == forcesWanted_.end()) forcesWanted_.push_back(who);
  if (!on && at != forcesWanted_.end()) forcesWanted_.erase(at);
  applyWants();
}

void Document::applyWants() {
  const bool want = wantAccelerations_ || !forcesWanted_.empty();
  if (state_.kinematics.accelerations() != want) {
    state_.kinematics.setAccelerations(want);
    forcesFresh_ = false;
  }
}

const InstantCentres& Document::instantCentres() {
  if (icFresh_) return icSolver_.result();
  const Kinematics& k = state_.kinematics;
  if (k.valid() && k.revision() != icRevision_) {
    icSolver_.prepare(k);
    icRevision_ = k.revision();
  }
  icFresh_ = true;
  return icSolver_.compute(k);
}

const Forces& Document::forces() {
  const Kinematics& k = state_.kinematics;
  if (forcesFresh_ && forcesRevision_ == k.revision())
    return forcesPrepared_ ? forceSolver_.result() : forcesRefused_;
  forcesFresh_ = true;
  // The masses and loads are the design's: the solver's mechanism is the design when solved.
  if (const Status m = motionStatus(); !m.ok()) {
    forcesPrepared_ = false;
    forcesRefused_ = Forces{};
    forcesRefused_.status = m;
    return forcesRefused_;
  }
  if (!forcesPrepared_ || forcesRevision_ != k.revision()) {
    const Status s = forceSolver_.prepare(k);
    forcesRevision_ = k.revision();
    forcesPrepared_ = s.ok();
    if (!s.ok()) {
      forcesRefused_ = Forces{};
      forcesRefused_.status = s;
      return forcesRefused_;
    }
  }
  return forceSolver_.compute(k);
}

}  // namespace linkage::ui
