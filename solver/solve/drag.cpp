// Dragging a point (Kinematics::dragTo): the mechanism moves along its one freedom, the driver
// angle phi, so that a point P comes as close as it can to a target T, as a hand pushing it would:
// a local descent of f(phi) = |P(phi) - T|^2 / 2 from the current pose.
//
//   f'  = P' . r                 r = P - T; P' = dP/dphi, exact (the solved velocities)
//   f'' = |P'|^2 + P'' . r       P'' = d2P/dphi2, exact where accelerations are computed
//
// A step is Newton's, -f'/f'', where f'' > 0. Gauss-Newton (|P'|^2 alone) is not enough: at a
// stationary point of P (a rocker at the end of its swing, a needle at a dead centre) P' -> 0 and
// its step -f'/|P'|^2 grows without bound, while the nearest position is exactly there; the P'' . r
// term keeps the step right. Without accelerations f'' is the secant of f' between the last two
// poses, else |P'|^2. Where f'' <= 0 (the distance is near a maximum) the step is the largest one,
// downhill. Every step is capped, goes through the tracker (moveToPhi), so it stays on its
// assembly branch however far the target is, and is halved until f falls.
#include <cmath>

#include "solve/kinematics_state.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180.0;
// At most this much crank per step: the descent stays local (it follows the valley it is in,
// as a hand would) and one call does bounded work, whatever the target.
constexpr double kMaxStep = 15 * kDeg;
// Per call: Newton steps, and moves of the tracker (a step and its halvings). An editor calls
// once per mouse move; a far target is reached over several calls.
constexpr int kMaxSteps = 8;
constexpr int kMaxMoves = 16;
// A tracker that stops within this of where it started has not moved: the start is the stop.
constexpr double kStuck = 1e-6 * kDeg;

}  // namespace

Kinematics::DragResult KinematicsState::drag(PointId id, const Vec2& target) {
  Kinematics::DragResult out;
  const PointLocation* loc = valid ? sys.point(id) : nullptr;
  auto finish = [&](Status s) {
    out.status = std::move(s);
    out.crankDeg = valid ? crankDeg() : NAN;
    out.distance = loc ? (cur().of(loc->body).pos(loc->s) - target).norm() : NAN;
    return out;
  };
  if (!valid) return finish(Status::badModel("no mechanism is loaded"));
  if (!sys.hasDriver) return finish(Status::badModel("the mechanism has no driver to move it by"));
  if (!loc) return finish(Status::badModel("unknown point"));
  if (!target.allFinite()) return finish(Status::badModel("the target is not a finite point"));
  const std::string label = mech.pointLabel(id);
  if (loc->body < 0) return finish(Status::badModel(label + " is on the ground: it does not move"));
  for (int k : structure.freeBodies)
    if (k == loc->body)
      return finish(Status::badModel(label + " is on a body the driver does not move (bodies " +
                                     bodyList(structure.freeBodies) + " are held where they are)"));
  // At a singular position velocities are not known: start from the last regular one, a step
  // away at most.
  if (atSingular) {
    if (Status s = moveToPhi(reg.phi); !s.ok()) return finish(s);
  }

  struct Probe {
    double f, g, H;  // f, f', and f'' (exact) or NaN
    double speed;    // |P'|
  };
  auto probe = [&] {
    const Snapshot& c = cur();
    const BodyState& b = c.of(loc->body);
    const Vec2 r = b.pos(loc->s) - target, dP = b.vel(loc->s);
    const double H = c.accelerations ? dP.squaredNorm() + b.acc(loc->s).dot(r) : NAN;
    return Probe{0.5 * r.squaredNorm(), dP.dot(r), H, dP.norm()};
  };
  const double L = sys.size;
  double phiBefore = NAN, gBefore = NAN;
  int moves = 0;
  Probe p = probe();
  for (int step = 0; step < kMaxSteps; ++step) {
    if (!std::isfinite(p.g))
      return finish(Status::failure(StatusCode::Singular, "velocities are not determined here"));
    const double phi0 = cur().phi;
    double H = p.H;
    if (!std::isfinite(H)) {
      const double secant = (p.g - gBefore) / (phi0 - phiBefore);
      H = std::isfinite(secant) && secant > 0 ? secant : p.speed * p.speed;
    }
    double h = H > 0 ? -p.g / H : (p.g > 0 ? -kMaxStep : kMaxStep);
    h = std::clamp(h, -kMaxStep, kMaxStep);
    // Converged: the point on the target, or a step below what an angle resolves.
    if (p.f <= 0.5 * (1e-13 * L) * (1e-13 * L) ||
        std::abs(h) <= 1e-13 * std::max(1.0, std::abs(phi0))) {
      out.converged = true;
      return finish(Status::success());
    }
    // A gain below what f resolves (its rounding, a few eps of f): near the minimum f' still
    // tells the way, f no longer does, so such a step is taken without the test that f fell.
    const bool withinRounding = 0.5 * std::abs(p.g * h) <= 1e-13 * p.f;
    // Halve the step until f falls; a limit position or a singular one stops the motion there.
    bool moved = false;
    for (; moves < kMaxMoves && !moved; ++moves) {
      const Status s = moveToPhi(phi0 + h);
      const Probe q = probe();
      if (!s.ok() && s.code != StatusCode::Unreachable && s.code != StatusCode::Singular &&
          s.code != StatusCode::NotConverged)
        return finish(s);
      if (!s.ok() && std::abs(cur().phi - phi0) <= kStuck) {
        // Stopped where it was: it is at the limit (or the singular position) already.
        out.atLimit = s.code == StatusCode::Unreachable;
        out.converged = true;
        return finish(s);
      }
      if (!(q.f < p.f || (withinRounding && s.ok() && q.f <= p.f * (1 + 1e-13)))) {
        h /= 2;
        continue;
      }
      moved = true;
      if (!s.ok()) {
        // Stopped short of the step, nearer than before. Beyond it f would fall further (the
        // stop is on the way down): this is as near as the motion goes. Otherwise the nearest
        // position lies before the stop: go on from there.
        if (!std::isfinite(q.g) || q.g * h < 0) {
          out.atLimit = s.code == StatusCode::Unreachable;
          out.converged = true;
          return finish(s);
        }
      }
      phiBefore = phi0;
      gBefore = p.g;
      p = q;
    }
    if (!moved) {
      // Nothing nearer within the halvings: back to where it was, which is as near as it gets.
      if (cur().phi != phi0) {
        if (Status s = moveToPhi(phi0); !s.ok()) return finish(s);
      }
      out.converged = moves < kMaxMoves;
      return finish(Status::success());
    }
  }
  return finish(Status::success());
}

}  // namespace linkage
