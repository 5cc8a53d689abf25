#include "kinematics.h"

#include <cassert>
#include <cmath>
#include <cstdio>

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180.0;
// Nearness to singular (NewtonSolver::nearness) below which a position's derivatives are not
// trusted as the base of the next step. Above NewtonSolver's 1e-8 (where velocities are not
// given at all); the closest legitimate positions measured stay above 1e-4.
constexpr double kUnreliable = 1e-7;

std::string deg(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g deg", std::abs(v) < 5e-10 ? 0.0 : v);
  return buf;
}

}  // namespace

double Kinematics::crankDeg() const {
  return (cur().phi - sys_.startRad) / kDeg;
}

double Kinematics::omega() const {
  return sys_.rpm * 2 * M_PI / 60;
}

std::string Kinematics::bodyList(const std::vector<int>& bodies) const {
  std::string s;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body* b = mech_.body(sys_.bodyIds[bodies[i]]);
    s += (i ? ", '" : "'") + (b ? b->name : std::string("?")) + "'";
  }
  return s;
}

Status Kinematics::load(const Mechanism& m) {
  return prepare(m, nullptr, 0.0);
}

Status Kinematics::prepare(const Mechanism& m, const Eigen::VectorXd* warm, double warmPhi) {
  valid_ = false;
  notes_.clear();
  assembly_ = {};
  plan_.reset();
  Status s;
  std::optional<System> compiled = compile(m, s);
  if (!compiled) return s;
  mech_ = m;
  sys_ = std::move(*compiled);

  Eigen::VectorXd q = warm ? *warm : sketchCoordinates(sys_);
  const double phi = warm ? warmPhi : 0.0;
  structure_ = analyzeStructure(sys_, q, opt_.sparseFrom);
  if (sys_.hasDriver && !structure_.driverMoves) {
    const JointId dj = mech_.driver->joint;
    s = Status::failure(StatusCode::Locked, "");
    s.joints.push_back(dj);
    s.message = "the driver at " + mech_.jointLabel(dj) + " cannot turn: " +
                (structure_.mobility == 0
                     ? "the mechanism has no degree of freedom (it is a structure)"
                     : "either the other joints hold the two bodies it joins rigidly together, "
                       "or the mechanism is drawn at a dead point (a limit position of the crank, "
                       "where links line up): draw it a little away from there");
    return s;
  }
  if (!structure_.redundantJoints.empty()) {
    std::string names;
    for (int j : structure_.redundantJoints)
      names += (names.empty() ? "" : ", ") + mech_.jointLabel(mech_.joints[j].id);
    notes_.push_back("redundant joint(s): " + names +
                     " repeat constraints of the others; checked, not needed by the solve");
  }
  std::vector<int> active = structure_.activeRows;
  for (int col : structure_.holdCoordinates) {
    addHold(sys_, col, q[col]);
    active.push_back(sys_.nRows - 1);
  }
  if (structure_.freeAfterDriver > 0) {
    notes_.push_back(std::to_string(structure_.freeAfterDriver) +
                     (sys_.hasDriver ? " degree(s) of freedom the driver does not determine"
                                     : " degree(s) of freedom and no driver") +
                     " (bodies " + bodyList(structure_.freeBodies) +
                     "): held where they are drawn");
  }
  newton_.reset(sys_, active, opt_.sparseFrom);

  s = assemble(mech_, sys_, structure_, newton_, q, phi, assembly_);
  if (!s.ok()) return s;
  if (!warm && assembly_.moved(sys_)) {
    const Body* b = mech_.body(assembly_.body);
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "the drawing does not close exactly: assembled by moving body '%s' by up to "
                  "%.6g mm (bodies keep their shape)",
                  b ? b->name.c_str() : "?", assembly_.maxMove);
    notes_.push_back(buf);
  }
  s = checkRedundant(mech_, sys_, structure_, q, phi);
  if (!s.ok()) return s;

  Snapshot snap;
  snap.q = q;
  if (!newton_.derivatives(sys_, q, snap.dq, snap.ddq)) {
    s = Status::failure(StatusCode::Singular,
                        "the mechanism is drawn in a singular position (links in line: a dead "
                        "point or a change point): velocities are not determined there; draw it "
                        "a little away from it");
    s.crankDeg = (phi - sys_.startRad) / kDeg;
    return s;
  }
  snap.fromCoordinates(phi, snap.q, snap.dq, snap.ddq);
  snap.coordinates = true;
  snap.regular = true;
  reg_ = snap;
  atSingular_ = false;
  regSign_ = newton_.detSign();
  valid_ = true;
  if (opt_.closedForm) {
    plan_ = ClosedFormPlan::build(mech_, sys_, q);
    // The plan must reproduce the configuration just solved, or it is not used.
    next_.coordinates = false;  // whatever next_ held before is not what the plan writes
    if (plan_ && !(plan_->solve(sys_, reg_, phi, next_) &&
                   (coordinates(next_).q - reg_.q).cwiseAbs().maxCoeff() <= 1e-9 * sys_.size &&
                   (next_.dq - reg_.dq).cwiseAbs().maxCoeff() <= 1e-7 * (1 + reg_.dq.norm())))
      plan_.reset();
  }
  if (!warm && sys_.hasDriver && sys_.startRad != 0) {
    s = moveToPhi(sys_.startRad);
    if (!s.ok()) {
      valid_ = false;
      s.message = "cannot turn the crank to its start angle (start_deg): " + s.message;
      return s;
    }
  }
  return Status::success();
}

