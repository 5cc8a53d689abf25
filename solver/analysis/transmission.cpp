// Transmission angles: see linkage/transmission.h.
#include "linkage/transmission.h"

#include <algorithm>
#include <cmath>

#include "analysis/sensitivity_space.h"
#include "analysis/transmission_track.h"
#include "linkage/elements.h"
#include "linkage/groups.h"
#include "linkage/guide.h"
#include "linkage/space.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

bool isRod(const TransmissionJoint& t) {
  return t.kind != TransmissionKind::Dyad;
}

// The point of `joint` that lies on `body`.
PointId pointOn(const Mechanism& m, JointId joint, BodyId body) {
  const Joint* j = m.joint(joint);
  if (!j) return {};
  const Point* a = m.point(j->a);
  if (a && a->body == body) return j->a;
  const Point* b = m.point(j->b);
  return b && b->body == body ? j->b : PointId{};
}

// theta (degrees, see transmission_track.h), its derivatives per degree of crank, and for a
// rod sin(2 theta) and cos(2 theta), from the lines' directions (no sine evaluated). `slot` is
// the slot's direction as drawn, on its body.
struct Signed {
  double deg = 0, perDeg = 0, perDeg2 = 0, sin2 = 0, cos2 = 0;
};

// A line from anchor `from` to anchor `to`: its rate of turning per radian of crank and the
// rate's derivative, from its ends' exact velocities and accelerations (per second, divided by
// the driver's speed): d/dt atan2(u) = u x u' / |u|^2.
struct LineTurn {
  Vec2 u = Vec2::Zero();
  double rate = 0, accel = 0;
};

LineTurn lineTurn(const Kinematics& k, const Anchor& from, const Anchor& to) {
  const Kinematics::PointMotion a = from.motion(k), b = to.motion(k);
  const double w = k.omega();
  const Vec2 u = b.position - a.position, du = (b.velocity - a.velocity) / w,
             ddu = (b.acceleration - a.acceleration) / (w * w);
  const double n2 = u.squaredNorm(), c = cross(u, du);
  return {u, c / n2, (cross(u, ddu) * n2 - 2 * c * u.dot(du)) / (n2 * n2)};
}

Signed signedAngle(const Kinematics& k, const TransmissionJoint& t, const Vec2& slot) {
  Signed out;
  double rate = 0, accel = 0;  // of theta, per radian of crank
  if (t.kind == TransmissionKind::Dyad) {
    // From the link's line (joint -> its outer pin) to the other's.
    const LineTurn u = lineTurn(k, t.linkAt, t.linkOuter), v = lineTurn(k, t.otherAt, t.otherOuter);
    out.deg = std::atan2(cross(u.u, v.u), u.u.dot(v.u)) / kDeg;
    rate = v.rate - u.rate;
    accel = v.accel - u.accel;
  } else {
    // From the slot's line (fixed in `other`) to the rod.
    const LineTurn u = lineTurn(k, t.linkOuter, t.linkAt);
    const Vec2 d = k.bodyTransform(t.other).R * slot;
    const double c = d.dot(u.u), s = cross(d, u.u), n = c * c + s * s;
    double theta = std::atan2(s, c);
    if (theta > M_PI / 2) theta -= M_PI;
    if (theta <= -M_PI / 2) theta += M_PI;
    out.deg = theta / kDeg;
    out.sin2 = 2 * s * c / n;
    out.cos2 = (c * c - s * s) / n;
    rate = u.rate - k.bodyOmega(t.other) / k.omega();
    accel = u.accel - k.bodyAlpha(t.other) / (k.omega() * k.omega());
  }
  out.perDeg = rate;
  out.perDeg2 = accel * kDeg;
  return out;
}

// The channel of the rod lying along its slot: sin(2 theta), smooth through the fold.
RootSample along(const Signed& s) {
  return {s.sin2, 2 * s.cos2 * s.perDeg * kDeg};
}

double muOf(const TransmissionJoint& t, double theta) {
  return isRod(t) ? 90 - std::abs(theta) : std::abs(theta);
}

}  // namespace

int transmissionClass(const Mechanism& m, const TransmissionJoint& t) {
  if (!isSpatial(m)) return 0;
  const Body* link = m.body(t.link);
  return link ? planeClasses(m).of(link->plane).cls : 0;
}

