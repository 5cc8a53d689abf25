// Clearance: see linkage/clearance.h.
#include "linkage/clearance.h"
#include "linkage/space.h"

#include <algorithm>
#include <optional>

#include "analysis/slot_frame.h"
#include "analysis/space_distance.h"
#include "linkage/guide.h"
#include "linkage/timing_text.h"

namespace linkage {

namespace {

// What the minima are found on. `distance`, with its derivatives: between two points, or from
// the slot as drawn (its line or arc between its ends, else its nearer end); where the two meet
// it has no derivative (d1 jumps from negative to positive: a minimum all the same, found by
// bisection). `side`, for a slot: the signed distance from its line or circle, whose zeros
// (smooth ones, found by Newton) are where the point crosses it: a touch is taken from there,
// exactly 0.
struct Quantities {
  CycleQuantity distance, side, along;
  double length = 0;  // the segment's or slot's
};

double periodicAngle(double deg, bool periodic) {
  if (periodic && deg >= 360 - 1e-9) deg = std::max(0.0, deg - 360);
  return deg;
}

// The point first (a), the other part second (b); false when neither is a point.
bool pointFirst(const ClearancePart& a0, const ClearancePart& b0, ClearancePart& a,
                ClearancePart& b) {
  a = a0.isPoint() ? a0 : b0;
  b = a0.isPoint() ? b0 : a0;
  return a.isPoint();
}

Status check(const Kinematics& k, const ClearancePart& a, const ClearancePart& b) {
  const Mechanism& m = k.mechanism();
  if (!a.isPoint())
    return Status::badModel(
        "the clearance between two segments or slots is not measured: give "
        "a point on one side");
  if (!k.contains(a.point) || (b.point && !k.contains(b.point)) || (b.end && !k.contains(b.end)) ||
      (b.slot && !k.contains(b.slot)))
    return Status::badModel("the point, segment or slot is not in the mechanism");
  if (std::string why = clearancePartProblem(m, a.point, b); !why.empty())
    return Status::badModel(why);
  if (b.isPoint()) return k.checkDetermined({a.point, b.point});
  return k.checkDetermined({a.point});
}

// The curve a segment or a slot is measured to, in its body's sketch frame.
std::optional<Guide> curveOf(const Mechanism& m, const ClearancePart& b, BodyId& body,
                             std::string* why) {
  if (b.isSlot()) {
    body = m.slot(b.slot)->body;
    return guideOf(*m.slot(b.slot), why);
  }
  Slot line;
  body = line.body = m.point(b.point)->body;
  line.p0 = m.point(b.point)->pos;
  line.p1 = m.point(b.end)->pos;
  return guideOf(line, why);
}

// In space the distance in the world alone: the point and the part need not share a plane, so
// a part's line is nothing the point crosses. A slot is its curve between its ends in its body's
// plane (the ground's where its points are written).
Quantities spaceQuantities(const Mechanism& m, const ClearancePart& a, const ClearancePart& b) {
  const PointId p = a.point;
  if (b.isSlot()) {
    const Slot& slot = *m.slot(b.slot);
    if (slot.arc())
      return {[p, slot](const Kinematics& at) { return spaceDistanceToArc(at, p, slot); }, {}, {}};
    return {[p, slot](const Kinematics& at) { return spaceDistanceToSlot(at, p, slot); }, {}, {}};
  }
  if (b.isPoint())
    return {[p, q = b.point](const Kinematics& at) { return spaceDistance(at, p, q); }, {}, {}};
  return {[p, s = b.point, e = b.end](const Kinematics& at) {
            return spaceDistanceToSegment(at, p, s, e);
          },
          {},
          {}};
}

// With the point first (a), the other part second (b).
Quantities quantitiesOf(const Kinematics& k, const ClearancePart& a, const ClearancePart& b,
                        Status& why) {
  if (why = check(k, a, b); !why.ok()) return {};
  const Mechanism& m = k.mechanism();
  if (isSpatial(m)) return spaceQuantities(m, a, b);
  const PointId p = a.point;
  if (b.isPoint()) {
    const PointId q = b.point;
    return {[p, q](const Kinematics& at) {
              const double rate = secondsPerDegree(at);
              const Kinematics::PointMotion u = at.motion(p), v = at.motion(q);
              return lengthOf(u.position - v.position, (u.velocity - v.velocity) * rate,
                              (u.acceleration - v.acceleration) * (rate * rate));
            },
            {},
            {}};
  }
  std::string bad;
  BodyId body;
  const std::optional<Guide> g = curveOf(m, b, body, &bad);
  if (!g) {
    why = Status::badModel(m.partDescription(b) + " has no curve: " + bad);
    return {};
  }
  return {[p, g = *g, body](const Kinematics& at) {
            return offDrawnSlot(g, relativeMotion(at, at.motion(p), body));
          },
          [p, g = *g, body](const Kinematics& at) {
            return offGuide(g, relativeMotion(at, at.motion(p), body));
          },
          [p, g = *g, body](const Kinematics& at) {
            return alongGuide(g, relativeMotion(at, at.motion(p), body));
          },
          g->length()};
}

// In space: in the world, and in each part's plane class frame (what the canvas draws).
void placeClosestInSpace(const Kinematics& at, const ClearancePart& a, const ClearancePart& b,
                         Clearance& out) {
  out.closestPoint3 = at.motionInSpace(a.point).position;
  out.closestPoint = at.position(a.point);
  if (b.isPoint()) {
    out.closestOther3 = at.motionInSpace(b.point).position;
    out.closestOther = at.position(b.point);
    return;
  }
  if (b.isSlot()) {  // as the slot's body carries it, in its class's frame
    const Slot& slot = *at.mechanism().slot(b.slot);
    if (slot.arc())
      spaceDistanceToArc(at, a.point, slot, &out.closestOther3);
    else
      spaceDistanceToSlot(at, a.point, slot, &out.closestOther3);
    out.closestOther = intoSlotClass(at.mechanism(), slot, out.closestOther3);
    out.closestPart = slotCurveInClass(at, slot, 48);
    return;
  }
  spaceDistanceToSegment(at, a.point, b.point, b.end, &out.closestOther3);
  const Vec3 A = at.motionInSpace(b.point).position, u = at.motionInSpace(b.end).position - A;
  const Vec2 p0 = at.position(b.point), p1 = at.position(b.end);
  const double t = std::clamp((out.closestOther3 - A).dot(u) / u.squaredNorm(), 0.0, 1.0);
  out.closestOther = p0 + t * (p1 - p0);
  out.closestPart = {p0, p1};
}

// Where the two things are at the crank angle `deg` (from 0, as the sweep went).
void placeClosest(const Kinematics& k, const ClearancePart& a, const ClearancePart& b, double deg,
                  Clearance& out) {
  Kinematics at = k;
  if (!at.moveTo(0).ok() || !at.moveTo(deg).ok()) return;  // the sweep went there already
  if (isSpatial(k.mechanism())) return placeClosestInSpace(at, a, b, out);
  out.closestPoint = at.position(a.point);
  if (b.isPoint()) {
    out.closestOther = at.position(b.point);
    return;
  }
  BodyId body;
  const Guide g = *curveOf(k.mechanism(), b, body, nullptr);  // quantitiesOf has checked it
  out.closestOther = at.toWorld(body, g.nearest(at.toSketch(body, out.closestPoint)));
  const int pieces = g.arc ? 48 : 1;
  for (int i = 0; i <= pieces; ++i)
    out.closestPart.push_back(at.toWorld(body, i == 0        ? g.p0
                                               : i == pieces ? g.p1
                                                             : g.at(g.length() * i / pieces)));
}

// Where along the segment or slot the point crosses its line or circle, at each crossing.
std::vector<ClearanceCrossing> crossingsOf(const Kinematics& k, const ClearancePart& a,
                                           const ClearancePart& b, const CycleTrack& side) {
  std::vector<ClearanceCrossing> out;
  BodyId body;
  const Guide g = *curveOf(k.mechanism(), b, body, nullptr);  // quantitiesOf has checked it
  Kinematics at = k;
  for (const Root& x : side.crossings.front()) {
    if (!at.moveTo(0).ok() || !at.moveTo(x.crankDeg).ok()) break;
    const double along = g.along(at.toSketch(body, at.position(a.point)));
    const double tol = 1e-9 * std::max(1.0, g.length());
    out.push_back({periodicAngle(x.crankDeg, side.periodic), along,
                   along >= -tol && along <= g.length() + tol});
  }
  std::sort(out.begin(), out.end(), [](const ClearanceCrossing& x, const ClearanceCrossing& y) {
    return x.crankDeg < y.crankDeg;
  });
  return out;
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

// Where a point that runs along the part's line is on the part (0 <= along <= length): the
// crank intervals between the crossings of `along` with 0 and the length, in [0, 360) (one that
// runs on past 360 ends above it).
std::vector<AngleInterval> onPartOf(const CycleTrack& along, double length) {
  const double tol = 1e-9 * std::max(1.0, length);
  const double s0 = along.samples.front().value;
  // Each crossing with whether the point is on the part after it: rising through 0 or falling
  // through the length, it comes onto the part.
  std::vector<std::pair<double, bool>> events;
  for (size_t level = 0; level < along.crossings.size(); ++level)
    for (const Root& r : along.crossings[level])
      events.push_back({r.crankDeg, level == 0 ? r.rising : !r.rising});
  std::sort(events.begin(), events.end());
  std::vector<AngleInterval> out;
  bool inside = s0 >= -tol && s0 <= length + tol;
  double from = 0;
  for (const auto& [deg, onAfter] : events) {
    if (inside && !onAfter) out.push_back({from, deg});
    if (!inside && onAfter) from = deg;
    inside = onAfter;
  }
  if (inside) {
    // On at the end of the turn: where it repeats, the first interval continues it.
    if (along.periodic && !out.empty() && out.front().fromDeg == 0)
      out.front() = {from, out.front().toDeg + 360};
    else
      out.push_back({from, 360});
  }
  return out;
}

// A point on the line throughout: its distance is 0 on the part and the minima found there
// are rounding; each interval's start stands for them.
void runAlong(const CycleTrack& along, double length, Clearance& out) {
  out.runsAlong = true;
  out.onPart = onPartOf(along, length);
  auto within = [&](double deg) {
    for (const AngleInterval& i : out.onPart)
      if ((deg >= i.fromDeg && deg <= i.toDeg) || (deg + 360 >= i.fromDeg && deg + 360 <= i.toDeg))
        return true;
    return false;
  };
  std::vector<ClearanceEvent> kept;
  for (const ClearanceEvent& e : out.minima)
    if (!within(e.crankDeg) || e.distance > 1e-9 * std::max(1.0, length)) kept.push_back(e);
  for (const AngleInterval& i : out.onPart) kept.push_back({periodicAngle(i.fromDeg, true), 0});
  std::sort(kept.begin(), kept.end(), [](const ClearanceEvent& x, const ClearanceEvent& y) {
    return x.crankDeg < y.crankDeg;
  });
  out.minima = kept;
}

}  // namespace

double clearanceAt(const Kinematics& k, const ClearancePart& a0, const ClearancePart& b0) {
  ClearancePart a, b;
  if (!pointFirst(a0, b0, a, b) || !k.valid() || !check(k, a, b).ok()) return NAN;
  if (isSpatial(k.mechanism())) {
    if (b.isSlot()) return NAN;
    return b.isPoint() ? spaceDistance(k, a.point, b.point).value
                       : spaceDistanceToSegment(k, a.point, b.point, b.end).value;
  }
  const Vec2 p = k.position(a.point);
  if (b.isPoint()) return (p - k.position(b.point)).norm();
  BodyId body;
  const std::optional<Guide> g = curveOf(k.mechanism(), b, body, nullptr);
  return g ? g->distance(k.toSketch(body, p)) : NAN;
}

namespace {

// The closest approach: where the motion repeats, the least of the minima (the turn's start is
// one of them, or beside one: taking it would name an angle no minimum has); otherwise the ends
// of the turn count too.
ClearanceEvent closestOf(const Clearance& c, const CycleTrack& d) {
  std::vector<ClearanceEvent> candidates = c.minima;
  if (!d.periodic || candidates.empty()) {
    candidates.push_back({0, d.samples.front().value});
    if (!d.periodic) candidates.push_back({360, d.samples.back().value});
  }
  ClearanceEvent best = candidates.front();
  for (const ClearanceEvent& e : candidates)
    if (e.distance < best.distance) best = e;
  return best;
}

}  // namespace

Clearance findClearance(const Kinematics& k, const ClearancePart& a0, const ClearancePart& b0,
                        const ClearanceOptions& opt) {
  Clearance out;
  if (!k.valid()) {
    out.status = Status::badModel("no mechanism is loaded");
    return out;
  }
  ClearancePart a, b;
  pointFirst(a0, b0, a, b);
  const Quantities q = quantitiesOf(k, a, b, out.status);
  if (!out.status.ok()) return out;
  CycleTrack d, side, along;
  d.quantity = q.distance;
  d.extremes = true;
  d.noise = 1e-12 * k.size() * M_PI / 180;
  std::vector<CycleTrack*> tracks{&d};
  if (q.side) {
    side.quantity = q.side;
    side.levels = {0};
    side.noise = d.noise;
    along.quantity = q.along;
    along.levels = {0, q.length};
    along.noise = d.noise;
    tracks.push_back(&side);
    tracks.push_back(&along);
  }
  const CycleSweep sweep = sweepCycle(k, tracks, opt.steps);
  if (out.status = sweep.status; !out.status.ok()) return out;
  out.periodic = d.periodic;
  out.minima = minimaOf(d, q.side ? &side : nullptr, k.size());
  if (q.side && !side.moves() && std::abs(side.samples.front().value) <= 1e-9 * k.size())
    runAlong(along, q.length, out);
  out.closest = closestOf(out, d);
  out.crankDeg = sweep.crank;
  for (const CycleReading& r : d.samples) out.distance.push_back(r.value);
  placeClosest(k, a, b, out.closest.crankDeg, out);
  if (q.side) {
    out.crossings = crossingsOf(k, a, b, side);
    out.partLengthMm = q.length;
  }
  return out;
}

}  // namespace linkage