bool Kinematics::editInPlace(const Mechanism& m) {
  std::vector<BodyId> reshaped;
  if (!plan_ || atSingular_ || !sameTopology(mech_, m, reshaped)) return false;
  Status s;
  std::optional<System> sys = compile(m, s);
  if (!sys || sys->nRows != sys_.nRows || sys->nBodies != sys_.nBodies) return false;
  // The current pose in the new body frames: a reshaped body keeps its rigid displacement from
  // the drawing (its frame origin, the centroid of its points, moved with the points).
  Motion warm = reg_;
  for (BodyId id : reshaped) {
    const int k = sys->bodyIndex(id);
    if (k < 0) continue;  // ground: no frame to move
    BodyState& b = warm.body[k];
    const Vec2 shift = b.R * (sys->frameOrigin[k] - sys_.frameOrigin[k]);
    b.r += shift;
    b.v += b.w * perp(shift);
    b.a += b.al * perp(shift) - b.w * b.w * shift;
  }
  Eigen::VectorXd q, dq, ddq;
  warm.toCoordinates(q, dq, ddq);
  std::optional<ClosedFormPlan> plan = ClosedFormPlan::build(m, *sys, q);
  if (!plan) return false;
  Motion solved;
  const int groups = plan->resolveEdited(*sys, *plan_, warm, solved);
  if (groups < 0) return false;
  mech_ = m;
  sys_ = std::move(*sys);
  plan_ = std::move(plan);
  static_cast<Motion&>(reg_) = std::move(solved);
  reg_.regular = true;
  reg_.coordinates = false;
  // The same rows, so the structure and the Newton solver's row map stay as they are.
  assembly_ = {};
  notes_.clear();
  lastEditGroups_ = groups;
  return true;
}

Status Kinematics::edit(const Mechanism& m) {
  if (!valid_) return load(m);
  if (editInPlace(m)) return Status::success();
  lastEditGroups_ = -1;
  // Carry each surviving body's rigid displacement (rotation, translation) over to its new frame.
  const System old = sys_;
  const Eigen::VectorXd oldQ = coordinates(cur()).q;
  const double phi = cur().phi;
  Status s;
  std::optional<System> next = compile(m, s);
  if (!next) return s;
  Eigen::VectorXd warm = sketchCoordinates(*next);
  for (int k = 0; k < next->nBodies; ++k) {
    const int o = old.bodyIndex(next->bodyIds[k]);
    if (o < 0) continue;
    const double th = oldQ[3 * o + 2];
    const Rot R{std::cos(th), std::sin(th)};
    const Vec2 t = Vec2(oldQ[3 * o], oldQ[3 * o + 1]) - R * old.frameOrigin[o];
    const Vec2 r = R * next->frameOrigin[k] + t;
    warm.segment<3>(3 * k) << r.x(), r.y(), th;
  }
  s = prepare(m, &warm, phi);
  if (s.ok()) return s;
  // The edit moved things too far for a warm start: assemble the drawing and turn the crank.
  const Status cold = load(m);
  if (!cold.ok()) return cold;
  return moveToPhi(phi);
}

