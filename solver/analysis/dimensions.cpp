// The dimensions of a mechanism and what each moves (linkage/sensitivity.h).
#include <cmath>

#include "analysis/dimensions_space.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/gear.h"
#include "linkage/guide.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"

namespace linkage {

namespace {

// Seen from Pk, P0 and P1 closer than this to one line (rad): two distances do not place Pk
// well (their sensitivities grow as 1 / this), so it is placed along and across P0->P1.
constexpr double kOnLine = 1e-3;

Dimension distance(const std::string& name, double value) {
  Dimension d;
  d.name = name;
  d.value = value;
  return d;
}

// Pk by its distances from P0 and P1: the move of Pk for a change t0 of |P0Pk|, t1 of |P1Pk|
// and a move m1 of P1 (u0 . dPk = t0, u1 . (dPk - m1) = t1).
Vec2 placed(const Vec2& u0, const Vec2& u1, double t0, double t1, const Vec2& m1) {
  const double det = cross(u0, u1);
  const double b0 = t0, b1 = t1 + u1.dot(m1);
  return Vec2(b0 * u1.y() - b1 * u0.y(), u0.x() * b1 - u1.x() * b0) / det;
}

}  // namespace

bool measuredAlongAcross(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double len = (b - a).norm(), r0 = (c - a).norm(), r1 = (c - b).norm();
  return !(r0 > 1e-9 * len && r1 > 1e-9 * len &&
           std::abs(cross((c - a) / r0, (c - b) / r1)) > kOnLine);
}

namespace {

void bodyDimensions(const Mechanism& m, const Body& body, std::vector<Dimension>& out) {
  std::vector<const Point*> p;
  for (const Point& q : m.points)
    if (q.body == body.id) p.push_back(&q);
  if (p.size() < 2) return;
  const std::string pre = body.name + ".";
  const Vec2 a = p[0]->pos, b = p[1]->pos;
  const double len = (b - a).norm();
  if (!(len > 0)) {  // no direction to measure from: each later point's own x and y
    for (size_t k = 1; k < p.size(); ++k)
      for (int c = 0; c < 2; ++c) {
        Dimension d = distance(pre + p[k]->name + (c ? ".y" : ".x"), p[k]->pos[c]);
        d.points.push_back({p[k]->id, c ? Vec2::UnitY() : Vec2::UnitX()});
        out.push_back(d);
      }
    return;
  }
  const Vec2 e = (b - a) / len;
  Dimension side = distance(pre + p[0]->name + "-" + p[1]->name, len);
  side.points.push_back({p[1]->id, e});
  const size_t sideAt = out.size();
  out.push_back(side);
  for (size_t k = 2; k < p.size(); ++k) {
    const Vec2 c = p[k]->pos;
    const double r0 = (c - a).norm(), r1 = (c - b).norm();
    const Vec2 u0 = (c - a) / r0, u1 = (c - b) / r1;
    if (measuredAlongAcross(a, b, c)) {
      Dimension along = distance(pre + p[k]->name + ".along", e.dot(c - a));
      along.points.push_back({p[k]->id, e});
      Dimension across = distance(pre + p[k]->name + ".across", cross(e, c - a));
      across.points.push_back({p[k]->id, perp(e)});
      out.push_back(along);
      out.push_back(across);
      continue;
    }
    out[sideAt].points.push_back({p[k]->id, placed(u0, u1, 0, 0, e)});
    Dimension d1 = distance(pre + p[1]->name + "-" + p[k]->name, r1);
    d1.points.push_back({p[k]->id, placed(u0, u1, 0, 1, Vec2::Zero())});
    Dimension d0 = distance(pre + p[0]->name + "-" + p[k]->name, r0);
    d0.points.push_back({p[k]->id, placed(u0, u1, 1, 0, Vec2::Zero())});
    out.push_back(d1);
    out.push_back(d0);
  }
}

void groundDimensions(const Mechanism& m, const Body& ground, std::vector<Dimension>& out) {
  for (const Point& q : m.points) {
    if (q.body != ground.id) continue;
    for (int c = 0; c < 2; ++c) {
      Dimension d = distance(ground.name + "." + q.name + (c ? ".y" : ".x"), q.pos[c]);
      d.points.push_back({q.id, c ? Vec2::UnitY() : Vec2::UnitX()});
      out.push_back(d);
    }
  }
}

// An arc slot's centre and radius (linkage/sensitivity.h), `from` its body's first point.
void arcDimensions(const Mechanism& m, const Slot& s, const Guide& g, const Vec2& from,
                   std::vector<Dimension>& out) {
  const std::string pre = m.slotLabel(s.id) + ".";
  for (int c = 0; c < 2; ++c) {
    const Vec2 e = c ? Vec2::UnitY() : Vec2::UnitX();
    Dimension d = distance(pre + (c ? "centre.y" : "centre.x"), g.centre[c] - from[c]);
    d.slots.push_back({s.id, e, e, 0, 0, e});
    out.push_back(d);
  }
  Dimension radius = distance(pre + "radius", g.radius);
  auto radial = [&](const Vec2& p) -> Vec2 { return (p - g.centre) / g.radius; };
  radius.slots.push_back({s.id, radial(s.p0), radial(s.p1), 0, 0, radial(*s.mid)});
  out.push_back(radius);
}

void slotDimensions(const Mechanism& m, const Slot& s, std::vector<Dimension>& out) {
  // In space the ground's slot is in the plane of its block, which its offset and angle keep
  // (an arc: its centre in the world and its radius); a moving body's is in its plane's
  // coordinates, as a planar machine's.
  if (m.body(s.body)->ground && isSpatial(m)) return internal::groundSlotInSpace(m, s, out);
  const std::optional<Guide> g = guideOf(s);
  if (!g) return;
  const std::string pre = m.slotLabel(s.id) + ".";
  // Measured from the body's first point (the ground's: the drawing's origin), so that the
  // body's lengths and its slot's offset scale together.
  Vec2 from = Vec2::Zero();
  if (!m.body(s.body)->ground)
    for (const Point& q : m.points)
      if (q.body == s.body) {
        from = q.pos;
        break;
      }
  if (s.arc()) return arcDimensions(m, s, *g, from, out);
  Dimension offset = distance(pre + "offset", g->normal.dot(s.p0 - from));
  offset.slots.push_back({s.id, g->normal, g->normal});
  Dimension angle =
      distance(pre + "angle", std::atan2(g->direction.y(), g->direction.x()) * 180 / M_PI);
  angle.unit = Dimension::Unit::Deg;
  angle.slots.push_back({s.id, Vec2::Zero(), perp(s.p1 - s.p0) * (M_PI / 180)});
  out.push_back(offset);
  out.push_back(angle);
}

// A cam's rises (each segment with a law that moves: a rise of 0 has no way to take the
// difference from) and its base (linkage/sensitivity.h). A cam not sound has none: its joint
// refuses to compile.
void camDimensions(const Mechanism& m, const Joint& j, std::vector<Dimension>& out) {
  const std::optional<CamJoint> c = camJoint(m, j);
  if (!c) return;
  const std::string pre = "cam:" + m.pointLabel(j.b) + ".";
  const std::vector<cam::Segment>& s = c->program.segments();
  for (size_t k = 0; k < s.size(); ++k) {
    const int o = s[k].law && s[k].rise != 0 ? risePartner(s, k, s[k].rise) : -1;
    if (o < 0) continue;
    Dimension d = distance(pre + "segment" + std::to_string(k + 1) + ".rise", s[k].rise);
    if (c->kind.oscillating) d.unit = Dimension::Unit::Deg;
    d.camOf = j.id;
    d.camRises.assign(s.size(), 0.0);
    d.camRises[k] = 1;
    d.camRises[o] = -1;
    out.push_back(d);
  }
  Dimension base = distance(pre + "base", c->kind.base);
  base.camOf = j.id;
  base.camBase = 1;
  out.push_back(base);
  if (c->kind.flat || c->kind.roller == 0) return;  // a flat face or a knife edge: no roller
  // The roller on the same cam: it reaches as far as the base (the pitch curve is their sum).
  Dimension roller = distance(pre + "roller", c->kind.roller);
  roller.camOf = j.id;
  roller.camBase = 1;
  roller.camRoller = true;
  out.push_back(roller);
}

}  // namespace

std::vector<Dimension> dimensions(const Mechanism& m) {
  std::vector<Dimension> out;
  for (const Body& b : m.bodies) {
    if (b.ground)
      groundDimensions(m, b, out);
    else
      bodyDimensions(m, b, out);
  }
  for (const Slot& s : m.slots) slotDimensions(m, s, out);
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Coupling) continue;
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b) continue;
    Dimension d =
        distance(m.body(a->body)->name + "-" + m.body(b->body)->name + ".ratio", gearRatio(j));
    d.unit = Dimension::Unit::Ratio;
    d.ratioOf = j.id;
    out.push_back(d);
  }
  for (const Joint& j : m.joints)
    if (std::string_view(kindOf(j).name) == "cam") camDimensions(m, j, out);
  if (internal::hasSpaceDimensions(m)) internal::spaceDimensions(m, out);
  return out;
}

}  // namespace linkage
