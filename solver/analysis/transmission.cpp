// Transmission angles: see linkage/transmission.h.
#include "linkage/transmission.h"

#include <algorithm>
#include <cmath>

#include "analysis/assur_groups.h"
#include "analysis/transmission_track.h"

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

Signed signedAngle(const Kinematics& k, const TransmissionJoint& t, const Vec2& slot) {
  const double w = k.omega();
  Signed out;
  if (t.kind == TransmissionKind::Dyad) {
    const Vec2 u = k.position(t.linkOuter) - k.position(t.linkAt);
    const Vec2 v = k.position(t.otherOuter) - k.position(t.otherAt);
    out.deg = std::atan2(cross(u, v), u.dot(v)) / kDeg;
  } else {
    const Vec2 d = k.bodyTransform(t.other).R * slot;
    const Vec2 u = k.position(t.linkAt) - k.position(t.linkOuter);
    const double c = d.dot(u), s = cross(d, u), n = c * c + s * s;
    double theta = std::atan2(s, c);
    if (theta > M_PI / 2) theta -= M_PI;
    if (theta <= -M_PI / 2) theta += M_PI;
    out.deg = theta / kDeg;
    out.sin2 = 2 * s * c / n;
    out.cos2 = (c * c - s * s) / n;
  }
  // A line fixed in a body turns with it: theta turns at the difference of the two bodies'
  // rates (the rod's minus the slot's, the second link's minus the first's).
  const double sign = isRod(t) ? 1 : -1;
  out.perDeg = sign * (k.bodyOmega(t.link) - k.bodyOmega(t.other)) / w;
  out.perDeg2 = sign * (k.bodyAlpha(t.link) - k.bodyAlpha(t.other)) / (w * w) * kDeg;
  return out;
}

// The slot's direction as drawn (zero for a dyad).
Vec2 slotDirection(const Mechanism& m, const TransmissionJoint& t) {
  const Slot* s = t.kind == TransmissionKind::Dyad ? nullptr : m.slot(t.slot);
  return s ? Vec2(s->p1 - s->p0) : Vec2::Zero();
}

// The channel of the rod lying along its slot: sin(2 theta), smooth through the fold.
RootSample along(const Signed& s) {
  return {s.sin2, 2 * s.cos2 * s.perDeg * kDeg};
}

double muOf(const TransmissionJoint& t, double theta) {
  return isRod(t) ? 90 - std::abs(theta) : std::abs(theta);
}

}  // namespace

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

std::vector<TransmissionJoint> transmissionJoints(const Mechanism& m) {
  std::vector<TransmissionJoint> out;
  for (const AssurGroup& g : decomposeAssur(m).groups) {
    using K = AssurGroup::Kind;
    if (g.kind != K::RRR && g.kind != K::RRP && g.kind != K::RP) continue;
    TransmissionJoint t;
    t.link = g.bodies[0];
    t.linkOuter = pointOn(m, g.joints[0], t.link);
    t.joint = g.joints[1];
    if (g.kind == K::RRR) {
      t.kind = TransmissionKind::Dyad;
      t.other = g.bodies[1];
      t.linkAt = pointOn(m, t.joint, t.link);
      t.otherAt = pointOn(m, t.joint, t.other);
      t.otherOuter = pointOn(m, g.joints[2], t.other);
    } else {
      const Joint* slide = m.joint(g.kind == K::RRP ? g.joints[2] : g.joints[1]);
      t.kind = g.kind == K::RRP ? TransmissionKind::RodSlider : TransmissionKind::RodInSlot;
      t.slot = slide->slot;
      t.other = m.slot(t.slot)->body;
      t.linkAt = pointOn(m, t.joint, t.link);
    }
    // A link whose two pins are drawn at one place has no direction.
    const Point *lo = m.point(t.linkOuter), *la = m.point(t.linkAt);
    if (!lo || !la || lo->pos == la->pos) continue;
    if (t.kind == TransmissionKind::Dyad) {
      const Point *oo = m.point(t.otherOuter), *oa = m.point(t.otherAt);
      if (!oo || !oa || oo->pos == oa->pos) continue;
    }
    t.label = "mu:" + m.pointLabel(m.joint(t.joint)->a);
    out.push_back(t);
  }
  return out;
}

TransmissionReading transmissionAngle(const Kinematics& k, const TransmissionJoint& t) {
  if (!k.valid()) return {NAN, NAN, NAN};
  const Signed s = signedAngle(k, t, slotDirection(k.mechanism(), t));
  // mu = |theta| or 90 - |theta|: its rates are theta's, turned by the side theta is on.
  const double side = (s.deg < 0 ? -1 : 1) * (isRod(t) ? -1 : 1);
  return {muOf(t, s.deg), side * s.perDeg, side * s.perDeg2};
}

TransmissionTrack::TransmissionTrack(const Mechanism& m, const TransmissionJoint& t) : t_(t) {
  const Vec2 slot = slotDirection(m, t);
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