Kinematics::StepResult Kinematics::tryStep(double phiNext, Snapshot& out) {
  const double h = phiNext - reg_.phi;
  const Snapshot& from = coordinates(reg_);
  out.q = from.q + h * from.dq + (0.5 * h * h) * from.ddq;
  lastRefusalCrossing_ = false;
  if (!newton_.solve(sys_, out.q, phiNext, opt_.newton).converged) return StepResult::Refused;
  out.coordinates = true;
  out.regular = newton_.derivatives(sys_, out.q, out.dq, out.ddq);
  if (!out.regular) {
    // No velocities here: NaN, sized, so a caller that does not check derivativesValid() gets
    // an obviously undefined number rather than a stale or out-of-range one.
    out.dq = Eigen::VectorXd::Constant(sys_.nCoords(), NAN);
    out.ddq = out.dq;
  }
  out.fromCoordinates(phiNext, out.q, out.dq, out.ddq);
  if (!out.regular) return StepResult::Singular;
  // Within 1e-7 of singular (scaled J) accelerations carry errors of eps / 1e-14 and more:
  // such a position is no base for the predictor or the branch test, which it could fool
  // into accepting a jump onto the other branch step by tiny step. Refused like a crossing,
  // so the tracker stops short of it and explains (explainFailure).
  lastRefusalCrossing_ = newton_.detSign() != regSign_ || !sameBranch(from, out, h) ||
                         newton_.nearness() < kUnreliable;
  if (lastRefusalCrossing_) return StepResult::Refused;
  return StepResult::Accepted;
}

bool Kinematics::sameBranch(const Snapshot& from, const Snapshot& to, double h) const {
  // Where two assembly branches cross (a change point) they have different tangents, and a
  // step across it may land on the other branch with det J of the same sign (the sign flips
  // along both). The velocities show it: along one smooth branch the velocity at the end of
  // the step is the one at the start plus the trapezoid of the two ends' accelerations, to
  // O(h^3); on the other branch they differ at first order. Body by body, so that a jump in
  // one loop of a long chain is not hidden in the norm of the whole; a tenth of the body's
  // speed is allowed, far more than a smooth path's error, far less than a change of tangent.
  // Next to a singular position the computed accelerations grow without bound (rounding over
  // a vanishing singular value): the trapezoid then misses and the step is refused, never
  // excused by them.
  const double L = sys_.size;
  for (int k = 0; k < sys_.nBodies; ++k) {
    double err = 0, speed = 0;
    for (int c = 3 * k; c < 3 * k + 3; ++c) {
      const double scale = c % 3 == 2 ? L : 1.0;  // angles as the arc they make over L
      const double pred = from.dq[c] + 0.5 * h * (from.ddq[c] + to.ddq[c]);
      err = std::max(err, scale * std::abs(to.dq[c] - pred));
      speed = std::max(speed, scale * (std::abs(to.dq[c]) + std::abs(from.dq[c])));
    }
    if (!(err <= 0.1 * speed + 1e-9 * L)) return false;
  }
  return true;
}

void Kinematics::setAccelerations(bool on) {
  opt_.accelerations = on;
  if (!on || !valid_ || reg_.accelerations || !plan_) return;
  if (plan_->solve(sys_, reg_, reg_.phi, next_, true)) {
    next_.regular = true;
    next_.coordinates = false;
    std::swap(reg_, next_);
  }
}

Status Kinematics::moveTo(double crankDeg) {
  if (!valid_) return Status::failure(StatusCode::BadModel, "no mechanism is loaded");
  if (!sys_.hasDriver)
    return Status::failure(StatusCode::BadModel, "the mechanism has no driver to turn");
  if (!std::isfinite(crankDeg))
    return Status::failure(StatusCode::BadModel, "the crank angle is not a finite number");
  return moveToPhi(sys_.startRad + crankDeg * kDeg);
}

Status Kinematics::skipWholeTurns(double target) {
  const double turn = 2 * M_PI;
  const double dir = target > reg_.phi ? 1.0 : -1.0;
  const Snapshot start = reg_;
  if (Status s = moveToPhi(reg_.phi + dir * turn); !s.ok()) return s;
  // Periodic when every point is back: x, y equal and angles equal modulo whole turns.
  Eigen::VectorXd perTurn = coordinates(reg_).q - coordinates(start).q;
  for (int k = 0; k < sys_.nBodies; ++k) {
    const double dth = perTurn[3 * k + 2];
    const double whole = turn * std::round(dth / turn);
    if (std::abs(perTurn[3 * k]) > 1e-9 * sys_.size ||
        std::abs(perTurn[3 * k + 1]) > 1e-9 * sys_.size || std::abs(dth - whole) > 1e-9)
      return Status::success();  // not periodic in one turn: tracked the whole way
    perTurn[3 * k] = perTurn[3 * k + 1] = 0;
    perTurn[3 * k + 2] = whole;
  }
  const double turns = std::floor(std::abs(target - reg_.phi) / turn);
  reg_.phi += dir * turns * turn;
  reg_.q += turns * perTurn;
  for (int k = 0; k < sys_.nBodies; ++k)
    reg_.body[k].turns += std::round(turns * perTurn[3 * k + 2] / turn);
  atSingular_ = false;
  return Status::success();
}

