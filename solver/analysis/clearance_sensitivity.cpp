// A closest approach's exact derivatives (linkage/clearance_sensitivity.h).
#include "linkage/clearance_sensitivity.h"

#include <algorithm>

namespace linkage {

namespace {

Status refused(std::string why) {
  return Status::failure(StatusCode::BadModel, std::move(why));
}

}  // namespace

ClearanceSensitivity clearanceSensitivity(const Kinematics& k, const ClearanceWatch& watch,
                                          std::vector<Dimension> dims) {
  ClearanceSensitivity out;
  const ClearancePart& other = watch.other;
  if (other.isSlot()) {
    out.status = refused("a clearance to a slot has no derivatives yet (a point or a segment)");
    return out;
  }
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
  if (!(out.status = s.prepare(at, std::move(dims))).ok()) return out;
  if (!(out.status = s.at(at)).ok()) return out;
  out.dims = s.dims();
  const Vec2 A = at.position(watch.point);
  Vec2 B = at.position(other.point);
  double t = 0;  // the nearest point's parameter on a segment
  if (other.isSegment()) {
    const Vec2 N = B, E = at.position(other.end), d = E - N;
    t = d.squaredNorm() > 0 ? std::clamp((A - N).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    B = N + t * d;
  }
  const Vec2 n = (A - B).normalized();
  for (size_t i = 0; i < out.dims.size(); ++i) {
    const int d = static_cast<int>(i);
    Vec2 dB = s.point(at, other.point, d);
    if (other.isSegment()) dB = (1 - t) * dB + t * s.point(at, other.end, d);
    out.derivative.push_back(n.dot(s.point(at, watch.point, d) - dB));
  }
  return out;
}

}  // namespace linkage
