// A closest approach's exact derivatives (linkage/clearance_sensitivity.h).
#include "linkage/clearance_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "linkage/guide.h"
#include "linkage/slot_sensitivity.h"
#include "linkage/space.h"

namespace linkage {

namespace {

Status refused(std::string why) {
  return Status::failure(StatusCode::BadModel, std::move(why));
}

// The nearest point B of the other part to the point A at the pose, and its derivative in each
// dimension with B held at its place on the part (the envelope theorem: along the part the
// distance is stationary there, or B is an end).
struct Nearest {
  Vec2 at = Vec2::Zero();
  std::function<Vec2(int)> change;
};

// A segment: B = (1 - t) N + t E.
Nearest onSegment(const Kinematics& at, const Sensitivity& s, const ClearancePart& other,
                  const Vec2& A) {
  const Vec2 N = at.position(other.point), E = at.position(other.end), d = E - N;
  const double t =
      d.squaredNorm() > 0 ? std::clamp((A - N).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return {N + t * d, [&at, &s, other, t](int dim) {
            return Vec2((1 - t) * s.point(at, other.point, dim) + t * s.point(at, other.end, dim));
          }};
}

// A slot: B is fixed in the slot's body and moves in its drawing as the slot does: a straight
// slot's point at t between its ends as they move; an arc's end as it moves, or its point in
// between, radially with the centre and the radius (a move along the arc is no change: B is
// the nearest point).
Nearest onSlot(const Kinematics& at, const Sensitivity& s, SlotId id, const Vec2& A) {
  const Mechanism& m = at.mechanism();
  const Slot& slot = *m.slot(id);
  const Guide g = *guideOf(slot);  // findClearance measured to it
  const Vec2 As = at.toSketch(slot.body, A), Bs = g.nearest(As);
  const double along = g.along(As), length = g.length();
  const double t = along <= 0 ? 0 : along >= length ? 1 : g.arc ? NAN : along / length;
  const Vec2 radial = g.arc ? Vec2((Bs - g.centre) / g.radius) : Vec2::Zero();
  return {at.toWorld(slot.body, Bs), [&at, &s, &m, id, body = slot.body, Bs, t, radial](int dim) {
            const SlotChange c = slotChange(m, id, s.dims()[dim]);
            const Vec2 own = std::isnan(t) ? Vec2(c.centre + c.radius * radial)
                                           : Vec2((1 - t) * c.p0 + t * c.p1);
            return s.point(at, body, Bs, own, dim);
          }};
}

// On a machine in space, in the world (findClearance's distance there: to a point or a
// segment): d(least)/dp = n . (dA - dB), B the nearest point of the segment at its parameter.
void inSpace(const Kinematics& at, const Sensitivity& s, const ClearanceWatch& watch,
             ClearanceSensitivity& out) {
  const ClearancePart& other = watch.other;
  auto world = [&](PointId p) { return Vec3(at.motionInSpace(p).position); };
  const Vec3 A = world(watch.point), N = world(other.point);
  double t = 0;
  Vec3 B = N;
  if (other.isSegment()) {
    const Vec3 d = world(other.end) - N;
    t = d.squaredNorm() > 0 ? std::clamp((A - N).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    B = N + t * d;
  }
  const Vec3 n = (A - B).normalized();
  for (size_t i = 0; i < out.dims.size(); ++i) {
    const int d = static_cast<int>(i);
    Vec3 dB = s.point3(at, other.point, d);
    if (other.isSegment()) dB = (1 - t) * dB + t * s.point3(at, other.end, d);
    out.derivative.push_back(n.dot(s.point3(at, watch.point, d) - dB));
  }
}

}  // namespace

ClearanceSensitivity clearanceSensitivity(const Kinematics& k, const ClearanceWatch& watch,
                                          std::vector<Dimension> dims) {
  ClearanceSensitivity out;
  const ClearancePart& other = watch.other;
  out.clearance = findClearance(k, ClearancePart::of(watch.point), other);
  const Clearance& c = out.clearance;
  if (!(out.status = c.status).ok()) return out;
  if (!c.periodic)
    out.status = refused(
        "the motion does not repeat after a turn: an end of the turn may be "
        "the closest, where the theorem does not hold");
  else if (c.runsAlong || !(c.closest.distance > 1e-9))
    out.status = refused(
        "the two touch at the closest approach: the least distance (0) has no "
        "derivative there");
  if (!out.status.ok()) return out;
  Kinematics at = k;
  Sensitivity s;
  if (!(out.status = at.moveTo(c.closest.crankDeg)).ok()) return out;
  const bool space = isSpatial(at.mechanism());
  if (!(out.status = s.prepare(at, std::move(dims),
                               space ? Sensitivity::Space::World : Sensitivity::Space::Refuse))
           .ok())
    return out;
  if (!(out.status = s.at(at)).ok()) return out;
  out.dims = s.dims();
  if (space) return inSpace(at, s, watch, out), out;
  const Vec2 A = at.position(watch.point);
  const Nearest B =
      other.isSlot() ? onSlot(at, s, other.slot, A)
      : other.isSegment()
          ? onSegment(at, s, other, A)
          : Nearest{at.position(other.point), [&](int d) { return s.point(at, other.point, d); }};
  const Vec2 n = (A - B.at).normalized();
  for (size_t i = 0; i < out.dims.size(); ++i) {
    const int d = static_cast<int>(i);
    out.derivative.push_back(n.dot(s.point(at, watch.point, d) - B.change(d)));
  }
  return out;
}

}  // namespace linkage
