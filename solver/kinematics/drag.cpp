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

#include "kinematics/kinematics_state.h"

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

// The descent for one point and target, on a state that can move.
class Descent {
 public:
  Descent(KinematicsState& k, const PointLocation& loc, const Vec2& target)
      : k_(k), loc_(loc), target_(target) {}

  // At most kMaxSteps steps; Ok, or the tracker's status where the motion stopped.
  Status run(Kinematics::DragResult& out) {
    const double L = k_.sys.size;
    Probe p = probe();
    for (int step = 0; step < kMaxSteps; ++step) {
      if (!std::isfinite(p.g))
        return Status::failure(StatusCode::Singular, "velocities are not determined here");
      const double phi0 = k_.cur().phi;
      const double h = newtonStep(p, phi0);
      // Converged: the point on the target, or a step below what an angle resolves.
      if (p.f <= 0.5 * (1e-13 * L) * (1e-13 * L) ||
          std::abs(h) <= 1e-13 * std::max(1.0, std::abs(phi0))) {
        out.converged = true;
        return Status::success();
      }
      Status s;
      switch (lineSearch(h, p, s)) {
        case Outcome::Moved:
          continue;
        case Outcome::Stopped:
          out.atLimit = s.code == StatusCode::Unreachable;
          out.converged = true;
          return s;
        case Outcome::Failed:
          return s;
        case Outcome::Nothing:
          // Nothing nearer within the halvings: back to where it was, as near as it gets.
          if (k_.cur().phi != phi0) {
            if (s = k_.moveToPhi(phi0); !s.ok()) return s;
          }
          out.converged = moves_ < kMaxMoves;
          return Status::success();
      }
    }
    return Status::success();
  }

 private:
  struct Probe {
    double f, g, H;  // f, f', and f'' (exact) or NaN
    double speed;    // |P'|
  };
  enum class Outcome { Moved, Stopped, Failed, Nothing };

  Probe probe() const {
    const KinematicsState::Snapshot& c = k_.cur();
    const BodyState& b = c.of(loc_.body);
    const Vec2 r = b.pos(loc_.s) - target_, dP = b.vel(loc_.s);
    const double H = c.accelerations ? dP.squaredNorm() + b.acc(loc_.s).dot(r) : NAN;
    return Probe{0.5 * r.squaredNorm(), dP.dot(r), H, dP.norm()};
  }

  // Newton's step where f'' > 0 (f'' exact, else the secant of f', else |P'|^2), the largest
  // downhill one where not; capped.
  double newtonStep(const Probe& p, double phi0) const {
    double H = p.H;
    if (!std::isfinite(H)) {
      const double secant = (p.g - gBefore_) / (phi0 - phiBefore_);
      H = std::isfinite(secant) && secant > 0 ? secant : p.speed * p.speed;
    }
    const double h = H > 0 ? -p.g / H : (p.g > 0 ? -kMaxStep : kMaxStep);
    return std::clamp(h, -kMaxStep, kMaxStep);
  }

  // Moves by h from the current pose, halving h until f falls. A limit position or a singular
  // one met on the way stops the motion there (Stopped, s says where) when it is on the way
  // down; Failed for any other failure of the tracker (s).
  Outcome lineSearch(double h, Probe& p, Status& s) {
    const double phi0 = k_.cur().phi;
    // A gain below what f resolves (its rounding, a few eps of f): near the minimum f' still
    // tells the way, f no longer does, so such a step is taken without the test that f fell.
    const bool withinRounding = 0.5 * std::abs(p.g * h) <= 1e-13 * p.f;
    for (; moves_ < kMaxMoves; ++moves_, h /= 2) {
      s = k_.moveToPhi(phi0 + h);
      const Probe q = probe();
      const bool stop = s.code == StatusCode::Unreachable || s.code == StatusCode::Singular ||
                        s.code == StatusCode::NotConverged;
      if (!s.ok() && !stop) return Outcome::Failed;
      // Stopped where it was: it is at the limit (or the singular position) already.
      if (!s.ok() && std::abs(k_.cur().phi - phi0) <= kStuck) return Outcome::Stopped;
      if (!(q.f < p.f || (withinRounding && s.ok() && q.f <= p.f * (1 + 1e-13)))) continue;
      ++moves_;
      // Stopped short of the step, nearer than before: if f falls beyond the stop, this is
      // as near as the motion goes; else the nearest position lies before it, go on from there.
      if (!s.ok() && (!std::isfinite(q.g) || q.g * h < 0)) return Outcome::Stopped;
      phiBefore_ = phi0;
      gBefore_ = p.g;
      p = q;
      return Outcome::Moved;
    }
    return Outcome::Nothing;
  }

  KinematicsState& k_;
  const PointLocation& loc_;
  const Vec2 target_;
  double phiBefore_ = NAN, gBefore_ = NAN;  // the pose before, for the secant
  int moves_ = 0;                           // of the tracker, this call
};

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
  return finish(Descent(*this, *loc, target).run(out));
}

}  // namespace linkage
