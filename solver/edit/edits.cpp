#include "linkage/edits.h"

#include <algorithm>
#include <cmath>

#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/space.h"

namespace linkage {

namespace {

void fail(std::string* why, const std::string& text) {
  if (why) *why = text;
}

// Spreadsheet-style letters: A..Z, AA, AB, ...
std::string letters(int n) {
  std::string s;
  for (++n; n > 0; n = (n - 1) / 26) s.insert(s.begin(), char('A' + (n - 1) % 26));
  return s;
}

bool pointNameUsed(const Mechanism& m, const std::string& name) {
  return std::any_of(m.points.begin(), m.points.end(),
                     [&](const Point& p) { return p.name == name; });
}

}  // namespace

bool bodyNameFree(const Mechanism& m, const std::string& name, BodyId self) {
  if (name.empty()) return false;
  const Body* b = m.bodyNamed(name);
  return !b || b->id == self;
}

bool pointNameFree(const Mechanism& m, BodyId body, const std::string& name, PointId self) {
  if (name.empty() || name.find('.') != std::string::npos) return false;
  const Point* p = m.pointNamed(body, name);
  return !p || p->id == self;
}

bool slotNameFree(const Mechanism& m, BodyId body, const std::string& name, SlotId self) {
  if (name.empty() || name.find('.') != std::string::npos) return false;
  const Slot* s = m.slotNamed(body, name);
  return !s || s->id == self;
}

std::string newBodyName(const Mechanism& m, const std::string& stem) {
  // link2, link3, ...: the textbook numbers the ground 1.
  for (int n = static_cast<int>(m.bodies.size()) + 1;; ++n) {
    const std::string name = stem + std::to_string(n);
    if (bodyNameFree(m, name)) return name;
  }
}

std::string newPointName(const Mechanism& m, BodyId body) {
  // A letter no point of the mechanism has: a new place in the drawing.
  for (int n = 0;; ++n) {
    const std::string name = letters(n);
    if (!pointNameUsed(m, name) && pointNameFree(m, body, name)) return name;
  }
}

std::string newSlotName(const Mechanism& m, BodyId body) {
  for (int n = 1;; ++n) {
    // Built in two steps: "s" + to_string(n) trips GCC 12's -Wrestrict (a false alarm, bug 105329).
    std::string name = "s";
    name += std::to_string(n);
    if (slotNameFree(m, body, name)) return name;
  }
}

BodyId addLink(Mechanism& m, const std::vector<LinkVertex>& vertices, std::string* why,
               const std::string& plane) {
  if (vertices.size() < 2) {
    fail(why, "a link needs two points at least");
    return {};
  }
  if (!planeNamed(m, plane)) {
    fail(why, "there is no plane \"" + plane + "\" to draw the link in");
    return {};
  }
  for (const LinkVertex& v : vertices)
    if (v.pinTo && !m.contains(v.pinTo)) {
      fail(why, "a point it is pinned to is gone");
      return {};
    }
  const BodyId b = m.addBody(newBodyName(m));
  // The drawing plane is written as no plane at all: a planar file stays as it was.
  if (!plane.empty() && plane != "drawing") m.body(b)->plane = plane;
  for (const LinkVertex& v : vertices) {
    if (v.pinTo) {
      const Point target = *m.point(v.pinTo);
      // The pin's two points share the name (textbook: one letter, one place), when free.
      const std::string name = pointNameFree(m, b, target.name) ? target.name : newPointName(m, b);
      const PointId p = m.addPoint(b, name, v.at);
      m.addPin(v.pinTo, p);
    } else {
      m.addPoint(b, newPointName(m, b), v.at);
    }
  }
  return b;
}

PointId addGroundPoint(Mechanism& m, const Vec2& at, PointId point, const std::string& plane) {
  const Body* g = m.ground();
  const Plane* pl = planeNamed(m, plane);
  if (!g || !pl) return {};
  const BodyId ground = g->id;
  std::string name = newPointName(m, ground);
  if (const Point* p = m.point(point); p && pointNameFree(m, ground, p->name)) name = p->name;
  const bool drawing = plane.empty() || plane == "drawing";
  const Vec3 w = pl->world(at);
  const PointId gp = m.addPoint(ground, name, drawing ? at : Vec2(w.x(), w.y()));
  if (!drawing) m.point(gp)->third = w.z();
  if (point) m.addPin(gp, point);
  return gp;
}

PointId addBodyPoint(Mechanism& m, BodyId body, const Vec2& at) {
  if (!m.contains(body)) return {};
  return m.addPoint(body, newPointName(m, body), at);
}

SlotId addBodySlot(Mechanism& m, BodyId body, const Vec2& p0, const Vec2& p1) {
  if (!m.contains(body) || p0 == p1) return {};
  return m.addSlot(body, newSlotName(m, body), p0, p1);
}

SlotId addBodyArcSlot(Mechanism& m, BodyId body, const Vec2& p0, const Vec2& mid, const Vec2& p1) {
  if (!m.contains(body)) return {};
  Slot probe{{}, body, "", p0, p1, mid, {}};
  if (!guideOf(probe)) return {};
  return m.addArcSlot(body, newSlotName(m, body), p0, mid, p1);
}

bool bendSlot(Mechanism& m, SlotId id, std::string* why) {
  Slot* s = m.slot(id);
  if (!s || s->arc()) return s != nullptr;
  Slot bent = *s;
  bent.mid = (s->p0 + s->p1) / 2 + perp(s->p1 - s->p0) / 4;  // in the drawing: n = z
  if (s->z.size() == 2) {
    const std::vector<Vec3> w = slotInWorld(*s);
    Vec3 n = Vec3::UnitZ();
    for (const Joint& j : m.joints)
      if (const Point* a = j.slot == id ? m.point(j.a) : nullptr) {
        const PlaneClasses pc = planeClasses(m);
        n = pc.frames[jointClass(m, pc, *a, *s)].normal();
        break;
      }
    const Vec3 mid = (w[0] + w[1]) / 2 + n.cross(w[1] - w[0]) / 4;
    bent.mid = mid.head<2>();
    bent.z = {w[0].z(), mid.z(), w[1].z()};
  }
  if (!soundSlot(bent, why)) return false;
  *s = bent;
  return true;
}

void straightenSlot(Mechanism& m, SlotId id) {
  Slot* s = m.slot(id);
  if (!s || !s->arc()) return;
  if (s->z.size() == 3) s->z.erase(s->z.begin() + 1);
  s->mid.reset();
}

namespace {

// The point of `body` where a pin joins it to `carrier`, or none.
PointId pivotOn(const Mechanism& m, BodyId body, BodyId carrier) {
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b) continue;
    if (a->body == body && b->body == carrier) return a->id;
    if (b->body == body && a->body == carrier) return b->id;
  }
  return {};
}

}  // namespace

