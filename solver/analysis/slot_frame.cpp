#include "analysis/slot_frame.h"

#include <cmath>

namespace linkage {

RelativeMotion relativeMotion(const Kinematics& k, const Kinematics::PointMotion& p, BodyId b) {
  const double rate = secondsPerDegree(k);
  const Rot back = k.bodyTransform(b).R.inverse();
  const Vec2 sketch = k.toSketch(b, p.position);
  // The body's own point under P: the velocity and acceleration P has relative to it.
  const Kinematics::PointMotion under = k.motionOf(b, sketch);
  const Vec2 vRel = p.velocity - under.velocity;
  const Vec2 aRel = p.acceleration - under.acceleration - 2 * k.bodyOmega(b) * perp(vRel);
  return {sketch, back * vRel * rate, back * aRel * (rate * rate)};
}

CycleReading alongGuide(const Guide& g, const RelativeMotion& m) {
  if (!g.arc) return {g.direction.dot(m.r - g.p0), g.direction.dot(m.dr), g.direction.dot(m.ddr)};
  // s = sign(sweep) radius (angle of r about the centre - a0).
  const Vec2 e = m.r - g.centre;
  const double e2 = e.squaredNorm(), k = std::copysign(g.radius, g.sweep);
  const double w = cross(e, m.dr) / e2;
  const double dw = cross(e, m.ddr) / e2 - 2 * e.dot(m.dr) * w / e2;
  return {g.along(m.r), k * w, k * dw};
}

namespace {
template <class V>
CycleReading lengthOfAny(const V& d, const V& dd, const V& ddd) {
  const double n = d.norm();
  if (n == 0) return {0, 0, 0};  // the two meet: a minimum of 0, where |d| has no derivative
  const double d1 = d.dot(dd) / n;
  return {n, d1, (dd.squaredNorm() + d.dot(ddd) - d1 * d1) / n};
}
}  // namespace

CycleReading lengthOf(const Vec2& d, const Vec2& dd, const Vec2& ddd) {
  return lengthOfAny(d, dd, ddd);
}
CycleReading lengthInSpace(const Vec3& d, const Vec3& dd, const Vec3& ddd) {
  return lengthOfAny(d, dd, ddd);
}

CycleReading offGuide(const Guide& g, const RelativeMotion& m) {
  if (!g.arc) return {g.normal.dot(m.r - g.p0), g.normal.dot(m.dr), g.normal.dot(m.ddr)};
  CycleReading r = lengthOf(m.r - g.centre, m.dr, m.ddr);
  r.value -= g.radius;
  return r;
}

CycleReading offDrawnSlot(const Guide& g, const RelativeMotion& m) {
  const double s = g.along(m.r);
  if (s < 0 || s > g.length()) return lengthOf(m.r - (s < 0 ? g.p0 : g.p1), m.dr, m.ddr);
  const CycleReading r = offGuide(g, m);
  return r.value < 0 ? CycleReading{-r.value, -r.d1, -r.d2} : r;
}

}  // namespace linkage
