#include "linkage/force_samples.h"

#include <cmath>

#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage {

namespace {

constexpr double kNaN = NAN;

// How a joint's reaction goes into the world on a machine in space (docs/dynamics.md, "Machines
// in space"): a force in the frame of its plane class (the class of its a body's plane; of b's,
// or of its slot's body's, when a is on the ground), with what it bears along the normal; a ball
// rod's pull along the rod; a bevel pair's couple alone.
struct JointInSpace {
  enum Kind { Planar, Rod, Bevel } kind = Planar;
  Plane frame;
  bool coupling = false;
};

JointInSpace jointInSpace(const Mechanism& m, const PlaneClasses& pc, const Joint& j) {
  JointInSpace x;
  const ElementKind& kind = kindOf(j);
  x.coupling = kind.role == Role::Coupling;
  const Point *a = m.point(j.a), *b = j.b ? m.point(j.b) : nullptr;
  if (kind.role == Role::Distance) x.kind = JointInSpace::Rod;
  if (x.coupling && a && b && !parallel(planeOf(m, a->body), planeOf(m, b->body)))
    x.kind = JointInSpace::Bevel;
  x.frame = pc.frames[0];
  const Slot* s = j.slot ? m.slot(j.slot) : nullptr;
  for (BodyId id : {a ? a->body : BodyId{}, b ? b->body : BodyId{}, s ? s->body : BodyId{}})
    if (const Body* body = m.body(id); body && !body->ground) {
      x.frame = pc.frames[pc.of(body->plane).cls];
      break;
    }
  return x;
}

// Joint j's reaction in the world at k's pose, and its tension or couple (NaN for none).
void inWorld(const Kinematics& k, const Joint& j, const JointInSpace& x, const JointReaction& r,
             Vec3& force, double& scalar) {
  scalar = x.kind == JointInSpace::Rod ? r.axialN : x.coupling ? r.transmittedNm : kNaN;
  if (x.kind == JointInSpace::Bevel) {
    force = Vec3::Constant(kNaN);
  } else if (x.kind == JointInSpace::Rod) {
    // The rod pulls a towards b by its tension.
    const Vec3 D = k.motionInSpace(j.b).position - k.motionInSpace(j.a).position;
    force = r.axialN * D.normalized();
  } else {
    const Plane& f = x.frame;
    force = r.force.x() * f.xAxis + r.force.y() * f.yAxis + r.normalN * f.normal();
  }
}

}  // namespace

SpaceReaction spaceReactionOf(const Mechanism& m, const Joint& j) {
  const JointInSpace::Kind kind = jointInSpace(m, planeClasses(m), j).kind;
  return kind == JointInSpace::Rod     ? SpaceReaction::Tension
         : kind == JointInSpace::Bevel ? SpaceReaction::Couple
                                       : SpaceReaction::Force;
}

void reactionInSpace(const Kinematics& k, int j, const JointReaction& r, Vec3& force,
                     double& tensionOrCouple) {
  const Mechanism& m = k.mechanism();
  const Joint& joint = m.joints[j];
  inWorld(k, joint, jointInSpace(m, planeClasses(m), joint), r, force, tensionOrCouple);
}

ForceSamples sampleForces(const Kinematics& k, long long steps, double revs, double rpm) {
  ForceSamples out;
  Kinematics probe = k;
  probe.setAccelerations(true);  // an editor may have them off while no view shows them
  if (rpm > 0) probe.setRpm(rpm);
  out.rpm = probe.valid() ? probe.rpm() : 0;
  out.steps = steps;
  ForceSolver solver;
  if (!(out.status = solver.prepare(probe)).ok()) return out;
  out.undetermined = solver.result().undetermined;
  const Mechanism& m = probe.mechanism();
  out.reactionN.assign(m.joints.size(), {});
  out.inSpace = isSpatial(m);
  std::vector<JointInSpace> space;
  if (out.inSpace) {
    const PlaneClasses pc = planeClasses(m);
    for (const Joint& j : m.joints) space.push_back(jointInSpace(m, pc, j));
    out.reaction3N.assign(m.joints.size(), {});
    out.axialOrCouple.assign(m.joints.size(), {});
  }
  const long long n = std::llround(static_cast<double>(steps) * revs);
  for (long long i = 0; i <= n; ++i) {
    const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(steps);
    if (Status s = probe.moveTo(deg); !s.ok()) return out.status = s, out;
    const Forces& f = solver.compute(probe);
    if (!f.status.ok()) return out.status = f.status, out;
    out.crankDeg.push_back(deg);
    out.driverTorqueNm.push_back(f.driverTorqueNm);
    out.shakingN.push_back(f.shakingForceN);
    out.shakingMomentNm.push_back(f.shakingMomentNm);
    for (size_t j = 0; j < f.joints.size(); ++j) out.reactionN[j].push_back(f.joints[j].force);
    if (!out.inSpace) continue;
    out.shaking3N.push_back(f.shakingForce3N);
    out.shakingMoment3Nm.push_back(f.shakingMoment3Nm);
    for (size_t j = 0; j < f.joints.size(); ++j) {
      Vec3 w;
      double x;
      inWorld(probe, m.joints[j], space[j], f.joints[j], w, x);
      out.reaction3N[j].push_back(w);
      out.axialOrCouple[j].push_back(x);
    }
  }
  out.complete = true;
  return out;
}

}  // namespace linkage