Status Kinematics::moveToPhi(double target) {
  // Far targets: one turn shows whether the motion repeats; if it does, whole turns are skipped
  // exactly (angles advance by whole turns), so a large angle costs no more than one turn.
  if (std::abs(target - reg_.phi) > 4 * M_PI) {
    if (Status s = skipWholeTurns(target); !s.ok()) return s;
  }
  if (plan_ && trackClosedForm(target)) return Status::success();
  if (plan_) {
    // The general solve takes over from the last closed-form position: its derivatives (with
    // accelerations, which the predictor uses, even where the steps left them out) and the
    // sign of det J that marks its branch.
    const Eigen::VectorXd q = coordinates(reg_).q;
    Eigen::VectorXd dq, ddq;
    if (newton_.derivatives(sys_, q, dq, ddq)) {
      regSign_ = newton_.detSign();
      reg_.q = q;
      reg_.dq = dq;
      reg_.ddq = ddq;
      reg_.coordinates = true;
      reg_.fromCoordinates(reg_.phi, q, dq, ddq);
    }
  }
  return trackGeneral(target);
}

bool Kinematics::trackClosedForm(double target) {
  // Whole turns are counted from one step to the next (motion.h), which needs every body to
  // turn less than half a turn a step: the crank, at least, turns by the step itself.
  const double hMax = std::min(opt_.maxStepDeg, 90.0) * kDeg;
  while (reg_.phi != target) {
    // Steps no larger than the general tracker's keep angles continued correctly and make a
    // region the mechanism cannot reach show up as a failed step, not be stepped over.
    const double remaining = target - reg_.phi;
    const double phiNext =
        std::abs(remaining) <= hMax ? target : reg_.phi + std::copysign(hMax, remaining);
    if (!plan_->solve(sys_, reg_, phiNext, next_, opt_.accelerations)) {
      atSingular_ = false;
      return false;
    }
    next_.regular = true;
    next_.coordinates = false;  // made on demand: a closed-form step needs none
    std::swap(reg_, next_);
  }
  atSingular_ = false;
  return true;
}

Status Kinematics::trackGeneral(double target) {
  const double hMax = opt_.maxStepDeg * kDeg;
  const double hMin = opt_.minStepDeg * kDeg;
  double hTry = hMax;
  bool crossing = false;  // the last refusal: a sign change of det J with Newton converged
  for (;;) {
    const double remaining = target - reg_.phi;
    if (remaining == 0) {
      atSingular_ = false;
      return Status::success();
    }
    const bool last = std::abs(remaining) <= hTry;
    const double phiNext = last ? target : reg_.phi + std::copysign(hTry, remaining);
    Snapshot next;
    switch (tryStep(phiNext, next)) {
      case StepResult::Accepted:
        reg_ = std::move(next);
        atSingular_ = false;
        regSign_ = newton_.detSign();
        hTry = std::min(hMax, 2 * hTry);
        continue;
      case StepResult::Singular:
        if (last) {
          singular_ = std::move(next);
          atSingular_ = true;
          Status s = Status::failure(
              StatusCode::Singular,
              "singular position at crank angle " + deg((target - sys_.startRad) / kDeg) +
                  ": positions are solved but velocities are not determined by the driver there");
          s.crankDeg = (target - sys_.startRad) / kDeg;
          return s;
        }
        [[fallthrough]];
      case StepResult::Refused:
        hTry = std::abs(phiNext - reg_.phi) / 4;
        crossing = lastRefusalCrossing_;
        break;
    }
    if (hTry < hMin) {
      atSingular_ = false;
      return explainFailure(target, crossing);
    }
  }
}