Vec2 slotLine(const Mechanism& m, const TransmissionJoint& t) {
  const Slot* s = t.kind == TransmissionKind::Dyad ? nullptr : m.slot(t.slot);
  if (!s) return Vec2::Zero();
  // In space the drawn x, y of a ground slot are the world's, and a body's are its plane's:
  // neither is the class frame the rod's line is read in.
  if (!isSpatial(m)) return s->p1 - s->p0;
  const Slot c = inClassFrame(m, planeClasses(m), *s, transmissionClass(m, t));
  return c.p1 - c.p0;
}

const char* toString(TransmissionKind k) {
  switch (k) {
    case TransmissionKind::Dyad:
      return "dyad";
    case TransmissionKind::RodSlider:
      return "rod-slider";
    case TransmissionKind::RodInSlot:
      return "rod-in-slot";
  }
  return "?";
}

namespace {

// Whether a slot joint (a slider or a pin in a slot) runs on an arc.
bool onArc(const Mechanism& m, JointId joint) {
  const Joint* j = m.joint(joint);
  if (!j || !kindOf(*j).reads(FieldType::Slot)) return false;
  const Slot* s = m.slot(j->slot);
  return s && s->arc() && soundSlot(*s);
}

// Where an anchor is as drawn, and on which body (NaN where it names nothing); an arc's in the
// frame its rows are written in (in space its class's, where Kinematics places its bodies).
std::pair<BodyId, Vec2> anchored(const Mechanism& m, const Anchor& a) {
  const Point* p = m.point(a.point);
  const Slot* s = m.slot(a.arc);
  if (!s || !s->arc()) return {p ? p->body : BodyId{}, p ? p->pos : Vec2(NAN, NAN)};
  Slot seen = *s;
  Vec2 at = p ? p->pos : Vec2::Zero();
  if (isSpatial(m)) {
    const PlaneClasses pc = planeClasses(m);
    const Body* b = m.body(s->body);
    const int cls =
        b && !b->ground ? pc.of(b->plane).cls : std::max(0, internal::groundSlotClass(m, pc, *s));
    seen = inClassFrame(m, pc, *s, cls);
    if (p) at = inClassFrame(m, pc, *p, cls);
  }
  const std::optional<Guide> g = guideOf(seen);
  if (!g) return {p ? p->body : BodyId{}, Vec2(NAN, NAN)};
  if (!p) return {s->body, g->centre};
  const Vec2 d = at - g->centre;
  return {p->body, Vec2(at - g->radius * d.normalized())};
}

Vec2 sketchOf(const Mechanism& m, const Anchor& a) {
  return anchored(m, a).second;
}

// The joint's angle as the group's kind gives it; false when the group has none.
bool fromGroup(const Mechanism& m, const AssurGroup& g, TransmissionJoint& t) {
  using K = AssurGroup::Kind;
  if (g.kind != K::RRR && g.kind != K::RRP && g.kind != K::RP) return false;
  t.link = g.bodies[0];
  t.linkOuter = {pointOn(m, g.joints[0], t.link), {}};
  t.joint = g.joints[1];
  t.linkAt = {pointOn(m, t.joint, t.link), {}};
  if (g.kind == K::RRR) {
    t.kind = TransmissionKind::Dyad;
    t.other = g.bodies[1];
    t.otherAt = {pointOn(m, t.joint, t.other), {}};
    if (onArc(m, g.joints[2])) {
      // A block in a curved guide: its line to the arc's centre, as the slider compiles it.
      t.slot = m.joint(g.joints[2])->slot;
      t.otherOuter = {m.joint(g.joints[2])->a, t.slot};
    } else {
      t.otherOuter = {pointOn(m, g.joints[2], t.other), {}};
    }
    return true;
  }
  const Joint* slide = m.joint(g.kind == K::RRP ? g.joints[2] : g.joints[1]);
  t.slot = slide->slot;
  t.other = m.slot(t.slot)->body;
  if (g.kind == K::RP && onArc(m, slide->id)) {
    // A pin in an arc slot: the radius from the pin to the centre, as the four-bar's rocker.
    t.kind = TransmissionKind::Dyad;
    t.otherAt = t.linkAt;
    t.otherOuter = {{}, t.slot};
    return true;
  }
  t.kind = g.kind == K::RRP ? TransmissionKind::RodSlider : TransmissionKind::RodInSlot;
  return true;
}

}  // namespace

