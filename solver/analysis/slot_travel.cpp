// Slot travel: see linkage/slot_travel.h.
#include "linkage/slot_travel.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "analysis/slot_frame.h"
#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage {

bool SlotTravels::allInside() const {
  return std::all_of(joints.begin(), joints.end(), [](const SlotTravel& t) { return t.inside; });
}

namespace {

struct Candidate {
  const Joint* joint;
  Guide guide;
  BodyId slotBody;
};

// In space each slot is measured in the frame its block moves in (the solver's positions are
// in it): a ground slot written in the world is projected there, not read in the drawing plane.
std::vector<Candidate> slotJoints(const Mechanism& m) {
  std::vector<Candidate> out;
  const bool spatial = isSpatial(m);
  const PlaneClasses classes = spatial ? planeClasses(m) : PlaneClasses{};
  for (const Joint& j : m.joints) {
    const Role role = kindOf(j).role;
    if (role != Role::Prismatic && role != Role::PointOnCurve) continue;
    const Slot* s = m.slot(j.slot);
    const Point* a = m.point(j.a);
    if (!s || !a) continue;
    const Slot inFrame =
        spatial ? inClassFrame(m, classes, *s, jointClass(m, classes, *a, *s)) : *s;
    if (std::optional<Guide> g = guideOf(inFrame)) out.push_back({&j, *g, s->body});
  }
  return out;
}

SlotTravel travelOf(const Candidate& c, const CycleTrack& t, const CycleSweep& sweep, double tol) {
  SlotTravel r;
  r.joint = c.joint->id;
  r.slot = c.joint->slot;
  r.slotTo = c.guide.length();
  r.min = r.max = t.samples.front().value;
  auto consider = [&](double deg, double v) {
    if (v < r.min) std::tie(r.min, r.minDeg) = std::pair(v, deg);
    if (v > r.max) std::tie(r.max, r.maxDeg) = std::pair(v, deg);
  };
  // The ends count when the motion does not repeat (and cannot do harm when it does).
  consider(sweep.crank.back(), t.samples.back().value);
  for (const Root& x : t.stationary) consider(x.crankDeg, x.value);
  if (t.periodic) {
    if (r.minDeg >= 360) r.minDeg -= 360;
    if (r.maxDeg >= 360) r.maxDeg -= 360;
  }
  r.before = std::max(0.0, r.slotFrom - r.min);
  r.past = std::max(0.0, r.max - r.slotTo);
  r.inside = r.before <= tol && r.past <= tol;
  return r;
}

// An arc's position (Guide::along) jumps by the circle's length where the point passes the
// place opposite the arc's middle, far outside the slot: a point that runs round there would
// read a travel that jumps. Kept continuous instead, each reading the one nearest the reading
// before it: the sweep samples the turn in order, and its root search goes forward from crank 0
// in steps far smaller than a turn of the circle.
void unwrapAround(CycleTrack& t, double turn) {
  auto last = std::make_shared<std::optional<double>>();
  t.quantity = [q = t.quantity, last, turn](const Kinematics& at) {
    CycleReading r = q(at);
    if (*last) r.value += turn * std::round((**last - r.value) / turn);
    *last = r.value;
    return r;
  };
  t.onSampled = [last](CycleTrack& sampled) { *last = sampled.samples.front().value; };
}

}  // namespace

SlotTravels slotTravel(const Kinematics& k, const SlotTravelOptions& opt) {
  SlotTravels out;
  if (!k.valid()) {
    out.status = Status::badModel("no mechanism is loaded");
    return out;
  }
  const std::vector<Candidate> cands = slotJoints(k.mechanism());
  if (cands.empty()) return out;
  std::vector<CycleTrack> tracks(cands.size());
  std::vector<CycleTrack*> ptrs;
  for (size_t i = 0; i < cands.size(); ++i) {
    const Candidate c = cands[i];
    const PointId a = c.joint->a;
    tracks[i].quantity = [c, a](const Kinematics& at) {
      return alongGuide(c.guide, relativeMotion(at, at.motion(a), c.slotBody));
    };
    if (c.guide.arc) unwrapAround(tracks[i], 2 * M_PI * c.guide.radius);
    tracks[i].extremes = true;
    tracks[i].noise = 1e-12 * k.size() * M_PI / 180;  // as the limits' (limits.cpp)
    ptrs.push_back(&tracks[i]);
  }
  const CycleSweep sweep = sweepCycle(k, ptrs, opt.steps);
  if (out.status = sweep.status; !out.status.ok()) return out;
  for (size_t i = 0; i < cands.size(); ++i)
    out.joints.push_back(travelOf(cands[i], tracks[i], sweep, 1e-9 * k.size()));
  return out;
}

}  // namespace linkage