Status Kinematics::explainFailure(double phiFailed, bool crossing) {
  const double reached = (reg_.phi - sys_.startRad) / kDeg;
  const double wanted = (phiFailed - sys_.startRad) / kDeg;
  // Near a dead point q' grows without bound (like 1 / sqrt of the distance to it).
  double speed = 0;
  std::vector<double> perBody(sys_.nBodies, 0.0);
  for (int k = 0; k < sys_.nBodies; ++k) {
    const BodyState& b = reg_.body[k];
    perBody[k] = std::max({std::abs(b.v.x()), std::abs(b.v.y()), std::abs(b.w) * sys_.size});
    speed = std::max(speed, perBody[k]);
  }
  Status s;
  s.crankDeg = wanted;
  s.lastReachedDeg = reached;
  if (speed > 1e2 * sys_.size) {
    std::vector<int> involved;
    for (int k = 0; k < sys_.nBodies; ++k)
      if (perBody[k] > 0.1 * speed) {
        involved.push_back(k);
        s.bodies.push_back(sys_.bodyIds[k]);
      }
    s.code = StatusCode::Unreachable;
    s.message = "cannot reach crank angle " + deg(wanted) +
                ": the mechanism locks at crank angle " + deg(reached) +
                " (limit position: " + bodyList(involved) +
                " reach a dead point, where no motion of the crank can pass)";
    return s;
  }
  if (!crossing) {
    // Finite velocities but a nearly singular Jacobian: the branches meet just ahead (a
    // change point), where Newton cannot tell them apart.
    Eigen::VectorXd dq, ddq;
    newton_.derivatives(sys_, coordinates(reg_).q, dq, ddq);
    crossing = newton_.nearness() < 1e-3;
  }
  if (crossing) {
    s.code = StatusCode::Singular;
    s.message = "cannot follow the motion past crank angle " + deg(reached) + " towards " +
                deg(wanted) +
                ": the mechanism passes a singular position there where two assembly branches "
                "meet (a change point: links in line); the driver does not decide which branch "
                "it takes, so it stops rather than guess";
  } else {
    s.code = StatusCode::NotConverged;
    s.message = "cannot follow the motion past crank angle " + deg(reached) + " towards " +
                deg(wanted) +
                ": the position solve does not converge there (a jump to another assembly "
                "branch or a singular crossing was refused)";
  }
  return s;
}

const PointLocation& Kinematics::locate(PointId p) const {
  const PointLocation* loc = sys_.point(p);
  assert(loc && "Kinematics: unknown point id; ids must come from this mechanism");
  return *loc;
}

Vec2 Kinematics::position(PointId p) const {
  const PointLocation& l = locate(p);
  return cur().of(l.body).pos(l.s);
}

Vec2 Kinematics::velocity(PointId p) const {
  const PointLocation& l = locate(p);
  return omega() * cur().of(l.body).vel(l.s);
}

Vec2 Kinematics::acceleration(PointId p) const {
  const PointLocation& l = locate(p);
  if (!cur().accelerations) return Vec2::Constant(NAN);
  const double w = omega();
  return w * w * cur().of(l.body).acc(l.s);
}

Kinematics::PointMotion Kinematics::motion(PointId p) const {
  const PointLocation& l = locate(p);
  const BodyState& b = cur().of(l.body);
  const Vec2 g = b.R * l.s;
  const double w = omega();
  return {b.r + g, w * (b.v + b.w * perp(g)),
          cur().accelerations ? Vec2(w * w * (b.a + b.al * perp(g) - b.w * b.w * g))
                              : Vec2::Constant(NAN)};
}

double Kinematics::bodyAngle(BodyId b) const {
  return cur().of(sys_.bodyIndex(b)).angle();
}

double Kinematics::bodyOmega(BodyId b) const {
  return omega() * cur().of(sys_.bodyIndex(b)).w;
}

double Kinematics::bodyAlpha(BodyId b) const {
  return cur().accelerations ? omega() * omega() * cur().of(sys_.bodyIndex(b)).al : NAN;
}

const Kinematics::Snapshot& Kinematics::coordinates(const Snapshot& s) const {
  if (!s.coordinates) {
    s.toCoordinates(s.q, s.dq, s.ddq);
    s.coordinates = true;
  }
  return s;
}

Status Kinematics::checkDetermined(const std::vector<PointId>& points) const {
  for (PointId p : points) {
    const PointLocation* loc = sys_.point(p);
    if (!loc) return Status::failure(StatusCode::BadModel, "unknown output point");
    if (!structure_.pointDetermined(sys_, coordinates(cur()).q, *loc)) {
      Status s = Status::failure(
          StatusCode::Underconstrained,
          "the motion of " + mech_.pointLabel(p) + " is not determined by the driver: " +
              std::to_string(structure_.freeAfterDriver) + " degree(s) of freedom remain (bodies " +
              bodyList(structure_.freeBodies) + " can move with the crank held)");
      for (int k : structure_.freeBodies) s.bodies.push_back(sys_.bodyIds[k]);
      return s;
    }
  }
  return Status::success();
}

}  // namespace linkage