Kinematics::PointMotion Anchor::motion(const Kinematics& k) const {
  if (!arc) return k.motion(point);
  const auto [body, sketch] = anchored(k.mechanism(), *this);
  return k.motionOf(body, sketch);
}

std::vector<TransmissionJoint> transmissionJoints(const Mechanism& m) {
  std::vector<TransmissionJoint> out;
  for (const AssurGroup& g : decomposeAssur(m).groups) {
    TransmissionJoint t;
    if (!fromGroup(m, g, t)) continue;
    // A line whose two ends are drawn at one place has no direction.
    if (sketchOf(m, t.linkOuter) == sketchOf(m, t.linkAt)) continue;
    if (t.kind == TransmissionKind::Dyad && sketchOf(m, t.otherOuter) == sketchOf(m, t.otherAt))
      continue;
    t.label = "mu:" + m.pointLabel(m.joint(t.joint)->a);
    out.push_back(t);
  }
  return out;
}

TransmissionReading transmissionAngle(const Kinematics& k, const TransmissionJoint& t) {
  if (!k.valid()) return {NAN, NAN, NAN};
  const Signed s = signedAngle(k, t, slotLine(k.mechanism(), t));
  // mu = |theta| or 90 - |theta|: its rates are theta's, turned by the side theta is on.
  const double side = (s.deg < 0 ? -1 : 1) * (isRod(t) ? -1 : 1);
  return {muOf(t, s.deg), side * s.perDeg, side * s.perDeg2};
}

TransmissionTrack::TransmissionTrack(const Mechanism& m, const TransmissionJoint& t) : t_(t) {
  const Vec2 slot = slotLine(m, t);
  stationary_.f = [t, slot](const Kinematics& k) {
    const Signed r = signedAngle(k, t, slot);
    return RootSample{r.perDeg, r.perDeg2};
  };
  stationary_.value = [t, slot](const Kinematics& k) { return signedAngle(k, t, slot).deg; };
  along_.f = [t, slot](const Kinematics& k) { return along(signedAngle(k, t, slot)); };
  along_.value = stationary_.value;
  slot_ = slot;
}

void TransmissionTrack::sample(const Kinematics& k) {
  const Signed r = signedAngle(k, t_, slot_);
  mu.push_back(muOf(t_, r.deg));
  stationary_.samples.push_back({r.perDeg, r.perDeg2});
  if (isRod(t_)) along_.samples.push_back(along(r));
}

void TransmissionTrack::closePeriod() {
  stationary_.samples.back() = stationary_.samples.front();
  if (isRod(t_)) along_.samples.back() = along_.samples.front();
}

std::vector<RootChannel*> TransmissionTrack::channels() {
  if (isRod(t_)) return {&stationary_, &along_};
  return {&stationary_};
}

TransmissionSummary TransmissionTrack::summary(bool periodic) const {
  TransmissionSummary s;
  s.min = s.max = mu.front();
  auto add = [&](double crank, double theta, bool max) {
    if (periodic && crank >= 360) crank -= 360;
    const double v = muOf(t_, theta);
    s.extremes.push_back({max, crank, v});
    if (v < s.min) s.min = v, s.minDeg = crank;
    if (v > s.max) s.max = v, s.maxDeg = crank;
  };
  for (const Root& r : stationary_.roots) {
    // theta at a minimum (rising rate) is a minimum of |theta| when theta > 0.
    const bool thetaMax = !r.rising;
    const bool absMax = r.value >= 0 ? thetaMax : !thetaMax;
    add(r.crankDeg, r.value, isRod(t_) ? !absMax : absMax);
  }
  for (const Root& r : along_.roots)
    if (std::abs(r.value) < 45) add(r.crankDeg, r.value, true);  // along the slot: mu = 90
  if (!periodic) {
    if (mu.back() < s.min) s.min = mu.back(), s.minDeg = 360;
    if (mu.back() > s.max) s.max = mu.back(), s.maxDeg = 360;
  }
  std::sort(s.extremes.begin(), s.extremes.end(),
            [](const auto& a, const auto& b) { return a.crankDeg < b.crankDeg; });
  return s;
}

}  // namespace linkage