std::vector<BodyId> pivotsOf(const Mechanism& m, BodyId body) {
  std::vector<BodyId> out;
  const Body* g = m.ground();
  if (g && pivotOn(m, body, g->id)) out.push_back(g->id);
  for (const Body& c : m.bodies)
    if (c.id != body && !c.ground && pivotOn(m, body, c.id)) out.push_back(c.id);
  return out;
}

JointId addCoupling(Mechanism& m, BodyId a, BodyId b, double ratio, std::string* why) {
  if (!m.contains(a) || !m.contains(b) || a == b) {
    fail(why, "pick two different bodies, each pivoted where it turns");
    return {};
  }
  const std::vector<BodyId> carriers = pivotsOf(m, a);
  for (BodyId c : carriers) {
    if (c == b) continue;
    const PointId pb = pivotOn(m, b, c);
    if (!pb) continue;
    const Body* cb = m.body(c);
    const JointId id = m.addGear(pivotOn(m, a, c), pb, ratio, cb->ground ? BodyId{} : c);
    if (const std::string problem = checkJoints(m); !problem.empty()) {
      m.remove(id);
      fail(why, problem);
      return {};
    }
    return id;
  }
  fail(why,
       "the two bodies are not pivoted on one body: a gear or belt couples two bodies that "
       "turn about pins on the same carrier (the frame, or an arm)");
  return {};
}

namespace {

// A point and a slot of two different bodies: what runs in a slot and the slot it runs in.
bool pointAndSlot(const Mechanism& m, PointId point, SlotId slot, std::string* why) {
  const Point* p = m.point(point);
  const Slot* s = m.slot(slot);
  if (!p || !s) {
    fail(why, "pick a point, then a slot");
    return false;
  }
  if (p->body == s->body) {
    fail(why, "the point and the slot are on the same body: it could not move in it");
    return false;
  }
  return true;
}

}  // namespace

BodyId addBlock(Mechanism& m, PointId point, SlotId slot, const Vec2& at, std::string* why) {
  if (!pointAndSlot(m, point, slot, why)) return {};
  const std::string name = m.point(point)->name;
  const BodyId block = m.addBody(newBodyName(m, "block"));
  const Body* guide = m.body(m.slot(slot)->body);
  m.body(block)->plane = guide->ground ? m.body(m.point(point)->body)->plane : guide->plane;
  const PointId bp = m.addPoint(block, name, at);
  m.addPin(point, bp);
  m.addSlider(bp, slot);
  return block;
}

