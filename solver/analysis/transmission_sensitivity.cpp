// A transmission angle's exact derivatives (linkage/transmission_sensitivity.h).
#include "linkage/transmission_sensitivity.h"

#include <cmath>

#include "analysis/sensitivity_space.h"
#include "kinematics/kinematics_state.h"
#include "linkage/guide.h"
#include "linkage/slot_sensitivity.h"
#include "linkage/space.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

// d(where the anchor is)/d(dimension dim): a point's, or an arc slot's centre's (in space in
// the frame of its class, as the solve holds it).
Vec2 anchorChange(const Kinematics& k, const Anchor& a, const Sensitivity& s, int dim) {
  if (!a.arc) return s.point(k, a.point, dim);
  const Slot& slot = *k.mechanism().slot(a.arc);
  const internal::SpaceMoves space(k.mechanism(), internal::system(k));
  const int cls = space.slotClass(slot);
  // An arc: transmissionJoints made it an anchor.
  const Vec2 centre = guideOf(space.slot(slot, cls))->centre;
  Vec2 dc;
  double drho;
  space.arcMove(slot, s.dims()[dim], cls, dc, drho);
  return s.point(k, slot.body, centre, dc, dim);
}

// A line's turn per unit of the dimension: cross(u, du) / |u|^2.
double lineTurn(const Vec2& u, const Vec2& du) {
  return cross(u, du) / u.squaredNorm();
}

// A dyad's turn from its link's line to the other's, radians, and its change.
double dyadTurn(const Kinematics& k, const TransmissionJoint& j, const Sensitivity* s, int dim,
                double* d) {
  const Vec2 u = j.linkOuter.at(k) - j.linkAt.at(k), w = j.otherOuter.at(k) - j.otherAt.at(k);
  if (s && d) {
    auto dp = [&](const Anchor& a) { return anchorChange(k, a, *s, dim); };
    *d =
        lineTurn(w, dp(j.otherOuter) - dp(j.otherAt)) - lineTurn(u, dp(j.linkOuter) - dp(j.linkAt));
  }
  return std::atan2(cross(u, w), u.dot(w));
}

// d(slotLine)/d(dimension d): the slot's ends' move in the frame slotLine reads. In space a
// ground slot's move is in the world (its ends' x, y and z), seen along the class's normal as
// the slot is; a body's is in its plane, turned into the class's frame as the slot is.
Vec2 slotLineChange(const Mechanism& m, const TransmissionJoint& j, const Dimension& d) {
  const SlotChange c = slotChange(m, j.slot, d);
  const Body* body = m.body(m.slot(j.slot)->body);
  if (!isSpatial(m) || !body) return c.p1 - c.p0;
  if (!body->ground) return planeClasses(m).of(body->plane).rot * Vec2(c.p1 - c.p0);
  double dz = 0;
  for (const Dimension::SlotMove& s : d.slots)
    if (s.slot == j.slot) dz += s.z1 - s.z0;
  const Plane f = planeClasses(m).frames[transmissionClass(m, j)];  // a copy: the classes go
  const Vec3 w((c.p1 - c.p0).x(), (c.p1 - c.p0).y(), dz);
  return Vec2(w.dot(f.xAxis), w.dot(f.yAxis));
}

// A rod's theta from the slot's line to the rod's, in (-90, 90] degrees as radians, and its
// change.
double rodTheta(const Kinematics& k, const TransmissionJoint& j, const Sensitivity* s, int dim,
                double* d) {
  const Mechanism& m = k.mechanism();
  const Slot& slot = *m.slot(j.slot);
  const Vec2 t = slotLine(m, j), line = k.bodyTransform(slot.body).R * t;
  const Vec2 u = j.linkAt.at(k) - j.linkOuter.at(k);
  if (s && d) {
    const double slotTurn =
        s->angle(k, slot.body, dim) + lineTurn(t, slotLineChange(m, j, s->dims()[dim]));
    *d = lineTurn(u, anchorChange(k, j.linkAt, *s, dim) - anchorChange(k, j.linkOuter, *s, dim)) -
         slotTurn;
  }
  double theta = std::atan2(cross(line, u), line.dot(u));
  if (theta > M_PI / 2) theta -= M_PI;
  if (theta <= -M_PI / 2) theta += M_PI;
  return theta;
}

}  // namespace

double transmissionAngleSensitivity(const Kinematics& k, const TransmissionJoint& j,
                                    const Sensitivity* sens, int dim, double* d) {
  double change = 0;
  double* dc = sens && d ? &change : nullptr;
  if (j.kind == TransmissionKind::Dyad) {
    const double turn = dyadTurn(k, j, sens, dim, dc);
    if (dc) *d = (turn < 0 ? -change : change) / kDeg;
    return std::abs(turn) / kDeg;
  }
  const double theta = rodTheta(k, j, sens, dim, dc);
  if (dc) *d = (theta < 0 ? change : -change) / kDeg;
  return 90 - std::abs(theta) / kDeg;
}

std::vector<double> transmissionAngleDerivatives(const Kinematics& k, const TransmissionJoint& j,
                                                 const Sensitivity& s) {
  std::vector<double> out(s.dims().size());
  for (size_t v = 0; v < out.size(); ++v)
    transmissionAngleSensitivity(k, j, &s, static_cast<int>(v), &out[v]);
  return out;
}

}  // namespace linkage
