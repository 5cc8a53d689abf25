// Branch flip (Kinematics::flipBranch): a group of the closed-form plan put on its other
// assembly at the current crank angle, the groups that depend on it re-solved on their own
// branches; and the design redrawn on the new branch, so that a file keeps the choice (a load
// assembles a drawing on the branch it is drawn on).
#include <cmath>

#include "kinematics/kinematics_state.h"

namespace linkage {

namespace {

// Moves below this (of the mechanism's size L) are rounding: a body that the redrawing would
// move less keeps its drawn coordinates exactly.
constexpr double kRounding = 1e-12;

// The largest distance any point or slot end of each body moves from `a` to `b`.
std::vector<double> moves(const Mechanism& m, const System& sys, const Motion& a, const Motion& b) {
  std::vector<double> out(sys.nBodies, 0.0);
  auto consider = [&](BodyId body, const Vec2& p) {
    const int k = sys.bodyIndex(body);
    if (k < 0) return;
    const Vec2 s = p - sys.frameOrigin[k];
    out[k] = std::max(out[k], (a.body[k].pos(s) - b.body[k].pos(s)).norm());
  };
  for (const Point& p : m.points) consider(p.body, p.pos);
  for (const Slot& s : m.slots) {
    consider(s.body, s.p0);
    consider(s.body, s.p1);
  }
  return out;
}

}  // namespace

std::vector<BodyId> KinematicsState::flippableBodies() const {
  std::vector<BodyId> out;
  if (!valid || !plan) return out;
  for (int k = 0; k < sys.nBodies; ++k)
    if (plan->hasMirror(plan->groupOfBody(k))) out.push_back(sys.bodyIds[k]);
  return out;
}

Status KinematicsState::flip(int group, const std::string& what, Mechanism* redrawn) {
  if (!plan) {
    return Status::badModel(
        what + " is solved by the general solve, not group by group in closed form (" +
        (opt.closedForm ? "the mechanism is not a crank with dyads and core groups only, or has "
                          "redundant joints or freedoms the driver leaves"
                        : "the closed-form groups are switched off") +
        "): there is no mirror assembly to put it on");
  }
  if (group < 0 || !plan->hasMirror(group))
    return Status::badModel(what +
                            " is solved with the crank, which has one position at each crank "
                            "angle: there is no other assembly to put it on");
  std::vector<BodyId> bodies;
  for (int b : plan->bodiesOf(group)) bodies.push_back(sys.bodyIds[b]);
  auto failure = [&](StatusCode code, std::string msg) {
    Status s = Status::failure(code, std::move(msg));
    s.crankDeg = crankDeg();
    s.bodies = bodies;
    return s;
  };
  if (atSingular)
    return failure(StatusCode::Singular,
                   "the mechanism is at a singular position, where its assemblies meet: turn "
                   "the crank away from it first");
  ClosedFormPlan flipped = *plan;
  Snapshot now;
  if (!flipped.flip(group, sys, reg, now))
    return failure(StatusCode::AssemblyFailed,
                   "the other assembly of " + what +
                       " cannot be closed at this crank angle: a group that depends on it does "
                       "not close there, or is at a dead point");
  const std::vector<double> moved = moves(mech, sys, reg, now);
  double most = 0;
  for (BodyId b : bodies) most = std::max(most, moved[sys.bodyIndex(b)]);
  if (most <= 1e-9 * sys.size)
    return failure(StatusCode::Singular,
                   "the two assemblies of " + what +
                       " coincide at this crank angle (its links are in line): turn the crank "
                       "away from here first");
  now.regular = true;
  now.coordinates = false;
  if (redrawn) {
    // The flipped state turned back to the drawing's driver angle (0: crank angle minus the
    // start offset), along its new branch.
    KinematicsState back = *this;
    back.plan = flipped;
    back.reg = now;
    if (Status s = back.moveToPhi(0.0); !s.ok()) {
      s.message = "the other assembly of " + what +
                  " cannot be turned back to where the mechanism is drawn, so it cannot be " +
                  "redrawn there: " + s.message;
      return s;
    }
    *redrawn = drawnAt(back.reg);
  }
  plan = std::move(flipped);
  reg = std::move(now);
  return Status::success();
}

Mechanism KinematicsState::drawnAt(const Motion& at) const {
  Motion sketch;
  const Eigen::VectorXd q = sketchCoordinates(sys), zero = Eigen::VectorXd::Zero(q.size());
  sketch.fromCoordinates(0, q, zero, zero);
  const std::vector<double> shift = moves(mech, sys, at, sketch);
  Mechanism out = mech;
  auto redraw = [&](BodyId body, Vec2& p) {
    const int k = sys.bodyIndex(body);
    if (k < 0 || shift[k] <= kRounding * sys.size) return;
    p = at.body[k].pos(p - sys.frameOrigin[k]);
  };
  for (Point& p : out.points) redraw(p.body, p.pos);
  for (Slot& s : out.slots) {
    redraw(s.body, s.p0);
    redraw(s.body, s.p1);
  }
  return out;
}

}  // namespace linkage
