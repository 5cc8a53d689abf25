// Tracking the motion from one crank angle to another (KinematicsState): closed-form steps
// where the plan allows, else predictor and Newton steps that refuse to cross a singular
// position or jump to another branch, and the explanation of where and why it stops.
#include <cmath>
#include <cstdio>

#include <Eigen/SVD>
#include <algorithm>

#include "kinematics/kinematics_state.h"

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

double KinematicsState::crankDeg() const {
  return (cur().phi - sys.startRad) / kDeg;
}

std::string KinematicsState::bodyList(const std::vector<int>& bodies) const {
  std::string s;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const Body* b = mech.body(sys.bodyIds[bodies[i]]);
    s += (i ? ", '" : "'") + (b ? b->name : std::string("?")) + "'";
  }
  return s;
}

const KinematicsState::Snapshot& KinematicsState::coordinates(const Snapshot& s) const {
  if (!s.coordinates) {
    s.toCoordinates(s.q, s.dq, s.ddq);
    s.coordinates = true;
  }
  return s;
}

KinematicsState::StepResult KinematicsState::tryStep(double phiNext, Snapshot& out) {
  const double h = phiNext - reg.phi;
  const Snapshot& from = coordinates(reg);
  out.q = from.q + h * from.dq + (0.5 * h * h) * from.ddq;
  lastRefusalCrossing = false;
  if (!newton.solve(sys, out.q, phiNext, opt.newton).converged) return StepResult::Refused;
  out.coordinates = true;
  out.regular = newton.derivatives(sys, out.q, out.dq, out.ddq);
  if (!out.regular) {
    // No velocities here: NaN, sized, so a caller that does not check derivativesValid() gets
    // an obviously undefined number rather than a stale or out-of-range one.
    out.dq = Eigen::VectorXd::Constant(sys.nCoords(), NAN);
    out.ddq = out.dq;
  }
  out.fromCoordinates(phiNext, out.q, out.dq, out.ddq);
  if (!out.regular) return StepResult::Singular;
  // Within 1e-7 of singular (scaled J) accelerations carry errors of eps / 1e-14 and more:
  // such a position is no base for the predictor or the branch test, which it could fool
  // into accepting a jump onto the other branch step by tiny step. Refused like a crossing,
  // so the tracker stops short of it and explains (explainFailure).
  lastRefusalCrossing =
      newton.detSign() != regSign || !sameBranch(from, out, h) || newton.nearness() < kUnreliable;
  if (lastRefusalCrossing) return StepResult::Refused;
  return StepResult::Accepted;
}

