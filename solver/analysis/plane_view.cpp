// A machine in space seen on one of its planes (linkage/plane_view.h).
#include "linkage/plane_view.h"

#include <algorithm>
#include <cmath>

namespace linkage {

namespace {

Rot times(const Rot& a, const Rot& b) {
  return Rot{a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
}

Transform toClassOf(const PlaneInClass& p) {
  return p.identity ? Transform{} : Transform{p.rot, p.shift};
}

Transform fromClassOf(const PlaneInClass& p) {
  if (p.identity) return Transform{};
  const Rot back = p.rot.inverse();
  return Transform{back, -(back * p.shift)};
}

}  // namespace

Transform compose(const Transform& a, const Transform& b) {
  return Transform{times(a.R, b.R), a.R * b.t + a.t};
}

PlaneView::PlaneView(const Mechanism& m, const std::string& plane) {
  if (!isSpatial(m)) return;
  identity_ = false;
  const PlaneClasses classes = planeClasses(m);
  view_ = classes.of(planeNamed(m, plane) ? plane : std::string());
  plane_ = planeNamed(m, plane) ? *planeNamed(m, plane) : drawingPlane();
  frame_ = classes.frames[view_.cls];
  std::uint32_t maxBody = 0, maxPoint = 0;
  for (const Body& b : m.bodies) maxBody = std::max(maxBody, b.id.value);
  for (const Point& p : m.points) maxPoint = std::max(maxPoint, p.id.value);
  placing_.assign(maxBody + 1, view_);
  for (const Body& b : m.bodies)
    if (!b.ground) placing_[b.id.value] = classes.of(b.plane);
  groundDepth_.assign(maxPoint + 1, 0.0);
  seen_ = m;
  // The ground seen along the chosen plane's normal: projected into its class's frame, then
  // into the plane (whose depth in that frame is view_.depth).
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (Point& p : seen_.points) {
    const Vec3 w = worldOf(m, p);
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
    const Body* b = m.body(p.body);
    if (!b || !b->ground) continue;
    double depth = 0;
    p.pos = view_.fromClass(classes.project(view_.cls, w, &depth));
    p.third.reset();
    groundDepth_[p.id.value] = depth - view_.depth;
  }
  for (Slot& s : seen_.slots) {
    const Body* b = m.body(s.body);
    if (!b || !b->ground) continue;
    s = inClassFrame(m, classes, s, view_.cls);
    s.p0 = view_.fromClass(s.p0);
    s.p1 = view_.fromClass(s.p1);
    if (s.mid) s.mid = view_.fromClass(*s.mid);
  }
  if (lo.allFinite() && hi.allFinite()) size_ = std::max(1.0, (hi - lo).norm());
}

Vec2 PlaneView::worldInView(const Vec3& w) const {
  if (identity_) return w.head<2>();
  const Vec3 d = w - frame_.origin;
  return view_.fromClass(Vec2(d.dot(frame_.xAxis), d.dot(frame_.yAxis)));
}

const PlaneInClass& PlaneView::placingOf(BodyId b) const {
  return b.value < placing_.size() ? placing_[b.value] : view_;
}

Transform PlaneView::outOf(const PlaneInClass& own) const {
  return fromClassOf(own.cls == view_.cls ? view_ : own);
}

Vec2 PlaneView::fromSolver(BodyId b, const Vec2& classPos) const {
  if (identity_) return classPos;
  const Body* body = seen_.body(b);
  if (!body || body->ground) return classPos;
  return outOf(placingOf(b)) * classPos;
}

Vec2 PlaneView::point(const Kinematics& k, PointId p) const {
  if (identity_) return k.position(p);
  const Point* q = seen_.point(p);
  if (!q) return Vec2(NAN, NAN);
  const Body* b = seen_.body(q->body);
  return b && b->ground ? q->pos : fromSolver(q->body, k.position(p));
}

Transform PlaneView::pose(const Kinematics& k, BodyId b) const {
  const Transform T = k.bodyTransform(b);
  if (identity_) return T;
  const Body* body = seen_.body(b);
  if (!body || body->ground) return T;
  // Own sketch -> class frame (the solver's sketch), moved, -> the view.
  const PlaneInClass& own = placingOf(b);
  return compose(outOf(own), compose(T, toClassOf(own)));
}

Kinematics::Segment PlaneView::slotEnds(const Kinematics& k, SlotId s) const {
  const Slot* sl = seen(k.mechanism()).slot(s);
  if (!sl) return {Vec2(NAN, NAN), Vec2(NAN, NAN)};
  const Transform T = pose(k, sl->body);
  return {T * sl->p0, T * sl->p1};
}

Vec2 PlaneView::sketchPoint(const Mechanism& m, PointId p) const {
  const Point* q = seen(m).point(p);
  return q ? sketchPose(q->body) * q->pos : Vec2(NAN, NAN);
}

Transform PlaneView::sketchPose(BodyId b) const {
  if (identity_) return Transform{};
  const Body* body = seen_.body(b);
  if (!body || body->ground) return Transform{};
  const PlaneInClass& own = placingOf(b);
  return compose(outOf(own), toClassOf(own));
}

double PlaneView::groundDepth(PointId p) const {
  return p.value < groundDepth_.size() ? groundDepth_[p.value] : 0.0;
}

void PlaneView::placeGround(Point& p, const Vec2& at) const {
  if (identity_) {
    p.pos = at;
    return;
  }
  const Vec3 w = plane_.world(at, groundDepth(p.id));
  p.pos = Vec2(w.x(), w.y());
  if (p.third || w.z() != 0) p.third = w.z();
}

void PlaneView::placeGround(Slot& s) const {
  if (identity_) return;
  s.z.clear();
  std::vector<Vec2*> ends{&s.p0, &s.p1};
  if (s.mid) ends.insert(ends.begin() + 1, &*s.mid);
  bool flat = true;
  for (Vec2* e : ends) {
    const Vec3 w = plane_.world(*e);
    *e = Vec2(w.x(), w.y());
    s.z.push_back(w.z());
    flat = flat && w.z() == 0;
  }
  if (flat) s.z.clear();  // in the drawing plane: [x, y] as before
}

}  // namespace linkage
