// Clearance: see linkage/clearance.h.
#include "linkage/clearance.h"

#include <algorithm>
#include <optional>

#include "analysis/slot_frame.h"
#include "linkage/guide.h"

namespace linkage {

namespace {

// The signed distance the minima are found on: the distance itself between two points; from a
// slot's line (along its normal) or circle (outside positive), so that a point crossing it
// passes through zero with a non-zero slope.
CycleQuantity signedDistance(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b,
                             Status& why) {
  const Mechanism& m = k.mechanism();
  if (a.slot && b.slot) {
    why = Status::badModel("the clearance between two slots is not measured: give a point");
    return {};
  }
  if (a.slot) return signedDistance(k, b, a, why);
  if (!k.contains(a.point) || (b.point && !k.contains(b.point)) || (b.slot && !k.contains(b.slot)))
    why = Status::badModel("the point or slot is not in the mechanism");
  else if (b.point)
    why = k.checkDetermined({a.point, b.point});
  else if (m.point(a.point)->body == m.slot(b.slot)->body)
    why = Status::badModel("the point " + m.pointLabel(a.point) + " is on the body of the slot " +
                           m.slotLabel(b.slot) + ": their distance does not change");
  else
    why = k.checkDetermined({a.point});
  if (!why.ok()) return {};
  const PointId p = a.point;
  if (b.point) {
    const PointId q = b.point;
    return [p, q](const Kinematics& at) {
      const double rate = secondsPerDegree(at);
      const Kinematics::PointMotion u = at.motion(p), v = at.motion(q);
      return lengthOf(u.position - v.position, (u.velocity - v.velocity) * rate,
                      (u.acceleration - v.acceleration) * (rate * rate));
    };
  }
  std::string bad;
  const std::optional<Guide> g = guideOf(*m.slot(b.slot), &bad);
  if (!g) {
    why = Status::badModel("the slot " + m.slotLabel(b.slot) + " has no curve: " + bad);
    return {};
  }
  const BodyId body = m.slot(b.slot)->body;
  return [p, g = *g, body](const Kinematics& at) {
    return offGuide(g, relativeMotion(at, at.motion(p), body));
  };
}

double periodicAngle(double deg, bool periodic) {
  if (periodic && deg >= 360 - 1e-9) deg = std::max(0.0, deg - 360);
  return deg;
}

}  // namespace

Clearance findClearance(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b,
                        const ClearanceOptions& opt) {
  Clearance out;
  if (!k.valid()) {
    out.status = Status::badModel("no mechanism is loaded");
    return out;
  }
  CycleTrack t;
  if (t.quantity = signedDistance(k, a, b, out.status); !out.status.ok()) return out;
  t.extremes = true;
  t.levels = {0};
  t.noise = 1e-12 * k.size() * M_PI / 180;
  const CycleSweep sweep = sweepCycle(k, {&t}, opt.steps);
  if (out.status = sweep.status; !out.status.ok()) return out;
  out.periodic = t.periodic;
  // A local minimum of |h|: a minimum of h above zero, a maximum below, or h crossing zero.
  for (const Root& r : t.stationary)
    if (r.rising == (r.value > 0) && r.value != 0)
      out.minima.push_back({periodicAngle(r.crankDeg, t.periodic), std::abs(r.value)});
  for (const Root& r : t.crossings.front())
    out.minima.push_back({periodicAngle(r.crankDeg, t.periodic), 0.0});
  std::sort(
      out.minima.begin(), out.minima.end(),
      [](const ClearanceEvent& x, const ClearanceEvent& y) { return x.crankDeg < y.crankDeg; });
  out.closest = {0, std::abs(t.samples.front().value)};
  std::vector<ClearanceEvent> candidates = out.minima;
  if (!t.periodic) candidates.push_back({360, std::abs(t.samples.back().value)});
  for (const ClearanceEvent& e : candidates)
    if (e.distance < out.closest.distance) out.closest = e;
  return out;
}

}  // namespace linkage
