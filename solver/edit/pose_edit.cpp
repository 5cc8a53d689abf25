// editAtPose (linkage/edits.h): an edit made at the current pose, redrawn at the sketch's.
#include <cmath>

#include "linkage/edits.h"

namespace linkage {

namespace {

// Its centre of mass and counterweights too: the file holds them in sketch coordinates, so a
// body redrawn without them would carry its mass somewhere else.
void transformBody(Mechanism& m, BodyId b, const Transform& T) {
  if (Body* body = m.body(b); body && body->mass) {
    body->mass->com = T * body->mass->com;
    for (PointMass& w : body->mass->counterweights) w.at = T * w.at;
  }
  for (Point& p : m.points)
    if (p.body == b) p.pos = T * p.pos;
  for (Slot& s : m.slots)
    if (s.body == b) {
      s.p0 = T * s.p0;
      s.p1 = T * s.p1;
      if (s.mid) s.mid = T * *s.mid;
    }
}

bool isIdentity(const Transform& T, double size) {
  return std::abs(T.R.s) <= 1e-15 && T.R.c > 0 && T.t.norm() <= 1e-15 * size;
}

// Redraws m at k's pose (k holds m).
void redraw(Mechanism& m, const Kinematics& k) {
  for (const Body& b : m.bodies)
    if (!b.ground && k.contains(b.id)) {
      const Transform T = k.bodyTransform(b.id);
      if (!isIdentity(T, k.size())) transformBody(m, b.id, T);
    }
}

}  // namespace

PoseEdit editAtPose(const Kinematics& current, Mechanism next) {
  PoseEdit out;
  // Solved from the pose before the edit (the current one): where the user drew it.
  out.kinematics = current;
  out.solved = current.valid() && out.kinematics.edit(next).ok();
  if (out.solved && next.driver) {
    const double sketchDeg = -next.driver->startDeg;
    if (std::abs(out.kinematics.crankDeg() - sketchDeg) <= 1e-12) {
      // At the sketch's pose already: the bodies the solve moved to close the loops (a typed
      // dimension that no longer fits) are drawn where they are, so that the file closes.
      redraw(next, out.kinematics);
      out.solved = out.kinematics.edit(next).ok();
    } else {
      Kinematics atSketch = out.kinematics;
      if (atSketch.moveTo(sketchDeg).ok()) {
        redraw(next, atSketch);
        // The same shapes moved rigidly to the same sketch pose: the solution here does not
        // change, nor does the crank angle.
        out.solved = out.kinematics.edit(next).ok();
      } else {
        // The sketch's pose is out of reach now: the drawing becomes this pose, and crank
        // angle 0 with it (a file must reach its crank angle 0 to load).
        redraw(next, out.kinematics);
        next.driver->startDeg = 0;
        out.solved = out.kinematics.load(next).ok();
      }
    }
  }
  out.design = std::move(next);
  return out;
}

}  // namespace linkage