JointId addPinInSlot(Mechanism& m, PointId point, SlotId slot, std::string* why) {
  if (!pointAndSlot(m, point, slot, why)) return {};
  return m.addPinInSlot(point, slot);
}

bool setDriver(Mechanism& m, JointId pin, std::string* why) {
  Joint* j = m.joint(pin);
  if (!j || kindOf(*j).role != Role::Revolute) {
    fail(why, "the driver is a pin joint: pick a pin");
    return false;
  }
  const Point* a = m.point(j->a);
  const Point* b = m.point(j->b);
  const Body* ba = a ? m.body(a->body) : nullptr;
  const Body* bb = b ? m.body(b->body) : nullptr;
  // The body of b turns relative to the body of a: the frame on the a side.
  if (bb && bb->ground && !(ba && ba->ground)) std::swap(j->a, j->b);
  Driver d;
  if (m.driver) d = *m.driver;
  d.joint = pin;
  m.driver = d;
  return true;
}

std::string newPlaneName(const Mechanism& m) {
  for (int n = 2;; ++n) {
    std::string name = "plane";
    name += std::to_string(n);
    if (!planeNamed(m, name)) return name;
  }
}

bool addPlane(Mechanism& m, const Plane& p, std::string* why) {
  if (planeNamed(m, p.name) && !p.name.empty()) {
    fail(why, "a plane is named \"" + p.name + "\" already");
    return false;
  }
  Mechanism next = m;
  if (!next.planes) next.planes.emplace();
  next.planes->push_back(p);
  // The file's own check, so that nothing is added that a file could not hold.
  if (const std::string problem = planesProblem(next); !problem.empty()) {
    fail(why, problem);
    return false;
  }
  m = std::move(next);
  return true;
}

Plane planeInclinedAboutX(const std::string& name, const Vec3& origin, double rhoDeg) {
  const double r = rhoDeg * M_PI / 180;
  Plane p;
  p.name = name;
  p.origin = origin;
  p.xAxis = Vec3::UnitX();
  p.yAxis = Vec3(0, std::cos(r), std::sin(r));
  return p;
}

namespace {
// The moving body turning on ground point `pivot`, or nullptr.
const Body* turningOn(const Mechanism& m, PointId pivot) {
  const Point* g = m.point(pivot);
  if (!g || !m.body(g->body) || !m.body(g->body)->ground) return nullptr;
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute || (j.a != pivot && j.b != pivot)) continue;
    const Point* other = m.point(j.a == pivot ? j.b : j.a);
    if (const Body* b = other ? m.body(other->body) : nullptr; b && !b->ground) return b;
  }
  return nullptr;
}
}  // namespace

std::vector<PointId> shafts(const Mechanism& m) {
  std::vector<PointId> out;
  for (const Point& p : m.points)
    if (turningOn(m, p.id)) out.push_back(p.id);
  return out;
}

std::optional<Plane> planeOnShaft(const Mechanism& m, const std::string& name, PointId pivot,
                                  double along) {
  const Body* b = turningOn(m, pivot);
  if (!b) return std::nullopt;
  Plane p = planeOf(m, b->id);
  p.name = name;
  p.extras = {};
  p.origin = worldOf(m, *m.point(pivot)) + along * p.normal();
  return p;
}

JointId addBallRod(Mechanism& m, PointId a, PointId b, std::string* why) {
  const Point* pa = m.point(a);
  const Point* pb = m.point(b);
  if (!pa || !pb || a == b) {
    fail(why, "pick two points, one at each end of the rod");
    return {};
  }
  // Both on the ground is this case too: the ground is one body.
  if (pa->body == pb->body) {
    fail(why, "both ends are on one body: a rod joins two bodies");
    return {};
  }
  if ((worldOf(m, *pa) - worldOf(m, *pb)).norm() < 1e-9) {
    fail(why, "the two points are drawn at one place: a rod of no length");
    return {};
  }
  Joint j;
  j.type = elementKindNamed("ball-rod")->type;
  j.a = a;
  j.b = b;
  return m.addJoint(j);
}

void toggleOutput(Mechanism& m, PointId p) {
  auto it = std::find(m.outputs.begin(), m.outputs.end(), p);
  if (it != m.outputs.end())
    m.outputs.erase(it);
  else if (m.contains(p))
    m.outputs.push_back(p);
}

