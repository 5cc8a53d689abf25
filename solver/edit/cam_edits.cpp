// Cam edits (linkage/cam_edits.h).
#include "linkage/cam_edits.h"

#include <cmath>

#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/geometry.h"
#include "linkage/guide.h"

namespace linkage {

namespace {

constexpr size_t kBase = 0, kRoller = 1, kFlat = 2;  // the cam's numbers (elements/cam.cpp)

bool refuse(std::string* why, std::string text) {
  if (why) *why = std::move(text);
  return false;
}

JointType camType() {
  return elementKindNamed("cam")->type;
}

// The point of `body` pinned to `other` (a revolute joint between them), or none.
PointId pinPoint(const Mechanism& m, BodyId body, BodyId other) {
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b) continue;
    if (a->body == body && b->body == other) return a->id;
    if (b->body == body && a->body == other) return b->id;
  }
  return {};
}

// The body b's body is guided by: the other side of its one slider or pin.
BodyId guideOf(const Mechanism& m, BodyId follower, std::string* why) {
  BodyId guide;
  int found = 0;
  for (const Joint& j : m.joints) {
    const Role role = kindOf(j).role;
    const Point* a = m.point(j.a);
    if (!a || (role != Role::Revolute && role != Role::Prismatic)) continue;
    const Point* b = role == Role::Revolute ? m.point(j.b) : nullptr;
    const Slot* s = role == Role::Prismatic ? m.slot(j.slot) : nullptr;
    const BodyId other = b ? b->body : s ? s->body : BodyId{};
    if (a->body != follower && other != follower) continue;
    ++found;
    guide = a->body == follower ? other : a->body;
  }
  if (found == 1) return guide;
  refuse(why, found == 0 ? "the body is neither a block in a slot nor pinned to a pivot"
                         : "the body has more than one pin or slider: a cam's follower is held "
                           "by one, to the body the cam turns on");
  return {};
}

Joint* camJointOf(Mechanism& m, JointId j, std::string* why) {
  Joint* k = m.joint(j);
  if (!k || k->type != camType()) refuse(why, "not a cam");
  return k && k->type == camType() ? k : nullptr;
}

// Every point, slot and mass of body b moved by T.
void moveBody(Mechanism& m, BodyId b, const Transform& T) {
  for (Point& p : m.points)
    if (p.body == b) p.pos = T * p.pos;
  for (Slot& s : m.slots)
    if (s.body == b) {
      s.p0 = T * s.p0;
      s.p1 = T * s.p1;
      if (s.mid) s.mid = T * *s.mid;
    }
  if (Body* body = m.body(b); body && body->mass) {
    body->mass->com = T * body->mass->com;
    for (PointMass& w : body->mass->counterweights) w.at = T * w.at;
  }
}

// The follower's move that puts b at `reach` from a: along the slot, or about the pivot
// (the smaller turn of the two); false where none does.
bool lowestMove(const CamJoint& c, double reach, Transform& T) {
  const cam::Place& d = c.drawn;
  if (!c.kind.oscillating) {
    const double e = c.offset, now = (d.b - d.pivot).dot(d.along);
    const double to = c.kind.flat ? reach : std::sqrt(reach * reach - e * e);
    if (!(std::abs(e) < reach) && !c.kind.flat) return false;
    T.t = (to - now) * d.along;
    return true;
  }
  // b turned about the pivot p by t onto the circle of `reach` about a: with k = p - a, q = b - p,
  // |k + R(t) q|^2 = reach^2 is A cos t + B sin t = C.
  const Vec2 q = d.b - d.pivot, k = d.pivot - d.centre;
  const double A = 2 * k.dot(q), B = 2 * cross(q, k),
               C = reach * reach - k.squaredNorm() - q.squaredNorm();
  const double r = std::hypot(A, B);
  if (!(r > 0) || std::abs(C) > r) return false;
  const double mid = std::atan2(B, A), half = std::acos(C / r);
  double t = std::remainder(mid + half, 2 * M_PI);
  if (const double u = std::remainder(mid - half, 2 * M_PI); std::abs(u) < std::abs(t)) t = u;
  T.R = Rot::of(t);
  T.t = d.pivot - T.R * d.pivot;
  return true;
}

}  // namespace

