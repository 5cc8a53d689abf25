// A dimension's move in the rows' class frames (analysis/sensitivity_space.h).
#include "analysis/sensitivity_space.h"

#include <algorithm>

#include "linkage/guide.h"
#include "linkage/slot_sensitivity.h"

namespace linkage::internal {

SpaceMoves::SpaceMoves(const Mechanism& m, const System& sys)
    : m_(m), sys_(sys), spatial_(sys.frames.size() > 1 || isSpatial(m)) {
  if (spatial_) pc_ = planeClasses(m);
}

Vec3 SpaceMoves::kept(const Point& p, const Vec2& move, double depth) const {
  const Body* b = m_.body(p.body);
  if (!spatial_ || ground(b)) return Vec3(move.x(), move.y(), depth);
  const PlaneInClass& at = pc_.of(b->plane);
  const Vec2 c = at.identity ? move : Vec2(at.rot * move);
  return Vec3(c.x(), c.y(), depth);
}

Vec2 SpaceMoves::inClass(PointId p, const Vec3& kept, int cls) const {
  const PointLocation* at = sys_.point(p);
  if (!spatial_ || (at && at->body >= 0)) return kept.head<2>();
  const Plane& f = sys_.frames[cls];
  return Vec2(kept.dot(f.xAxis), kept.dot(f.yAxis));
}

double SpaceMoves::depthIn(PointId p, const Vec3& kept, int cls) const {
  const PointLocation* at = sys_.point(p);
  if (!spatial_ || (at && at->body >= 0)) return kept.z();
  return kept.dot(sys_.frames[cls].normal());
}

Slot SpaceMoves::slot(const Slot& s, int cls) const {
  return spatial_ ? inClassFrame(m_, pc_, s, cls) : s;
}

void SpaceMoves::slotMove(const Slot& s, const Dimension::SlotMove& mv, int cls, Vec2& d0,
                          Vec2& d1) const {
  d0 = mv.p0;
  d1 = mv.p1;
  if (!spatial_) return;
  const Body* b = m_.body(s.body);
  if (ground(b)) {
    const Plane& f = sys_.frames[cls];
    const Vec3 w0(mv.p0.x(), mv.p0.y(), mv.z0), w1(mv.p1.x(), mv.p1.y(), mv.z1);
    d0 = Vec2(w0.dot(f.xAxis), w0.dot(f.yAxis));
    d1 = Vec2(w1.dot(f.xAxis), w1.dot(f.yAxis));
    return;
  }
  const PlaneInClass& at = pc_.of(b->plane);
  if (at.identity) return;
  d0 = at.rot * mv.p0;
  d1 = at.rot * mv.p1;
}

Vec2 SpaceMoves::midMove(const Slot& s, const Dimension::SlotMove& mv, int cls) const {
  const Vec2 d = mv.mid.value_or(Vec2::Zero());
  if (!spatial_) return d;
  const Body* b = m_.body(s.body);
  if (ground(b)) {
    const Plane& f = sys_.frames[cls];
    const Vec3 w(d.x(), d.y(), mv.zm);
    return Vec2(w.dot(f.xAxis), w.dot(f.yAxis));
  }
  const PlaneInClass& at = pc_.of(b->plane);
  return at.identity ? d : Vec2(at.rot * d);
}

void SpaceMoves::arcMove(const Slot& drawn, const Dimension& d, int cls, Vec2& dc,
                         double& drho) const {
  dc = Vec2::Zero();
  drho = 0;
  const Slot s = slot(drawn, cls);
  const std::optional<Guide> g = guideOf(s);
  for (const Dimension::SlotMove& sm : d.slots) {
    if (sm.slot != drawn.id || !g || !g->arc) continue;
    Vec2 dp[3], c;
    double rho;
    slotMove(drawn, sm, cls, dp[0], dp[2]);
    dp[1] = midMove(drawn, sm, cls);
    arcChange(*g, {s.p0, *s.mid, s.p1}, dp, c, rho);
    dc += c;
    drho += rho;
  }
}

int SpaceMoves::slotClass(const Slot& s) const {
  if (!spatial_) return 0;
  const Body* b = m_.body(s.body);
  return ground(b) ? std::max(0, groundSlotClass(m_, pc_, s)) : pc_.of(b->plane).cls;
}

Vec2 SpaceMoves::drawn(const Point& p, int cls) const {
  return spatial_ ? inClassFrame(m_, pc_, p, cls) : p.pos;
}

int SpaceMoves::rowClass(const Row& r) const {
  for (int b : r.body)
    if (b >= 0) return sys_.classOf.empty() ? 0 : sys_.classOf[b];
  return 0;
}

Vec3 SpaceMoves::lift(int cls, const Vec2& v, double depth) const {
  const Plane& f = sys_.frames[cls];
  return v.x() * f.xAxis + v.y() * f.yAxis + depth * f.normal();
}

int groundSlotClass(const Mechanism& m, const PlaneClasses& pc, const Slot& s) {
  for (const Joint& j : m.joints)
    if (j.slot == s.id)
      if (const Point* a = m.point(j.a)) return jointClass(m, pc, *a, s);
  return -1;
}

}  // namespace linkage::internal
