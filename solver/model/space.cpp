// Planes in space: lookups, the checks of the file format and the plane classes
// (linkage/space.h).
#include "linkage/space.h"

#include <algorithm>
#include <cmath>

namespace linkage {

namespace {

constexpr double kTol = 1e-9;

std::string literal(const std::string& s) {
  std::string q = "\"";
  q += s;
  q += '"';
  return q;
}

std::string axisProblem(const Plane& p) {
  const std::string at = "planes." + p.name;
  for (const auto& [v, key] : {std::pair{&p.origin, ".origin"}, std::pair{&p.xAxis, ".x_axis"},
                               std::pair{&p.yAxis, ".y_axis"}})
    if (!v->allFinite()) return at + key + ": expected three finite numbers";
  if (std::abs(p.xAxis.norm() - 1) > kTol) return at + ".x_axis: not a unit vector (to 1e-9)";
  if (std::abs(p.yAxis.norm() - 1) > kTol) return at + ".y_axis: not a unit vector (to 1e-9)";
  if (std::abs(p.xAxis.dot(p.yAxis)) > kTol)
    return at + ".y_axis: not perpendicular to x_axis (to 1e-9)";
  return {};
}

}  // namespace

const Plane& drawingPlane() {
  static const Plane p{"drawing", Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), {}};
  return p;
}

const Plane* planeNamed(const Mechanism& m, const std::string& name) {
  if (name.empty() || name == "drawing") return &drawingPlane();
  if (m.planes)
    for (const Plane& p : *m.planes)
      if (p.name == name) return &p;
  return nullptr;
}

const Plane& planeOf(const Mechanism& m, BodyId body) {
  const Body* b = m.body(body);
  const Plane* p = b ? planeNamed(m, b->plane) : nullptr;
  return p ? *p : drawingPlane();
}

bool isSpatial(const Mechanism& m) {
  if (m.planes) return true;
  if (std::any_of(m.points.begin(), m.points.end(), [](const Point& p) { return p.third; }))
    return true;
  return std::any_of(m.slots.begin(), m.slots.end(), [](const Slot& s) { return !s.z.empty(); });
}

std::string notInSpaceYet(const Mechanism& m, const std::string& what) {
  if (!isSpatial(m)) return {};
  for (const Body& b : m.bodies)
    if (!b.ground && !b.plane.empty() && b.plane != "drawing")
      return what + " of a machine in space (body \"" + b.name + "\" moves in plane \"" + b.plane +
             "\") are not computed yet: the motion table and the kinematics are";
  const bool third =
      std::any_of(m.points.begin(), m.points.end(), [](const Point& p) { return p.third; }) ||
      std::any_of(m.slots.begin(), m.slots.end(), [](const Slot& s) { return !s.z.empty(); });
  if (!third) return {};  // "planes" named, none used: a planar machine
  return what +
         " of a machine in space (points with a third number) are not computed yet: "
         "the motion table and the kinematics are";
}

bool parallel(const Plane& a, const Plane& b) {
  return (a.normal() - b.normal()).lpNorm<Eigen::Infinity>() <= kTol;
}

Vec3 worldOf(const Mechanism& m, const Point& p) {
  const Body* b = m.body(p.body);
  if (!b || b->ground) return Vec3(p.pos.x(), p.pos.y(), p.third.value_or(0.0));
  return planeOf(m, p.body).world(p.pos, p.third.value_or(0.0));
}

std::string planesProblem(const Mechanism& m) {
  if (m.planes) {
    const std::vector<Plane>& planes = *m.planes;
    for (size_t i = 0; i < planes.size(); ++i) {
      const Plane& p = planes[i];
      if (p.name.empty()) return "planes: a plane name may not be empty";
      if (p.name == "drawing")
        return "planes.drawing: the drawing plane is fixed (origin 0, x (1, 0, 0), y (0, 1, 0)) "
               "and cannot be redefined";
      for (size_t k = 0; k < i; ++k)
        if (planes[k].name == p.name) return "planes: two planes are named " + literal(p.name);
      if (std::string why = axisProblem(p); !why.empty()) return why;
    }
  }
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    const std::string at = "bodies[" + std::to_string(i) + "].plane";
    if (b.plane.empty()) continue;
    if (b.ground)
      return at +
             ": the ground has no plane (its points are in the drawing plane or, with "
             "three numbers, in the world)";
    if (!planeNamed(m, b.plane)) return at + ": no plane " + literal(b.plane);
  }
  return {};
}

const PlaneInClass& PlaneClasses::of(const std::string& plane) const {
  const std::string& name = plane.empty() ? names.front() : plane;
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return placing[i];
  return placing.front();
}

Vec2 PlaneClasses::project(int k, const Vec3& w, double* depth) const {
  const Plane& f = frames[k];
  const Vec3 d = w - f.origin;
  if (depth) *depth = d.dot(f.normal());
  return Vec2(d.dot(f.xAxis), d.dot(f.yAxis));
}

