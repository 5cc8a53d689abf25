#include "view3d/scene3d.h"

#include <algorithm>
#include <cmath>

#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage::ui {

namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// Andrew's monotone chain: the indices of the hull of `p`, counter-clockwise; all of them when
// there are fewer than three distinct points.
std::vector<size_t> hullOf(const std::vector<Vec2>& p) {
  std::vector<size_t> order(p.size());
  for (size_t i = 0; i < p.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return p[a].x() < p[b].x() || (p[a].x() == p[b].x() && p[a].y() < p[b].y());
  });
  if (p.size() < 3) return order;
  std::vector<size_t> h(2 * p.size());
  size_t k = 0;
  for (size_t i : order) {
    while (k >= 2 && cross(p[h[k - 2]], p[h[k - 1]], p[i]) <= 0) --k;
    h[k++] = i;
  }
  for (size_t j = order.size() - 1, t = k + 1; j-- > 0;) {
    const size_t i = order[j];
    while (k >= t && cross(p[h[k - 2]], p[h[k - 1]], p[i]) <= 0) --k;
    h[k++] = i;
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

// A moving body's plate: its points brought back to its plane (their depth taken off), the
// hull of them in the plane's axes.
Scene3d::Plate plateOf(const Mechanism& m, const Body& b, const WorldPose& at) {
  Scene3d::Plate plate{b.id, b.number.value_or(0), b.plane, {}, {}};
  const Plane& pl = planeOf(m, b.id);
  const Vec3 n = pl.normal();
  std::vector<Vec3> inPlane;
  std::vector<Vec2> flat;
  for (const Point& p : m.points) {
    if (p.body != b.id) continue;
    const Vec3 w = at.point(p.id);
    if (!w.allFinite()) continue;
    const double d = p.third.value_or(0);
    const Vec3 foot = w - d * n;
    if (d != 0) plate.studs.emplace_back(foot, w);
    inPlane.push_back(foot);
  }
  // A slot is part of its body's outline (the Wanzer's slotted disk).
  for (const Slot& sl : m.slots) {
    if (sl.body != b.id) continue;
    for (const Vec2& e : {sl.p0, sl.p1})
      if (const Vec3 w = at.body(b.id, e); w.allFinite()) inPlane.push_back(w);
  }
  for (const Vec3& v : inPlane) flat.emplace_back(v.dot(pl.xAxis), v.dot(pl.yAxis));
  for (size_t i : hullOf(flat)) plate.outline.push_back(inPlane[i]);
  // Two points drawn over one another are one: a dot, not a bar of no length.
  if (plate.outline.size() == 2 && (plate.outline[0] - plate.outline[1]).norm() < 1e-9)
    plate.outline.pop_back();
  return plate;
}

// Every slot's groove: the ground's in the world as written, a moving body's sampled in its
// drawing and carried to where the body is.
void addGrooves(const Mechanism& m, Scene3d& s, const WorldPose& at) {
  for (const Slot& sl : m.slots) {
    const Body* b = m.body(sl.body);
    if (!b) continue;
    Scene3d::Groove g{sl.id, b->id, b->number.value_or(0), b->ground, {}};
    if (b->ground) {
      g.path = slotCurveInWorld(sl);
    } else {
      Slot drawn = sl;  // in the body's sketch
      drawn.z.clear();
      for (const Vec3& q : slotCurveInWorld(drawn)) g.path.push_back(at.body(b->id, q.head<2>()));
    }
    if (std::all_of(g.path.begin(), g.path.end(), [](const Vec3& v) { return v.allFinite(); }))
      s.grooves.push_back(std::move(g));
  }
}

void grow(Scene3d& s, const Vec3& p, bool& first) {
  s.lo = first ? p : Vec3(s.lo.cwiseMin(p));
  s.hi = first ? p : Vec3(s.hi.cwiseMax(p));
  first = false;
}

// The ground's pivots: a pin of the ground to a moving body is a shaft along that body's
// plane's normal.
void addAxes(const Mechanism& m, Scene3d& s, const WorldPose& at) {
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const Point* a = m.point(j.a);
    const Point* b = m.point(j.b);
    if (!a || !b) continue;
    const Body* ba = m.body(a->body);
    const Body* bb = m.body(b->body);
    if (!ba || !bb || ba->ground == bb->ground) continue;
    const Point* pivot = ba->ground ? a : b;
    const Body* turning = ba->ground ? bb : ba;
    s.axes.push_back({at.point(pivot->id), planeOf(m, turning->id).normal()});
  }
}

}  // namespace

std::vector<Vec3> Scene3d::extent() const {
  std::vector<Vec3> out;
  for (const Mark& m : points) out.push_back(m.at);
  for (const Plate& p : plates) out.insert(out.end(), p.outline.begin(), p.outline.end());
  for (const Groove& g : grooves) out.insert(out.end(), g.path.begin(), g.path.end());
  const double reach = 0.15 * std::max((hi - lo).norm(), 1.0);
  for (const Axis& a : axes) {
    out.push_back(a.at + reach * a.direction);
    out.push_back(a.at - reach * a.direction);
  }
  return out;
}

Scene3d describeScene3d(const Mechanism& m, const WorldPose& at) {
  Scene3d s;
  for (const Body& b : m.bodies)
    if (!b.ground) s.plates.push_back(plateOf(m, b, at));
  bool first = true;
  for (const Point& p : m.points) {
    const Vec3 w = at.point(p.id);
    if (!w.allFinite()) continue;
    const Body* b = m.body(p.body);
    s.points.push_back({p.id, p.body, w, b && b->ground});
    grow(s, w, first);
  }
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Distance) continue;
    const Vec3 a = at.point(j.a), b = at.point(j.b);
    if (a.allFinite() && b.allFinite()) s.rods.push_back({j.id, a, b});
  }
  addGrooves(m, s, at);
  for (const Scene3d::Plate& p : s.plates)
    for (const Vec3& v : p.outline) grow(s, v, first);
  for (const Scene3d::Groove& g : s.grooves)
    for (const Vec3& v : g.path) grow(s, v, first);
  addAxes(m, s, at);
  return s;
}

}  // namespace linkage::ui
