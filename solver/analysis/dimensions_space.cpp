// The dimensions only a machine in space has (analysis/dimensions_space.h). Each is a move of the
// drawing in the world (a moving body's points in its plane's coordinates and depth, the
// ground's in x, y, z), so that scaling every length, the ground's coordinates and the planes'
// origins by s scales the machine in the world by s (docs/sensitivity.md, "In space").
#include "analysis/dimensions_space.h"

#include <cmath>

#include "analysis/sensitivity_space.h"
#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage::internal {

namespace {

Dimension named(const std::string& name, double value) {
  Dimension d;
  d.name = name;
  d.value = value;
  return d;
}

bool isRod(const Joint& j) {
  return kindOf(j).role == Role::Distance;
}

// The moving points whose depth matters: written with one, or at a ball rod's end.
void depths(const Mechanism& m, std::vector<Dimension>& out) {
  for (const Point& p : m.points) {
    const Body* b = m.body(p.body);
    if (!b || b->ground) continue;
    bool rodEnd = false;
    for (const Joint& j : m.joints) rodEnd = rodEnd || (isRod(j) && (j.a == p.id || j.b == p.id));
    if (!p.third && !rodEnd) continue;
    Dimension d = named(b->name + "." + p.name + ".depth", p.third.value_or(0.0));
    d.depths.push_back({p.id, 1.0});
    out.push_back(d);
  }
}

void groundZ(const Mechanism& m, std::vector<Dimension>& out) {
  const Body* g = m.ground();
  if (!g) return;
  for (const Point& p : m.points) {
    if (p.body != g->id) continue;
    Dimension d = named(g->name + "." + p.name + ".z", p.third.value_or(0.0));
    d.depths.push_back({p.id, 1.0});
    out.push_back(d);
  }
}

void rodLengths(const Mechanism& m, std::vector<Dimension>& out) {
  for (const Joint& j : m.joints) {
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!isRod(j) || !a || !b) continue;
    Dimension d = named("ball-rod:" + m.pointLabel(j.a) + ".length",
                        (worldOf(m, *a) - worldOf(m, *b)).norm());
    d.lengthOf = j.id;
    out.push_back(d);
  }
}

// A plane's origin moved along world axis c: its bodies' points and slots move with it.
void planeOrigins(const Mechanism& m, std::vector<Dimension>& out) {
  if (!m.planes) return;
  static const char* const kAxis[] = {".x", ".y", ".z"};
  for (const Plane& f : *m.planes)
    for (int c = 0; c < 3; ++c) {
      Dimension d = named("planes." + f.name + ".origin" + kAxis[c], f.origin[c]);
      d.carriesMasses = true;
      const Vec2 in(f.xAxis[c], f.yAxis[c]);
      const double along = f.normal()[c];
      for (const Body& b : m.bodies) {
        if (b.ground || b.plane != f.name) continue;
        for (const Point& p : m.points)
          if (p.body == b.id) {
            d.points.push_back({p.id, in});
            d.depths.push_back({p.id, along});
          }
        for (const Slot& s : m.slots)
          if (s.body == b.id)
            d.slots.push_back({s.id, in, in, 0, 0, s.mid ? std::optional(in) : std::nullopt});
      }
      out.push_back(d);
    }
}

}  // namespace

bool hasSpaceDimensions(const Mechanism& m) {
  if (isSpatial(m)) return true;
  for (const Joint& j : m.joints)
    if (isRod(j)) return true;
  return false;
}

// A ground arc's centre in the world and its radius: each moves its three points, the centre
// along a world axis, the radius away from the centre in the arc's own plane.
void groundArcInSpace(const Mechanism& m, const Slot& s, std::vector<Dimension>& out) {
  Vec3 c;
  double radius;
  const std::vector<Vec3> w = slotInWorld(s);
  if (!circleThrough(w[0], w[1], w[2], c, radius)) return;
  const std::string pre = m.slotLabel(s.id) + ".";
  static const char* const kAxis[] = {"centre.x", "centre.y", "centre.z"};
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    Dimension d = named(pre + kAxis[k], c[k]);
    d.slots.push_back({s.id, e.head<2>(), e.head<2>(), e.z(), e.z(), e.head<2>(), e.z()});
    out.push_back(d);
  }
  Dimension r = named(pre + "radius", radius);
  const Vec3 r0 = (w[0] - c) / radius, rm = (w[1] - c) / radius, r1 = (w[2] - c) / radius;
  r.slots.push_back({s.id, r0.head<2>(), r1.head<2>(), r0.z(), r1.z(), rm.head<2>(), rm.z()});
  out.push_back(r);
}

void groundSlotInSpace(const Mechanism& m, const Slot& s, std::vector<Dimension>& out) {
  const PlaneClasses pc = planeClasses(m);
  const int cls = groundSlotClass(m, pc, s);
  if (cls < 0) return;
  if (s.arc()) return groundArcInSpace(m, s, out);
  const Vec3 w0(s.p0.x(), s.p0.y(), s.z.size() > 0 ? s.z[0] : 0.0);
  const Vec3 w1(s.p1.x(), s.p1.y(), s.z.size() > 1 ? s.z[1] : 0.0);
  const Plane& f = pc.frames[cls];
  const Vec3 n = f.normal(), t = (w1 - w0).normalized(), across = n.cross(t);
  const std::string pre = m.slotLabel(s.id) + ".";
  Dimension offset = named(pre + "offset", across.dot(w0));
  offset.slots.push_back({s.id, across.head<2>(), across.head<2>(), across.z(), across.z()});
  Dimension angle = named(pre + "angle", std::atan2(t.dot(f.yAxis), t.dot(f.xAxis)) * 180 / M_PI);
  angle.unit = Dimension::Unit::Deg;
  const Vec3 turn = n.cross(w1 - w0) * (M_PI / 180);
  angle.slots.push_back({s.id, Vec2::Zero(), turn.head<2>(), 0.0, turn.z()});
  out.push_back(offset);
  out.push_back(angle);
}

void spaceDimensions(const Mechanism& m, std::vector<Dimension>& out) {
  if (isSpatial(m)) {
    depths(m, out);
    groundZ(m, out);
  }
  rodLengths(m, out);
  planeOrigins(m, out);
}

}  // namespace linkage::internal
