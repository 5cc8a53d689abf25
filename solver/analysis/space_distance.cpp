// Distances in space: see analysis/space_distance.h.
//
// To the segment: with w = X - A and u = B - A (|u| fixed: one body), the foot of the
// perpendicular is at t = w.u / u.u along u and r = w - t u; t' and t'' follow from w.u
// differentiated (u.u is constant), r' = w' - t' u - t u', r'' = w'' - t'' u - 2 t' u' - t u''.
#include "analysis/space_distance.h"

#include <algorithm>

#include "analysis/sensitivity_space.h"
#include "analysis/slot_frame.h"
#include "linkage/guide.h"
#include "linkage/space.h"

namespace linkage {

SpaceMotion spaceMotion(const Kinematics& k, PointId p) {
  const double rate = secondsPerDegree(k);
  const Kinematics::PointMotion3 m = k.motionInSpace(p);
  return {m.position, m.velocity * rate, m.acceleration * (rate * rate)};
}

CycleReading spaceDistance(const Kinematics& k, PointId p, PointId q) {
  const SpaceMotion a = spaceMotion(k, p), b = spaceMotion(k, q);
  return lengthInSpace(Vec3(a.r - b.r), Vec3(a.dr - b.dr), Vec3(a.ddr - b.ddr));
}

namespace {

CycleReading toSegment(const SpaceMotion& x, const SpaceMotion& A, const SpaceMotion& B,
                       Vec3* nearest) {
  const Vec3 w = x.r - A.r, w1 = x.dr - A.dr, w2 = x.ddr - A.ddr;
  const Vec3 u = B.r - A.r, u1 = B.dr - A.dr, u2 = B.ddr - A.ddr;
  const double uu = u.squaredNorm(), t = w.dot(u) / uu;
  if (t <= 0 || t >= 1) {
    const SpaceMotion& end = t <= 0 ? A : B;
    if (nearest) *nearest = end.r;
    return lengthInSpace(Vec3(x.r - end.r), Vec3(x.dr - end.dr), Vec3(x.ddr - end.ddr));
  }
  const double t1 = (w1.dot(u) + w.dot(u1)) / uu;
  const double t2 = (w2.dot(u) + 2 * w1.dot(u1) + w.dot(u2)) / uu;
  if (nearest) *nearest = A.r + t * u;
  return lengthInSpace(Vec3(w - t * u), Vec3(w1 - t1 * u - t * u1),
                       Vec3(w2 - t2 * u - 2 * t1 * u1 - t * u2));
}

}  // namespace

CycleReading spaceDistanceToSegment(const Kinematics& k, PointId p, PointId a, PointId b,
                                    Vec3* nearest) {
  return toSegment(spaceMotion(k, p), spaceMotion(k, a), spaceMotion(k, b), nearest);
}

void slotEndsInSpace(const Kinematics& k, const Slot& s, SpaceMotion ends[2]) {
  const Mechanism& m = k.mechanism();
  const Body* body = m.body(s.body);
  const Vec2 drawn[2] = {s.p0, s.p1};
  if (!body || body->ground) {
    for (int e = 0; e < 2; ++e)
      ends[e] = {Vec3(drawn[e].x(), drawn[e].y(), e < static_cast<int>(s.z.size()) ? s.z[e] : 0.0),
                 Vec3::Zero(), Vec3::Zero()};
    return;
  }
  // The body's points are held in its plane class's frame: the slot's ends mapped there, moved
  // with the body, lifted into the world at the plane's depth.
  const PlaneClasses pc = planeClasses(m);
  const PlaneInClass& in = pc.of(body->plane);
  const Plane& f = pc.frames[in.cls];
  auto lift = [&](const Vec2& v) { return Vec3(v.x() * f.xAxis + v.y() * f.yAxis); };
  const double rate = secondsPerDegree(k);
  for (int e = 0; e < 2; ++e) {
    const Kinematics::PointMotion at = k.motionOf(s.body, in.toClass(drawn[e]));
    ends[e] = {Vec3(f.origin + lift(at.position) + in.depth * f.normal()), lift(at.velocity) * rate,
               lift(at.acceleration) * (rate * rate)};
  }
}

CycleReading spaceDistanceToSlot(const Kinematics& k, PointId p, const Slot& s, Vec3* nearest) {
  SpaceMotion ends[2];
  slotEndsInSpace(k, s, ends);
  return toSegment(spaceMotion(k, p), ends[0], ends[1], nearest);
}

namespace {

// A slot's plane in the world and its curve as its class's frame draws it.
struct SlotPlace {
  Plane f;           // the class's frame
  double depth = 0;  // the arc's plane along f's normal
  std::optional<Guide> g;
};

SlotPlace slotPlace(const Mechanism& m, const Slot& s) {
  const PlaneClasses pc = planeClasses(m);
  const Body* body = m.body(s.body);
  const bool ground = !body || body->ground;
  const int cls =
      ground ? std::max(0, internal::groundSlotClass(m, pc, s)) : pc.of(body->plane).cls;
  SlotPlace a{pc.frames[cls], 0,
              soundSlot(s) ? guideOf(inClassFrame(m, pc, s, cls)) : std::nullopt};
  a.depth = ground ? a.f.normal().dot(slotInWorld(s)[0] - a.f.origin) : pc.of(body->plane).depth;
  return a;
}

}  // namespace

CycleReading spaceDistanceToArc(const Kinematics& k, PointId p, const Slot& s, Vec3* nearest,
                                int* end) {
  const SlotPlace a = slotPlace(k.mechanism(), s);
  if (!a.g || !a.g->arc) return {NAN, NAN, NAN};
  const Vec3 n = a.f.normal();
  const double rate = secondsPerDegree(k);
  auto lift = [&](const Vec2& v) { return Vec3(v.x() * a.f.xAxis + v.y() * a.f.yAxis); };
  auto inWorld = [&](const Vec2& drawn) {  // a point of the slot's body, drawn in the class frame
    const Kinematics::PointMotion at = k.motionOf(s.body, drawn);
    return SpaceMotion{a.f.origin + lift(at.position) + a.depth * n, lift(at.velocity) * rate,
                       lift(at.acceleration) * (rate * rate)};
  };
  const SpaceMotion x = spaceMotion(k, p), c = inWorld(a.g->centre);
  const Vec3 w = x.r - c.r, w1 = x.dr - c.dr, w2 = x.ddr - c.ddr;
  // The body turns about n: n holds, and so h's rates are n's components of w's.
  const double h = n.dot(w), h1 = n.dot(w1), h2 = n.dot(w2);
  const Vec3 v = w - h * n, v1 = w1 - h1 * n, v2 = w2 - h2 * n;
  const double rho = v.norm();
  const Vec3 rel = x.r - a.f.origin;
  const double along = a.g->along(k.toSketch(s.body, Vec2(rel.dot(a.f.xAxis), rel.dot(a.f.yAxis))));
  if (end) *end = -1;
  if (along <= 0 || along >= a.g->length() || !(rho > 0)) {  // on the axis: every point alike
    const int e = along <= 0 ? 0 : 1;
    const SpaceMotion at = inWorld(e ? a.g->p1 : a.g->p0);
    if (nearest) *nearest = at.r;
    if (end) *end = e;
    return lengthInSpace(Vec3(x.r - at.r), Vec3(x.dr - at.dr), Vec3(x.ddr - at.ddr));
  }
  const double rho1 = v.dot(v1) / rho;
  const double rho2 = (v1.squaredNorm() + v.dot(v2)) / rho - rho1 * rho1 / rho;
  if (nearest) *nearest = c.r + a.g->radius / rho * v;
  return lengthInSpace(Vec3(h, rho - a.g->radius, 0), Vec3(h1, rho1, 0), Vec3(h2, rho2, 0));
}

std::vector<Vec2> slotCurveInClass(const Kinematics& k, const Slot& s, int pieces) {
  const SlotPlace a = slotPlace(k.mechanism(), s);
  if (!a.g) return {};
  if (!a.g->arc) pieces = 1;
  std::vector<Vec2> out;
  for (int i = 0; i <= pieces; ++i)
    out.push_back(k.toWorld(s.body, i == 0        ? a.g->p0
                                    : i == pieces ? a.g->p1
                                                  : a.g->at(a.g->length() * i / pieces)));
  return out;
}

Vec2 intoSlotClass(const Mechanism& m, const Slot& s, const Vec3& w) {
  const SlotPlace a = slotPlace(m, s);
  return Vec2((w - a.f.origin).dot(a.f.xAxis), (w - a.f.origin).dot(a.f.yAxis));
}

}  // namespace linkage