bool changeJointType(Mechanism& m, JointId id, JointType type, std::string* why) {
  Joint* j = m.joint(id);
  if (!j) return false;
  if (!sameFields(j->type, type)) {
    fail(why, std::string("a ") + toString(j->type) + " cannot become a " + toString(type) +
                  ": they join different things (a slider and a pin-in-slot change into each "
                  "other; a pin needs a slot first)");
    return false;
  }
  j->type = type;
  return true;
}

std::vector<PointId> pinnedTogether(const Mechanism& m, PointId p) {
  std::vector<PointId> out;
  if (!m.contains(p)) return out;
  out.push_back(p);
  for (size_t i = 0; i < out.size(); ++i)
    for (const Joint& j : m.joints) {
      if (kindOf(j).role != Role::Revolute) continue;
      PointId other;
      if (j.a == out[i]) other = j.b;
      if (j.b == out[i]) other = j.a;
      if (other && std::find(out.begin(), out.end(), other) == out.end()) out.push_back(other);
    }
  return out;
}

namespace {

std::vector<PointId> pointsOf(const Mechanism& m, BodyId body) {
  std::vector<PointId> out;
  for (const Point& p : m.points)
    if (p.body == body) out.push_back(p.id);
  return out;
}

void moveTogether(Mechanism& m, PointId p, const Vec2& to) {
  for (PointId q : pinnedTogether(m, p)) m.point(q)->pos = to;
}

bool refuse(std::string* why, const std::string& text) {
  if (why) *why = text;
  return false;
}

}  // namespace

std::vector<double> sideLengths(const Mechanism& m, BodyId body) {
  const std::vector<PointId> p = pointsOf(m, body);
  auto d = [&](int i, int j) { return (m.point(p[j])->pos - m.point(p[i])->pos).norm(); };
  if (p.size() == 2) return {d(0, 1)};
  if (p.size() == 3) return {d(0, 1), d(1, 2), d(0, 2)};
  return {};
}

bool setSideLengths(Mechanism& m, BodyId body, const std::vector<double>& lengths,
                    std::string* why) {
  const std::vector<PointId> p = pointsOf(m, body);
  // A bar has one side, a triangle three.
  if ((p.size() != 2 || lengths.size() != 1) && (p.size() != 3 || lengths.size() != 3))
    return refuse(why, "side lengths are typed for a bar or a triangle");
  for (double l : lengths)
    if (!(l > 0 && std::isfinite(l))) return refuse(why, "a length must be positive");
  const Vec2 a = m.point(p[0])->pos, b = m.point(p[1])->pos;
  const Vec2 dir = (b - a).norm() > 0 ? Vec2((b - a).normalized()) : Vec2(1, 0);
  const Vec2 b1 = a + lengths[0] * dir;
  if (p.size() == 2) {
    moveTogether(m, p[1], b1);
    return true;
  }
  // The third point where the circles about P0 (radius |P0P2|) and P1 (|P1P2|) meet, on the
  // side of P0P1 it was drawn on.
  const double c = lengths[0], r1 = lengths[1], r0 = lengths[2];
  if (r0 + r1 <= c || c + r0 <= r1 || c + r1 <= r0)
    return refuse(why, "these sides make no triangle: each must be shorter than the other two");
  const double along = (c * c + r0 * r0 - r1 * r1) / (2 * c);
  const double off = std::sqrt(std::max(0.0, r0 * r0 - along * along));
  const Vec2 c0 = m.point(p[2])->pos - a;
  const double side = dir.x() * c0.y() - dir.y() * c0.x() < 0 ? -1 : 1;
  const Vec2 third = a + along * dir + side * off * Vec2(-dir.y(), dir.x());
  moveTogether(m, p[1], b1);
  moveTogether(m, p[2], third);
  return true;
}

bool setPolar(Mechanism& m, PointId p, PointId from, double distance, double angleDeg,
              std::string* why) {
  if (!m.contains(p) || !m.contains(from) || p == from)
    return refuse(why, "pick another point to measure from");
  if (!(distance > 0 && std::isfinite(distance))) return refuse(why, "a distance must be positive");
  if (!std::isfinite(angleDeg)) return refuse(why, "the angle must be a number");
  const double a = angleDeg * M_PI / 180;
  Vec2 u(std::cos(a), std::sin(a));
  // A quarter turn exactly (0, 90, 180...): cos 90 deg is 6e-17, not 0.
  if (std::remainder(angleDeg, 90.0) == 0) u = Vec2(std::round(u.x()), std::round(u.y()));
  moveTogether(m, p, m.point(from)->pos + distance * u);
  return true;
}

}  // namespace linkage