PlaneClasses planeClasses(const Mechanism& m) {
  PlaneClasses c;
  std::vector<const Plane*> all{&drawingPlane()};
  if (m.planes)
    for (const Plane& p : *m.planes) all.push_back(&p);
  for (const Plane* p : all) {
    PlaneInClass at;
    at.cls = -1;
    for (size_t k = 0; k < c.frames.size() && at.cls < 0; ++k)
      if (parallel(*p, c.frames[k])) at.cls = static_cast<int>(k);
    if (at.cls < 0) {
      at.cls = static_cast<int>(c.frames.size());
      c.frames.push_back(*p);
    } else {
      const Plane& f = c.frames[at.cls];
      const double cs = p->xAxis.dot(f.xAxis), sn = p->xAxis.dot(f.yAxis), n = std::hypot(cs, sn);
      at.rot = Rot{cs / n, sn / n};
      double depth = 0;
      at.shift = c.project(at.cls, p->origin, &depth);
      at.depth = depth;
      at.identity = false;
    }
    c.names.push_back(p->name);
    c.placing.push_back(at);
  }
  return c;
}

std::vector<Vec3> slotInWorld(const Slot& s) {
  std::vector<Vec3> w{{s.p0.x(), s.p0.y(), 0}};
  if (s.mid) w.emplace_back(s.mid->x(), s.mid->y(), 0);
  w.emplace_back(s.p1.x(), s.p1.y(), 0);
  for (size_t k = 0; k < w.size() && k < s.z.size(); ++k) w[k].z() = s.z[k];
  return w;
}

bool circleThrough(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& centre, double& radius) {
  // Relative to c: centre = c + ((|u|^2 v - |v|^2 u) x (u x v)) / (2 |u x v|^2).
  const Vec3 u = a - c, v = b - c, n = u.cross(v);
  if (!(n.norm() > 1e-12 * u.norm() * v.norm())) return false;
  centre = c + (u.squaredNorm() * v - v.squaredNorm() * u).cross(n) / (2 * n.squaredNorm());
  radius = (a - centre).norm();
  return std::isfinite(radius);
}

std::vector<Vec3> slotCurveInWorld(const Slot& s) {
  const std::vector<Vec3> q = slotInWorld(s);
  Vec3 c;
  double r = 0;
  if (q.size() < 3 || !circleThrough(q[0], q[1], q[2], c, r)) return {q.front(), q.back()};
  // Turning about n the arc meets its points in order: n from its two chords.
  const Vec3 n = (q[1] - q[0]).cross(q[2] - q[1]).normalized(), u = (q[0] - c) / r, v = n.cross(u),
             e = q[2] - c;
  double end = std::atan2(e.dot(v), e.dot(u));
  if (end <= 0) end += 2 * M_PI;
  const int steps = std::max(2, static_cast<int>(std::ceil(end / (5 * M_PI / 180))));
  std::vector<Vec3> out;
  for (int i = 0; i < steps; ++i) {
    const double t = end * i / steps;
    out.push_back(c + r * (std::cos(t) * u + std::sin(t) * v));
  }
  out.push_back(q[2]);
  return out;
}

Vec2 inClassFrame(const Mechanism& m, const PlaneClasses& pc, const Point& p, int cls) {
  const Body* b = m.body(p.body);
  if (b && !b->ground) return pc.of(b->plane).toClass(p.pos);
  return pc.project(cls, Vec3(p.pos.x(), p.pos.y(), p.third.value_or(0.0)));
}

Slot inClassFrame(const Mechanism& m, const PlaneClasses& pc, const Slot& s, int cls) {
  Slot c = s;
  c.z.clear();
  const Body* b = m.body(s.body);
  const PlaneInClass* moving = b && !b->ground ? &pc.of(b->plane) : nullptr;
  std::vector<Vec2*> ends{&c.p0, &c.p1};
  if (c.mid) ends.insert(ends.begin() + 1, &*c.mid);
  for (size_t e = 0; e < ends.size(); ++e) {
    const double z = e < s.z.size() ? s.z[e] : 0.0;
    *ends[e] =
        moving ? moving->toClass(*ends[e]) : pc.project(cls, Vec3(ends[e]->x(), ends[e]->y(), z));
  }
  return c;
}

Mechanism flattenedTo(const Mechanism& m, const PlaneClasses& pc, int cls) {
  Mechanism f = m;
  for (Point& p : f.points) {
    p.pos = inClassFrame(m, pc, p, cls);
    p.third.reset();
  }
  for (Slot& s : f.slots) s = inClassFrame(m, pc, s, cls);
  for (Body& b : f.bodies) b.plane.clear();
  f.planes.reset();
  return f;
}

int jointClass(const Mechanism& m, const PlaneClasses& classes, const Point& a, const Slot& s) {
  const Body* body = m.body(a.body);
  if (!body || body->ground) body = m.body(s.body);
  return body && !body->ground ? classes.of(body->plane).cls : 0;
}

}  // namespace linkage