std::vector<BodyId> camBodiesFor(const Mechanism& m, PointId b, std::string* why) {
  const Point* p = m.point(b);
  if (!p) return refuse(why, "unknown point"), std::vector<BodyId>{};
  const BodyId guide = guideOf(m, p->body, why);
  if (!guide) return {};
  std::vector<BodyId> out;
  for (const Body& body : m.bodies)
    if (body.id != p->body && body.id != guide && pinPoint(m, body.id, guide))
      out.push_back(body.id);
  if (out.empty())
    refuse(why, "no body is pinned to the follower's guide \"" + m.body(guide)->name +
                    "\" to carry a cam");
  return out;
}

std::vector<Record> camMotionRecords(std::span<const cam::Segment> segments, bool oscillating) {
  std::vector<Record> out;
  for (const cam::Segment& s : segments) {
    Record r{{"to_deg", s.toDeg}};
    if (s.law) {
      r.push_back({oscillating ? "rise_deg" : "rise_mm", s.rise});
      r.push_back({"law", std::string(cam::lawName(*s.law))});
    }
    out.push_back(std::move(r));
  }
  return out;
}

JointId addCam(Mechanism& m, PointId b, BodyId cam, bool flat, std::string* why) {
  const Point* p = m.point(b);
  if (!p) return refuse(why, "unknown point"), JointId{};
  for (const Joint& j : m.joints)
    if (j.type == camType() && m.point(j.b) && m.point(j.b)->body == p->body)
      return refuse(why, "the follower has a cam already"), JointId{};
  const BodyId guide = guideOf(m, p->body, why);
  if (!guide) return {};
  const PointId a = pinPoint(m, cam, guide);
  if (!a || cam == p->body)
    return refuse(why, "the cam's body is not pinned to the follower's guide"), JointId{};
  Mechanism trial = m;
  Joint j;
  j.type = camType();
  j.a = a;
  j.b = b;
  j.numbers = {1.0, flat ? NAN : 0.0, flat ? 1.0 : 0.0};
  const cam::Segment first[] = {
      {120, 1, cam::Law::Cycloidal}, {180, 0, {}}, {300, -1, cam::Law::Cycloidal}, {360, 0, {}}};
  j.records = {{Record{{"to_deg", 360.0}}}};  // a dwell all round: read as either follower
  const JointId id = trial.addJoint(j);
  std::string where, w;
  std::optional<CamJoint> c = camJointAsDrawn(trial, *trial.joint(id), &w, &where);
  if (!c) return refuse(why, w + " (" + where + ")"), JointId{};
  // The pitch circle through b: base + roller its radius (a flat face: base the distance).
  const double reach =
      c->kind.oscillating ? (c->drawn.b - c->drawn.centre).norm()
      : flat              ? (c->drawn.b - c->drawn.pivot).dot(c->drawn.along)
             : std::hypot((c->drawn.b - c->drawn.pivot).dot(c->drawn.along), c->offset);
  const double roller = flat ? 0.0 : reach / 4;
  Joint& made = *trial.joint(id);
  made.numbers[kBase] = reach - roller;
  if (!flat) made.numbers[kRoller] = roller;
  const double rise =
      c->kind.oscillating ? 10.0 : std::max(1.0, std::round(made.numbers[kBase] / 4));
  cam::Segment sized[std::size(first)];
  for (size_t k = 0; k < std::size(first); ++k)
    sized[k] = {first[k].toDeg, first[k].rise * rise, first[k].law};
  made.records = {camMotionRecords(sized, c->kind.oscillating)};
  if (!camJoint(trial, made, &w, &where)) return refuse(why, w + " (" + where + ")"), JointId{};
  m = std::move(trial);
  return id;
}

bool setCamMotion(Mechanism& m, JointId j, std::span<const cam::Segment> segments,
                  std::string* why) {
  Joint* k = camJointOf(m, j, why);
  if (!k) return false;
  std::string where, w;
  const std::optional<CamJoint> c = camJointAsDrawn(m, *k, &w, &where);
  if (!c) return refuse(why, where + ": " + w);
  Joint next = *k;
  next.records = {camMotionRecords(segments, c->kind.oscillating)};
  if (!camJointAsDrawn(m, next, &w, &where)) return refuse(why, where + ": " + w);
  *k = std::move(next);
  return true;
}