bool KinematicsState::sameBranch(const Snapshot& from, const Snapshot& to, double h) const {
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
  const double L = sys.size;
  for (int k = 0; k < sys.nBodies; ++k) {
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

Status KinematicsState::skipWholeTurns(double target) {
  const double turn = 2 * M_PI;
  const double dir = target > reg.phi ? 1.0 : -1.0;
  const Snapshot start = reg;
  if (Status s = moveToPhi(reg.phi + dir * turn); !s.ok()) return s;
  // Periodic when every point is back: x, y equal and angles equal modulo whole turns.
  Eigen::VectorXd perTurn = coordinates(reg).q - coordinates(start).q;
  for (int k = 0; k < sys.nBodies; ++k) {
    const double dth = perTurn[3 * k + 2];
    const double whole = turn * std::round(dth / turn);
    if (std::abs(perTurn[3 * k]) > 1e-9 * sys.size ||
        std::abs(perTurn[3 * k + 1]) > 1e-9 * sys.size || std::abs(dth - whole) > 1e-9) {
      // Not periodic in one turn: tracked the whole way, step by step, which a thousand turns
      // (a few seconds of steps) bound, so that a typed angle never stalls an editor.
      constexpr double kMaxTrackedTurns = 1000;
      if (std::abs(target - reg.phi) <= kMaxTrackedTurns * turn) return Status::success();
      Status s = Status::failure(
          StatusCode::BadModel,
          "crank angle " + deg((target - sys.startRad) / kDeg) +
              " is refused: the motion does not repeat after one turn, and tracking it more "
              "than 1000 turns step by step would take too long");
      s.crankDeg = (target - sys.startRad) / kDeg;
      return s;
    }
    perTurn[3 * k] = perTurn[3 * k + 1] = 0;
    perTurn[3 * k + 2] = whole;
  }
  const double turns = std::floor(std::abs(target - reg.phi) / turn);
  reg.phi += dir * turns * turn;
  reg.q += turns * perTurn;
  for (int k = 0; k < sys.nBodies; ++k)
    reg.body[k].turns += std::round(turns * perTurn[3 * k + 2] / turn);
  atSingular = false;
  return Status::success();
}

Status KinematicsState::moveToPhi(double target) {
  // Crank angles are counted in a double: up to 1e12 degrees from the start (2.8 billion
  // turns) its rounding stays under 3e-4 degrees, a ten-thousandth of a step. Far beyond, a step
  // rounds to nothing and the tracker would never arrive: refused, naming the angle.
  constexpr double kMaxFromStartRad = 1e12 * kDeg;
  const bool farFromStart = std::abs(target - sys.startRad) > kMaxFromStartRad;
  if (!std::isfinite(target) || farFromStart || std::abs(target) > kMaxFromStartRad) {
    Status s = Status::failure(
        StatusCode::BadModel,
        "crank angle " + deg((target - sys.startRad) / kDeg) +
            (farFromStart ? "" : " (" + deg(target / kDeg) + " from the drawing, with start_deg)") +
            " is beyond the 1e12 degrees (2.8 billion turns) either way from the start that the "
            "crank angle is counted to");
    s.crankDeg = (target - sys.startRad) / kDeg;
    return s;
  }
  // Far targets: one turn shows whether the motion repeats; if it does, whole turns are skipped
  // exactly (angles advance by whole turns), so a large angle costs no more than one turn.
  if (std::abs(target - reg.phi) > 4 * M_PI) {
    if (Status s = skipWholeTurns(target); !s.ok()) return s;
  }
  if (plan && trackClosedForm(target)) return Status::success();
  if (plan) {
    // The general solve takes over from the last closed-form position: its derivatives (with
    // accelerations, which the predictor uses, even where the steps left them out) and the
    // sign of det J that marks its branch.
    const Eigen::VectorXd q = coordinates(reg).q;
    Eigen::VectorXd dq, ddq;
    if (newton.derivatives(sys, q, dq, ddq)) {
      regSign = newton.detSign();
      reg.q = q;
      reg.dq = dq;
      reg.ddq = ddq;
      reg.coordinates = true;
      reg.fromCoordinates(reg.phi, q, dq, ddq);
    }
  }
  return trackGeneral(target);
}

bool KinematicsState::trackClosedForm(double target) {
  // Whole turns are counted from one step to the next (motion.h), which needs every body to
  // turn less than half a turn a step: the crank, at least, turns by the step itself.
  const double hMax = std::min(opt.maxStepDeg, 90.0) * kDeg;
  while (reg.phi != target) {
    // Steps no larger than the general tracker's keep angles continued correctly and make a
    // region the mechanism cannot reach show up as a failed step, not be stepped over.
    const double remaining = target - reg.phi;
    const double phiNext =
        std::abs(remaining) <= hMax ? target : reg.phi + std::copysign(hMax, remaining);
    if (phiNext == reg.phi) return false;  // no step left in a double (moveToPhi bounds it)
    if (!plan->solve(sys, reg, phiNext, next, opt.accelerations)) {
      atSingular = false;
      return false;
    }
    next.regular = true;
    next.coordinates = false;  // made on demand: a closed-form step needs none
    std::swap(reg, next);
  }
  atSingular = false;
  return true;
}

Status KinematicsState::trackGeneral(double target) {
  const double hMax = opt.maxStepDeg * kDeg;
  const double hMin = opt.minStepDeg * kDeg;
  double hTry = hMax;
  bool crossing = false;  // the last refusal: a sign change of det J with Newton converged
  for (;;) {
    const double remaining = target - reg.phi;
    if (remaining == 0) {
      atSingular = false;
      return Status::success();
    }
    const bool last = std::abs(remaining) <= hTry;
    const double phiNext = last ? target : reg.phi + std::copysign(hTry, remaining);
    if (phiNext == reg.phi) return explainFailure(target, false);  // as above
    Snapshot next;
    switch (tryStep(phiNext, next)) {
      case StepResult::Accepted:
        reg = std::move(next);
        atSingular = false;
        regSign = newton.detSign();
        hTry = std::min(hMax, 2 * hTry);
        continue;
      case StepResult::Singular:
        if (last) {
          singular = std::move(next);
          atSingular = true;
          Status s = Status::failure(
              StatusCode::Singular,
              "singular position at crank angle " + deg((target - sys.startRad) / kDeg) +
                  ": positions are solved but velocities are not determined by the driver there");
          s.crankDeg = (target - sys.startRad) / kDeg;
          namePlace(coordinates(singular).q, s);
          return s;
        }
        [[fallthrough]];
      case StepResult::Refused:
        hTry = std::abs(phiNext - reg.phi) / 4;
        crossing = lastRefusalCrossing;
        break;
    }
    if (hTry < hMin) {
      atSingular = false;
      return explainFailure(target, crossing);
    }
  }
}

void KinematicsState::namePlace(const Eigen::VectorXd& q, Status& s) const {
  // The bodies that can move with the crank held at a singular position (the direction J is
  // blind to, from a singular value decomposition of J with its angle columns scaled by L so
  // that every body's entries are lengths), and the joints on them: the links in line.
  if (sys.nCoords() == 0 || sys.nCoords() > 300) return;  // a dense SVD: small systems only
  std::vector<BodyView> views;
  makeViews(sys, q, nullptr, views);
  const std::vector<int>& rows = newton.rowMap();
  const int n =
      static_cast<int>(std::count_if(rows.begin(), rows.end(), [](int r) { return r >= 0; }));
  Eigen::MatrixXd J(n, sys.nCoords());
  evalJacobian(sys, views, rows, J);
  for (int k = 0; k < sys.nBodies; ++k) J.col(3 * k + 2) /= sys.size;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd v = svd.matrixV().col(sys.nCoords() - 1);
  const double big = v.cwiseAbs().maxCoeff();
  std::vector<int> moving;
  for (int k = 0; k < sys.nBodies; ++k)
    if (v.segment<3>(3 * k).cwiseAbs().maxCoeff() > 0.1 * big) {
      moving.push_back(k);
      s.bodies.push_back(sys.bodyIds[k]);
    }
  auto isMoving = [&](int b) { return std::find(moving.begin(), moving.end(), b) != moving.end(); };
  for (const Row& c : sys.cons)
    if (c.joint >= 0 && !c.isDriver() && c.kind != Primitive::Hold &&
        (isMoving(c.body[0]) || isMoving(c.body[1]) || isMoving(c.body[2])) &&
        std::find(s.joints.begin(), s.joints.end(), sys.jointIds[c.joint]) == s.joints.end())
      s.joints.push_back(sys.jointIds[c.joint]);
  if (!moving.empty()) s.message += " (" + bodyList(moving) + " can move with the crank held)";
}

Status KinematicsState::explainFailure(double phiFailed, bool crossing) {
  const double reached = (reg.phi - sys.startRad) / kDeg;
  const double wanted = (phiFailed - sys.startRad) / kDeg;
  // Near a dead point q' grows without bound (like 1 / sqrt of the distance to it).
  double speed = 0;
  std::vector<double> perBody(sys.nBodies, 0.0);
  for (int k = 0; k < sys.nBodies; ++k) {
    const BodyState& b = reg.body[k];
    perBody[k] = std::max({std::abs(b.v.x()), std::abs(b.v.y()), std::abs(b.w) * sys.size});
    speed = std::max(speed, perBody[k]);
  }
  Status s;
  s.crankDeg = wanted;
  s.lastReachedDeg = reached;
  if (speed > 1e2 * sys.size) {
    std::vector<int> involved;
    for (int k = 0; k < sys.nBodies; ++k)
      if (perBody[k] > 0.1 * speed) {
        involved.push_back(k);
        s.bodies.push_back(sys.bodyIds[k]);
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
    newton.derivatives(sys, coordinates(reg).q, dq, ddq);
    crossing = newton.nearness() < 1e-3;
  }
  if (crossing) {
    namePlace(coordinates(reg).q, s);
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

}  // namespace linkage
