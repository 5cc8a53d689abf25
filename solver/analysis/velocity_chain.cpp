#include "linkage/velocity_chain.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "linkage/elements.h"

namespace linkage {

namespace {

Status fail(StatusCode code, std::string msg) {
  return Status::failure(code, std::move(msg));
}

std::string ic(int i, int j) {
  return "IC(" + std::to_string(std::min(i, j)) + "," + std::to_string(std::max(i, j)) + ")";
}

// One step: `from` moves as `motion`; finds the motion of `to` through IC(from, to).
Status step(const InstantCentres& ics, int from, int to, const BodyMotion& motion, ChainStep& s) {
  s = ChainStep{};
  s.from = from;
  s.to = to;
  s.fromMotion = motion;
  const InstantCentre* c = ics.find(from, to);
  const InstantCentre* g = ics.find(1, to);
  if (!c || !g) return fail(StatusCode::BadModel, "no body numbered " + std::to_string(to));
  auto undetermined = [&](const InstantCentre* x) {
    return fail(StatusCode::NotConverged,
                ic(x->i, x->j) + " is not determined at this position" +
                    (ics.velocitiesValid ? " (the two bodies do not move relative to each other)"
                                         : " (no velocities at a singular position)"));
  };
  if (c->across)
    return fail(StatusCode::BadModel,
                ic(c->i, c->j) + " does not exist: bodies " + std::to_string(c->i) + " and " +
                    std::to_string(c->j) +
                    " move in planes that are not parallel (a chain of centres stays among "
                    "bodies of parallel planes)");
  if (!c->determined) return undetermined(c);
  // Ground centre undetermined with velocities known: `to` does not move at this instant.
  const bool toAtRest = !g->determined && ics.velocitiesValid;
  if (!g->determined && !toAtRest) return undetermined(g);
  BodyMotion& out = s.toMotion;
  if (c->atInfinity()) {
    // The two bodies translate relative to each other: the same angular velocity.
    s.centreAtInfinity = true;
    s.centre = c->direction();
    const double omega = motion.kind == BodyMotion::Kind::Turns ? motion.omega : 0.0;
    if (toAtRest) {
      out.kind = BodyMotion::Kind::AtRest;
    } else if (!g->atInfinity()) {
      out.kind = BodyMotion::Kind::Turns;
      out.pivot = g->point();
      out.omega = omega;
    } else if (omega != 0) {
      return fail(StatusCode::NotConverged,
                  ic(from, to) + " and " + ic(1, to) + " are both at infinity, but body " +
                      std::to_string(from) + " turns: the centres are inconsistent");
    } else {
      return fail(StatusCode::NotConverged, ic(from, to) + " and " + ic(1, to) +
                                                " are both at infinity: the step gives "
                                                "the direction of body " +
                                                std::to_string(to) +
                                                "'s translation, not its speed");
    }
    return Status::success();
  }
  s.centre = c->point();
  s.vP = motion.velocityAt(s.centre);
  if (motion.kind == BodyMotion::Kind::Turns) s.fromArm = (s.centre - motion.pivot).norm();
  if (toAtRest) {
    out.kind = BodyMotion::Kind::AtRest;
  } else if (g->atInfinity()) {
    out.kind = BodyMotion::Kind::Translates;
    out.v = s.vP;
  } else {
    const Vec2 r = s.centre - g->point();
    s.toArm = r.norm();
    if (!(s.toArm > 1e-9 * ics.size))
      return fail(StatusCode::NotConverged, ic(from, to) + " coincides with " + ic(1, to) +
                                                ": the step does not fix body " +
                                                std::to_string(to) + "'s angular velocity");
    out.kind = BodyMotion::Kind::Turns;
    out.pivot = g->point();
    // v_P = omega perp(r), so r x v_P = omega |r|^2.
    out.omega = (r.x() * s.vP.y() - r.y() * s.vP.x()) / (s.toArm * s.toArm);
  }
  return Status::success();
}

Status follow(const InstantCentres& ics, const std::vector<int>& bodies, const BodyMotion& start,
              std::vector<ChainStep>& steps, BodyMotion& end) {
  steps.clear();
  BodyMotion motion = start;
  for (size_t i = 1; i < bodies.size(); ++i) {
    ChainStep s;
    if (Status st = step(ics, bodies[i - 1], bodies[i], motion, s); !st.ok()) {
      st.message = "step " + std::to_string(i) + " (body " + std::to_string(bodies[i - 1]) +
                   " to body " + std::to_string(bodies[i]) + "): " + st.message;
      return st;
    }
    motion = s.toMotion;
    steps.push_back(s);
  }
  end = motion;
  return Status::success();
}

}  // namespace

namespace {

// The crank: the driven body pivoted to the ground, at the driver's speed and direction.
Status startFromCrank(const Kinematics& k, const InstantCentres& ics, VelocityChain& ch) {
  const Mechanism& m = k.mechanism();
  const Joint* dj = m.driver ? m.joint(m.driver->joint) : nullptr;
  if (!dj || kindOf(*dj).role != Role::Revolute || !m.point(dj->a) || !m.point(dj->b))
    return fail(StatusCode::BadModel, "the mechanism has no driver to start the chain from");
  const BodyId ground = ics.bodies[0];
  const BodyId ba = m.point(dj->a)->body, bb = m.point(dj->b)->body;
  const double sigma = m.driver->direction == Direction::Cw ? -1.0 : 1.0;
  ch.crankMotion.kind = BodyMotion::Kind::Turns;
  ch.crankMotion.pivot = k.position(dj->a);
  if (ba == ground) {
    ch.crank = ics.numberOf(bb);
    ch.crankMotion.omega = sigma * k.omega();
  } else if (bb == ground) {
    ch.crank = ics.numberOf(ba);
    ch.crankMotion.omega = -sigma * k.omega();
  } else {
    return fail(StatusCode::BadModel,
                "the driver at " + jointName(m, dj->id) +
                    " turns one moving body relative to another: the chain starts from a "
                    "crank pivoted to the ground");
  }
  return Status::success();
}

// The bodies the chain goes through: the crank, those of `via`, the point's body.
Status chainBodies(const InstantCentres& ics, const VelocityChain& ch, const std::vector<int>& via,
                   std::vector<int>& bodies) {
  bodies = {ch.crank};
  for (int v : via) {
    if (v == 1 || !ics.bodyNumbered(v))
      return fail(StatusCode::BadModel, v == 1 ? "the chain cannot go through the ground (body 1)"
                                               : "no body numbered " + std::to_string(v));
    if (v == bodies.back())
      return fail(StatusCode::BadModel, "body " + std::to_string(v) + " twice in a row");
    bodies.push_back(v);
  }
  if (bodies.back() != ch.body) bodies.push_back(ch.body);
  return Status::success();
}

// Follows the chain through `bodies`; where the direct step (no `via`) does not work here,
// through the first intermediate body that does.
Status followChain(const InstantCentres& ics, const std::vector<int>& bodies, bool direct,
                   VelocityChain& ch) {
  Status status = follow(ics, bodies, ch.crankMotion, ch.steps, ch.bodyMotion);
  if (status.ok() || !direct) return status;
  for (int n : ics.numbers) {
    if (n == 1 || n == ch.crank || n == ch.body) continue;
    if (follow(ics, {ch.crank, n, ch.body}, ch.crankMotion, ch.steps, ch.bodyMotion).ok())
      return Status::success();
  }
  ch.steps.clear();
  return status;
}

}  // namespace

Vec2 BodyMotion::velocityAt(const Vec2& x) const {
  switch (kind) {
    case Kind::Turns:
      return omega * perp(x - pivot);
    case Kind::Translates:
      return v;
    case Kind::AtRest:
      break;
  }
  return Vec2::Zero();
}

VelocityChain velocityChain(const Kinematics& k, const InstantCentres& ics, PointId point,
                            const std::vector<int>& via) {
  VelocityChain ch;
  ch.point = point;
  if (!ics.status.ok()) {
    ch.status = ics.status;
    return ch;
  }
  if (!k.valid() || ics.revision != k.revision() || ics.crankDeg != k.crankDeg()) {
    ch.status = fail(StatusCode::BadModel,
                     "the instant centres are of another mechanism, another revision of it or "
                     "another crank angle than the kinematics: compute them again");
    return ch;
  }
  const Point* pt = k.mechanism().point(point);
  if (!pt) {
    ch.status = fail(StatusCode::BadModel, "unknown point");
    return ch;
  }
  ch.body = ics.numberOf(pt->body);
  ch.position = k.position(point);
  if (k.derivativesValid()) ch.solverVelocity = k.velocity(point);
  if (ch.status = startFromCrank(k, ics, ch); !ch.status.ok()) return ch;
  if (ch.body == 1) {
    ch.bodyMotion.kind = BodyMotion::Kind::AtRest;
    if (!via.empty()) ch.status = fail(StatusCode::BadModel, "the point is on the ground");
    return ch;
  }
  std::vector<int> bodies;
  if (ch.status = chainBodies(ics, ch, via, bodies); !ch.status.ok()) return ch;
  if (ch.status = followChain(ics, bodies, via.empty(), ch); !ch.status.ok()) return ch;
  ch.velocity = ch.bodyMotion.velocityAt(ch.position);
  if (ch.bodyMotion.kind == BodyMotion::Kind::Turns)
    ch.arm = (ch.position - ch.bodyMotion.pivot).norm();
  return ch;
}

}  // namespace linkage