namespace {

// Where b should be moved by T for `to` to be where `from` is, when they are apart.
bool apart(const Vec2& from, const Vec2& to, Transform& T) {
  T = Transform{};
  T.t = from - to;
  return T.t.norm() > 1e-12 * std::max(1.0, from.cwiseAbs().maxCoeff());
}

// The cam's body onto the guide's pin at a; the follower onto its pivot (oscillating) or b onto
// its slot's line (translating): rigid translations.
void ontoSupports(Mechanism& m, const Joint& k, const CamJoint& c) {
  Transform T;
  const Point& a = *m.point(k.a);
  for (const Joint& p : m.joints) {
    if (kindOf(p).role != Role::Revolute) continue;
    const Point *x = m.point(p.a), *y = m.point(p.b);
    if (!x || !y || (x->id != a.id && y->id != a.id)) continue;
    const Point* other = x->id == a.id ? y : x;
    if (other->body == c.guide && apart(other->pos, a.pos, T)) moveBody(m, c.cam, T);
  }
  const Joint& f = *m.joint(c.followerJoint);
  if (c.kind.oscillating) {
    const Point *x = m.point(f.a), *y = m.point(f.b);
    const bool xOn = x->body == c.follower;
    if (apart((xOn ? y : x)->pos, (xOn ? x : y)->pos, T)) moveBody(m, c.follower, T);
    return;
  }
  const std::optional<Guide> g = guideOf(*m.slot(f.slot));
  const Vec2 b = m.point(k.b)->pos;
  if (g && apart(b - g->normal * g->normal.dot(b - g->p0), b, T)) moveBody(m, c.follower, T);
}

}  // namespace

bool replaceCam(Mechanism& m, JointId j, std::string* why) {
  Joint* k = camJointOf(m, j, why);
  if (!k) return false;
  std::string where, w;
  std::optional<CamJoint> c = camJointAsDrawn(m, *k, &w, &where);
  if (!c) return refuse(why, where + ": " + w);
  Mechanism trial = m;
  ontoSupports(trial, *k, *c);
  const Joint& moved = *trial.joint(j);
  if (!camJoint(trial, moved) && !setCamBase(trial, j, c->kind.base, why)) return false;
  m = std::move(trial);
  return true;
}

int risePartner(std::span<const cam::Segment> s, size_t k, double way) {
  for (size_t i = 1; i < s.size(); ++i) {
    const size_t o = (k + i) % s.size();
    if (s[o].law && s[o].rise * way < 0) return static_cast<int>(o);
  }
  return -1;
}

bool withCamRise(std::vector<cam::Segment>& s, size_t k, double rise) {
  if (k >= s.size()) return false;
  const double delta = rise - s[k].rise;
  if (delta == 0) return true;
  const int o = risePartner(s, k, rise != 0 ? rise : s[k].rise);
  if (o < 0) return false;
  s[k].rise = rise;
  s[o].rise -= delta;
  return true;
}

bool setCamBase(Mechanism& m, JointId j, double baseMm, std::string* why) {
  Joint* k = camJointOf(m, j, why);
  if (!k) return false;
  if (!(baseMm > 0) || !std::isfinite(baseMm))
    return refuse(why, "the base circle's radius is a number above 0");
  std::string where, w;
  const std::optional<CamJoint> c = camJointAsDrawn(m, *k, &w, &where);
  if (!c) return refuse(why, where + ": " + w);
  Transform T;
  if (!lowestMove(*c, baseMm + c->kind.roller, T))
    return refuse(why, c->kind.oscillating
                           ? "the follower's arm cannot reach a base circle of that radius"
                           : "the slot's line misses a base circle of that radius");
  Mechanism trial = m;
  trial.joint(j)->numbers[kBase] = baseMm;
  moveBody(trial, c->follower, T);
  if (!camJoint(trial, *trial.joint(j), &w, &where)) return refuse(why, where + ": " + w);
  m = std::move(trial);
  return true;
}

bool setCamRoller(Mechanism& m, JointId j, double rollerMm, std::string* why) {
  Joint* k = camJointOf(m, j, why);
  if (!k) return false;
  if (k->number(kFlat) != 0) return refuse(why, "a flat face has no roller");
  const double reach = k->number(kBase) + k->number(kRoller);
  if (!(rollerMm >= 0) || !(rollerMm < reach))
    return refuse(why,
                  "the roller's radius is 0 (a knife edge) or more, and less than base + roller");
  k->numbers[kBase] = reach - rollerMm;
  k->numbers[kRoller] = rollerMm;
  return true;
}

}  // namespace linkage
