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

// theta (degrees, see transmission_track.h) and its derivatives per degree of crank.
TransmissionReading signedAngle(const Kinematics& k, const TransmissionJoint& t) {
  const double w = k.omega();
  double theta = 0, rate = 0, accel = 0;
  if (t.kind == TransmissionKind::Dyad) {
    const Vec2 u = k.position(t.linkOuter) - k.position(t.linkAt);
    const Vec2 v = k.position(t.otherOuter) - k.position(t.otherAt);
    theta = std::atan2(cross(u, v), u.dot(v));
  } else {
    const Kinematics::Segment s = k.slotEnds(t.slot);
    const Vec2 d = s.p1 - s.p0, u = k.position(t.linkAt) - k.position(t.linkOuter);
    theta = std::atan2(cross(d, u), d.dot(u));
    if (theta > M_PI / 2) theta -= M_PI;
    if (theta <= -M_PI / 2) theta += M_PI;
  }
  // A line fixed in a body turns with it: theta turns at the difference of the two bodies'
  // rates (the rod's minus the slot's, the second link's minus the first's).
  const double sign = isRod(t) ? 1 : -1;
  rate = sign * (k.bodyOmega(t.link) - k.bodyOmega(t.other)) / w;
  accel = sign * (k.bodyAlpha(t.link) - k.bodyAlpha(t.other)) / (w * w) * kDeg;
  return {theta / kDeg, rate, accel};
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
  const TransmissionReading s = signedAngle(k, t);
  // mu = |theta| or 90 - |theta|: its rates are theta's, turned by the side theta is on.
  const double side = (s.deg < 0 ? -1 : 1) * (isRod(t) ? -1 : 1);
  return {muOf(t, s.deg), side * s.perDeg, side * s.perDeg2};
}

TransmissionTrack::TransmissionTrack(const TransmissionJoint& t) : t_(t) {
  stationary_.f = [t](const Kinematics& k) {
    const TransmissionReading r = signedAngle(k, t);
    return RootSample{r.perDeg, r.perDeg2};
  };
  stationary_.value = [t](const Kinematics& k) { return signedAngle(k, t).deg; };
  along_.f = [t](const Kinematics& k) {
    const TransmissionReading r = signedAngle(k, t);
    return RootSample{std::sin(2 * r.deg * kDeg), 2 * std::cos(2 * r.deg * kDeg) * r.perDeg * kDeg};
  };
  along_.value = stationary_.value;
}

void TransmissionTrack::sample(const Kinematics& k) {
  const TransmissionReading r = signedAngle(k, t_);
  mu.push_back(muOf(t_, r.deg));
  stationary_.samples.push_back({r.perDeg, r.perDeg2});
  if (isRod(t_))
    along_.samples.push_back(
        {std::sin(2 * r.deg * kDeg), 2 * std::cos(2 * r.deg * kDeg) * r.perDeg * kDeg});
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
