// A closest approach's exact derivatives (linkage/clearance_sensitivity.h).
#include "linkage/clearance_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "analysis/sensitivity_space.h"
#include "analysis/space_distance.h"
#include "kinematics/kinematics_state.h"
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

// The move along its class's normal of a plane whose origin dimension `dim` is (its component
// of the world axis), else 0: a moving body's slot goes with its plane.
double planeDepthChange(const Mechanism& m, const Body& body, const Dimension& dim) {
  const Plane* plane = planeNamed(m, body.plane);
  const std::string origin = "planes." + (plane ? plane->name : "") + ".origin.";
  return plane && dim.name.rfind(origin, 0) == 0 && dim.name.size() == origin.size() + 1
             ? plane->normal()[dim.name.back() - 'x']
             : 0.0;
}

// A straight slot's end e in the world moved by dimension d (per unit): the ground's as the
// dimension moves it (x, y and z); a moving body's as its body moves in its class's frame, its
// move in its plane turned into that frame, lifted with its plane's move along the normal (a
// plane's origin alone moves it so).
Vec3 slotEndChange(const Kinematics& at, const Sensitivity& s, const Slot& slot, int e, int d) {
  const Mechanism& m = at.mechanism();
  const Dimension& dim = s.dims()[d];
  const SlotChange c = slotChange(m, slot.id, dim);
  const Vec2 own = e ? c.p1 : c.p0;
  const Body* body = m.body(slot.body);
  if (!body || body->ground) {
    double dz = 0;
    for (const Dimension::SlotMove& mv : dim.slots)
      if (mv.slot == slot.id) dz += e ? mv.z1 : mv.z0;
    return Vec3(own.x(), own.y(), dz);
  }
  const PlaneClasses pc = planeClasses(m);
  const PlaneInClass& in = pc.of(body->plane);
  const Plane& f = pc.frames[in.cls];
  const Vec2 v = s.point(at, slot.body, in.toClass(e ? slot.p1 : slot.p0), in.rot * own, d);
  return v.x() * f.xAxis + v.y() * f.yAxis + planeDepthChange(m, *body, dim) * f.normal();
}

// The point B of an arc slot nearest the watched point (world), inside its span, moved by
// dimension d: B stays on its radius in the slot's drawing, which the arc's centre and radius
// move (in its class's frame; the ground's arc along the normal as its points move, the same
// for each of them under its own dimensions), and goes where the body takes it.
Vec3 arcPointChange(const Kinematics& at, const Sensitivity& s, const Slot& slot, const Vec3& B,
                    int d) {
  const Mechanism& m = at.mechanism();
  const Dimension& dim = s.dims()[d];
  const internal::SpaceMoves space(m, internal::system(at));
  const int cls = space.slotClass(slot);
  const Plane& f = internal::system(at).frames[cls];
  const Guide g = *guideOf(space.slot(slot, cls));
  const Vec2 drawn = at.toSketch(slot.body, intoSlotClass(m, slot, B));
  Vec2 dc;
  double drho;
  space.arcMove(slot, dim, cls, dc, drho);
  const Vec2 own = dc + drho * (drawn - g.centre) / g.radius;
  const Body* body = m.body(slot.body);
  if (body && !body->ground) {
    const Vec2 v = s.point(at, slot.body, drawn, own, d);
    return v.x() * f.xAxis + v.y() * f.yAxis + planeDepthChange(m, *body, dim) * f.normal();
  }
  double along = 0;
  for (const Dimension::SlotMove& mv : dim.slots)
    if (mv.slot == slot.id)
      along +=
          f.normal().dot(
              Vec3(mv.p0.x(), mv.p0.y(), mv.z0) + Vec3(mv.p1.x(), mv.p1.y(), mv.z1) +
              Vec3(mv.mid.value_or(Vec2::Zero()).x(), mv.mid.value_or(Vec2::Zero()).y(), mv.zm)) /
          3;
  return own.x() * f.xAxis + own.y() * f.yAxis + along * f.normal();
}

// On a machine in space, in the world (findClearance's distance there: to a point, a segment or
// a slot's curve): d(least)/dp = n . (dA - dB), B the nearest point of the part held at its
// place on it (a segment's or a straight slot's parameter; an arc's end or radius).
void inSpace(const Kinematics& at, const Sensitivity& s, const ClearanceWatch& watch,
             ClearanceSensitivity& out) {
  const ClearancePart& other = watch.other;
  auto world = [&](PointId p) { return Vec3(at.motionInSpace(p).position); };
  const Slot* slot = other.isSlot() ? at.mechanism().slot(other.slot) : nullptr;
  const Vec3 A = world(watch.point);
  Vec3 B;
  std::function<Vec3(int)> dB;
  if (slot && slot->arc()) {
    int end = -1;
    spaceDistanceToArc(at, watch.point, *slot, &B, &end);
    dB = [&, end, B](int d) {
      return end >= 0 ? slotEndChange(at, s, *slot, end, d) : arcPointChange(at, s, *slot, B, d);
    };
  } else {
    SpaceMotion ends[2];
    if (slot) slotEndsInSpace(at, *slot, ends);
    const Vec3 N = slot ? ends[0].r : world(other.point);
    double t = 0;
    B = N;
    if (other.isSegment() || slot) {
      const Vec3 e = (slot ? ends[1].r : world(other.end)) - N;
      t = e.squaredNorm() > 0 ? std::clamp((A - N).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
      B = N + t * e;
    }
    dB = [&, t](int d) -> Vec3 {
      if (slot)
        return (1 - t) * slotEndChange(at, s, *slot, 0, d) + t * slotEndChange(at, s, *slot, 1, d);
      const Vec3 n0 = s.point3(at, other.point, d);
      return other.isSegment() ? Vec3((1 - t) * n0 + t * s.point3(at, other.end, d)) : n0;
    };
  }
  const Vec3 n = (A - B).normalized();
  for (size_t i = 0; i < out.dims.size(); ++i) {
    const int d = static_cast<int>(i);
    out.derivative.push_back(n.dot(s.point3(at, watch.point, d) - dB(d)));
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
