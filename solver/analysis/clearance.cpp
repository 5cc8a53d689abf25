// Clearance: see linkage/clearance.h.
#include "linkage/clearance.h"

#include <algorithm>
#include <optional>

#include "analysis/slot_frame.h"
#include "linkage/guide.h"

namespace linkage {

namespace {

// What the minima are found on. `distance`, with its derivatives: between two points, or from
// the slot as drawn (its line or arc between its ends, else its nearer end); where the two meet
// it has no derivative (d1 jumps from negative to positive: a minimum all the same, found by
// bisection). `side`, for a slot: the signed distance from its line or circle, whose zeros
// (smooth ones, found by Newton) are where the point crosses it: a touch is taken from there,
// exactly 0.
struct Quantities {
  CycleQuantity distance, side;
};

Status check(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b) {
  const Mechanism& m = k.mechanism();
  if (a.slot && b.slot)
    return Status::badModel("the clearance between two slots is not measured: give a point");
  if (b.point == a.point)
    return Status::badModel("the clearance of a point to itself is not measured: give two");
  if (!k.contains(a.point) || (b.point && !k.contains(b.point)) || (b.slot && !k.contains(b.slot)))
    return Status::badModel("the point or slot is not in the mechanism");
  if (b.point) return k.checkDetermined({a.point, b.point});
  if (m.point(a.point)->body == m.slot(b.slot)->body)
    return Status::badModel("the point " + m.pointLabel(a.point) + " is on the body of the slot " +
                            m.slotLabel(b.slot) + ": their distance does not change");
  return k.checkDetermined({a.point});
}

// With the point first (a), the other point or the slot second (b).
Quantities quantitiesOf(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b,
                        Status& why) {
  if (why = check(k, a, b); !why.ok()) return {};
  const Mechanism& m = k.mechanism();
  const PointId p = a.point;
  if (b.point) {
    const PointId q = b.point;
    return {[p, q](const Kinematics& at) {
              const double rate = secondsPerDegree(at);
              const Kinematics::PointMotion u = at.motion(p), v = at.motion(q);
              return lengthOf(u.position - v.position, (u.velocity - v.velocity) * rate,
                              (u.acceleration - v.acceleration) * (rate * rate));
            },
            {}};
  }
  std::string bad;
  const std::optional<Guide> g = guideOf(*m.slot(b.slot), &bad);
  if (!g) {
    why = Status::badModel("the slot " + m.slotLabel(b.slot) + " has no curve: " + bad);
    return {};
  }
  const BodyId body = m.slot(b.slot)->body;
  return {[p, g = *g, body](const Kinematics& at) {
            return offDrawnSlot(g, relativeMotion(at, at.motion(p), body));
          },
          [p, g = *g, body](const Kinematics& at) {
            return offGuide(g, relativeMotion(at, at.motion(p), body));
          }};
}

// Where the two things are at the crank angle `deg` (from 0, as the sweep went).
void placeClosest(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b, double deg,
                  Clearance& out) {
  Kinematics at = k;
  if (!at.moveTo(0).ok() || !at.moveTo(deg).ok()) return;  // the sweep went there already
  out.closestPoint = at.position(a.point);
  if (b.point) {
    out.closestOther = at.position(b.point);
    return;
  }
  const Slot& s = *k.mechanism().slot(b.slot);
  const Guide g = *guideOf(s);  // quantitiesOf has checked it
  out.closestOther = at.toWorld(s.body, g.nearest(at.toSketch(s.body, out.closestPoint)));
}

double periodicAngle(double deg, bool periodic) {
  if (periodic && deg >= 360 - 1e-9) deg = std::max(0.0, deg - 360);
  return deg;
}

// The minima of the distance: its derivative rising through zero. One where the point touches
// the slot (a distance of rounding size next to a crossing of its line or circle) is that
// crossing, at distance 0.
std::vector<ClearanceEvent> minimaOf(const CycleTrack& d, const CycleTrack* side, double size) {
  std::vector<ClearanceEvent> out;
  for (const Root& r : d.stationary) {
    if (!r.rising) continue;
    ClearanceEvent e{r.crankDeg, r.value};
    if (side && e.distance <= 1e-6 * size)
      for (const Root& x : side->crossings.front())
        if (std::abs(x.crankDeg - e.crankDeg) <= 1e-6) e = {x.crankDeg, 0.0};
    out.push_back({periodicAngle(e.crankDeg, d.periodic), e.distance});
  }
  std::sort(out.begin(), out.end(), [](const ClearanceEvent& x, const ClearanceEvent& y) {
    return x.crankDeg < y.crankDeg;
  });
  return out;
}

}  // namespace

double clearanceAt(const Kinematics& k, const ClearanceItem& a0, const ClearanceItem& b0) {
  const bool swap = a0.slot && !b0.slot;
  const ClearanceItem &a = swap ? b0 : a0, &b = swap ? a0 : b0;
  if (!k.valid() || !check(k, a, b).ok()) return NAN;
  const Vec2 p = k.position(a.point);
  if (b.point) return (p - k.position(b.point)).norm();
  const Slot& s = *k.mechanism().slot(b.slot);
  const std::optional<Guide> g = guideOf(s);
  return g ? g->distance(k.toSketch(s.body, p)) : NAN;
}

Clearance findClearance(const Kinematics& k, const ClearanceItem& a0, const ClearanceItem& b0,
                        const ClearanceOptions& opt) {
  Clearance out;
  if (!k.valid()) {
    out.status = Status::badModel("no mechanism is loaded");
    return out;
  }
  const bool swap = a0.slot && !b0.slot;  // the point first
  const ClearanceItem &a = swap ? b0 : a0, &b = swap ? a0 : b0;
  const Quantities q = quantitiesOf(k, a, b, out.status);
  if (!out.status.ok()) return out;
  CycleTrack d, side;
  d.quantity = q.distance;
  d.extremes = true;
  d.noise = 1e-12 * k.size() * M_PI / 180;
  std::vector<CycleTrack*> tracks{&d};
  if (q.side) {
    side.quantity = q.side;
    side.levels = {0};
    side.noise = d.noise;
    tracks.push_back(&side);
  }
  const CycleSweep sweep = sweepCycle(k, tracks, opt.steps);
  if (out.status = sweep.status; !out.status.ok()) return out;
  out.periodic = d.periodic;
  out.minima = minimaOf(d, q.side ? &side : nullptr, k.size());
  out.closest = {0, d.samples.front().value};
  std::vector<ClearanceEvent> candidates = out.minima;
  if (!d.periodic) candidates.push_back({360, d.samples.back().value});
  for (const ClearanceEvent& e : candidates)
    if (e.distance < out.closest.distance) out.closest = e;
  out.crankDeg = sweep.crank;
  for (const CycleReading& r : d.samples) out.distance.push_back(r.value);
  placeClosest(k, a, b, out.closest.crankDeg, out);
  return out;
}

}  // namespace linkage
