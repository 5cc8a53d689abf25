// Cam: the cam's body (of a, its centre, where it is pinned to the guiding body) moves the
// follower (the body of b) by a motion programme s(theta) (linkage/cam.h), the follower guided by
// its own joint to that body: a slider in a straight slot (translating) or a pin (oscillating).
//
//   file:     {"type": "cam", "a": "cam.O", "b": "follower.R", "base_mm": 30, "roller_mm": 8,
//              "motion": [{"to_deg": 90, "rise_mm": 10, "law": "cycloidal"}, {"to_deg": 150},
//                         {"to_deg": 270, "rise_mm": -10, "law": "polynomial-345"},
//                         {"to_deg": 360}]}
//             "flat": true in place of roller_mm, roller_mm 0 a knife edge; rise_deg for an
//             oscillating follower (../shared/specs/model-format.md, "Cams")
//   rows:     Cam(follower, cam, guide): the follower's displacement from the drawing (mm along
//             the slot away from the cam, or its turn relative to the guide in radians) minus
//             s(theta), theta the cam's turn relative to the guide, counter-clockwise
//                                                                    1 equation (cam_row.h)
//   checks:   base > 0; a roller of 0 or more, or a flat face, not both; a where the cam is
//             pinned to the guide, and the follower's one joint to it a slider in a straight
//             slot or a pin; the programme (linkage/cam.h); the drawing its lowest position:
//             translating, b on the slot's line at sqrt((base + roller)^2 - e^2) from the foot
//             F of the perpendicular from a (a flat face: at base from F), to 1e-6 mm;
//             oscillating, b at base + roller from a (a flat face: base), to 1e-6 mm
//   forces:   along the common normal at the contact (cam_row.h): the reaction on the cam, its
//             moment about a, and the contact force (compression positive)
//   centre:   on the common normal (a PoseLine): Kennedy meets it with the line of the cam's
//             and the follower's pivots
//   drawn:    the cam's base circle about a and the follower's roller (or face) at b
#include "elements/cam.h"

#include <cmath>

#include "elements/cam_row.h"
#include "elements/frames.h"
#include "linkage/cam_geometry.h"
#include "linkage/guide.h"

namespace linkage {

namespace {

constexpr const char* kForceColumns[] = {"fx_N", "fy_N", "m_Nm", "contact_N"};

constexpr FieldSpec kFields[] = {
    {"a", FieldType::Point, 0, true},        {"b", FieldType::Point, 1, true},
    {"base_mm", FieldType::Number, 0, true}, {"roller_mm", FieldType::Number, 1, false},
    {"flat", FieldType::Flag, 2, false},     {"motion", FieldType::Records, 0, true}};

constexpr double kDrawn = 1e-6;  // mm: how closely the drawing must be the lowest position

std::string quoted(const std::string& s) {
  std::string q = "\"";
  q += s;
  q += '"';
  return q;
}

std::string mm(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

struct Fault {
  std::string where, why;
};

// The body p's body is pinned to at p (a revolute joint at p or at its place), or none.
BodyId pinnedAt(const Mechanism& m, const Point& p, BodyId besides) {
  const double tol = 1e-9 * std::max(1.0, p.pos.cwiseAbs().maxCoeff());
  for (const Joint& k : m.joints) {
    if (kindOf(k).role != Role::Revolute) continue;
    const Point *x = m.point(k.a), *y = m.point(k.b);
    if (!x || !y) continue;
    for (const auto& [on, other] : {std::pair{x, y}, std::pair{y, x}})
      if (on->body == p.body && other->body != besides &&
          (on->id == p.id || (on->pos - p.pos).norm() <= tol))
        return other->body;
  }
  return {};
}

// The follower's joint to the guide: its kind and place filled in c, or a fault.
std::optional<Fault> followerJoint(const Mechanism& m, CamJoint& c) {
  int found = 0;
  for (const Joint& k : m.joints) {
    const Role role = kindOf(k).role;
    const Point* a = m.point(k.a);
    if (!a || (role != Role::Revolute && role != Role::Prismatic)) continue;
    const Point* b = role == Role::Revolute ? m.point(k.b) : nullptr;
    const Slot* s = role == Role::Prismatic ? m.slot(k.slot) : nullptr;
    const BodyId other = b ? b->body : s ? s->body : BodyId{};
    if (!((a->body == c.follower && other == c.guide) ||
          (a->body == c.guide && other == c.follower)))
      continue;
    ++found;
    c.followerJoint = k.id;
    c.kind.oscillating = role == Role::Revolute;
    if (c.kind.oscillating) {
      c.drawn.pivot = a->pos;
      continue;
    }
    const std::optional<Guide> g = guideOf(*s);
    if (!g || g->arc)
      return Fault{"b",
                   "the follower's slider runs in an arc slot: a translating follower "
                   "runs in a straight one"};
    c.drawn.along = g->direction;
    c.drawn.pivot = g->p0;  // a point of the slot's line
  }
  const std::string names = quoted(m.body(c.follower)->name) + " and " +
                            quoted(m.body(c.guide)->name) + " (the body the cam turns on)";
  if (found == 0)
    return Fault{"b", "no slider and no pin joins the follower's body and its guide, " + names +
                          ": a follower is a block in a straight slot or a body pinned to its "
                          "pivot"};
  if (found > 1)
    return Fault{"b", "more than one joint joins " + names +
                          ": the follower's own joint to its "
                          "guide is one slider or one pin"};
  return std::nullopt;
}

// The motion records as segments (rises in the file's unit), or a fault naming the record.
std::optional<Fault> segments(const Joint& j, bool oscillating, std::vector<cam::Segment>& out) {
  const char* unit = oscillating ? "rise_deg" : "rise_mm";
  const char* other = oscillating ? "rise_mm" : "rise_deg";
  const std::vector<Record>& records = j.recordsAt(0);
  for (size_t k = 0; k < records.size(); ++k) {
    const std::string at = "motion[" + std::to_string(k) + "]";
    const Record& r = records[k];
    cam::Segment s;
    auto number = [&](const char* key, double& v) -> std::optional<Fault> {
      const RecordMember* x = recordMember(r, key);
      if (!x) return std::nullopt;
      if (const double* d = std::get_if<double>(&x->value)) {
        v = *d;
        return std::nullopt;
      }
      return Fault{at + "." + key,
                   "expected a number, got " + quoted(std::get<std::string>(x->value))};
    };
    if (!recordMember(r, "to_deg")) return Fault{at, "missing required field \"to_deg\""};
    if (auto f = number("to_deg", s.toDeg)) return f;
    if (recordMember(r, other))
      return Fault{at + "." + other, oscillating ? "an oscillating follower rises in degrees: "
                                                   "\"rise_deg\""
                                                 : "a translating follower rises in mm: "
                                                   "\"rise_mm\""};
    if (auto f = number(unit, s.rise)) return f;
    if (const RecordMember* law = recordMember(r, "law")) {
      const std::string* name = std::get_if<std::string>(&law->value);
      if (!name) return Fault{at + ".law", "expected the name of a law: " + cam::lawNames()};
      s.law = cam::lawNamed(*name);
      if (!s.law)
        return Fault{at + ".law", "unknown law " + quoted(*name) + ": " + cam::lawNames()};
    }
    out.push_back(s);
  }
  int bad = -1;
  const char* key = "";
  const std::string why = cam::checkProgram(out, bad, key);
  if (why.empty()) return std::nullopt;
  if (bad < 0) return Fault{"motion", why};
  const char* field = std::string_view(key) == "rise" ? unit : key;
  return Fault{"motion[" + std::to_string(bad) + "]." + field, why};
}

// The drawing oriented (the spec's rules): a translating follower's rise direction u away from
// the foot F of the perpendicular from a to the slot, towards b, and its offset; an oscillating
// one's sign (+1 when turning counter-clockwise moves b away from a) and flat face.
std::optional<Fault> orient(CamJoint& c) {
  cam::Place& d = c.drawn;
  if (c.kind.oscillating) {
    if (c.kind.flat) d.face = (d.b - d.centre).normalized();
    const double turn = cross(d.b - d.pivot, d.b - d.centre);
    if (!(std::abs(turn) > 1e-9 * (d.b - d.pivot).norm() * (d.b - d.centre).norm()))
      return Fault{"b",
                   "the follower's arm from its pivot points at the cam's centre: turning "
                   "it would not move b away from a"};
    c.kind.sign = turn > 0 ? 1 : -1;
    return std::nullopt;
  }
  const Vec2 line = d.along;
  const Vec2 foot = d.pivot + (d.centre - d.pivot).dot(line) * line;
  const double along = (d.b - foot).dot(line);
  if (along == 0) return Fault{"b", "b is at the foot of the perpendicular from a to the slot"};
  d.along = along > 0 ? line : Vec2(-line);
  d.pivot = foot;  // a point of the slot's line: the foot, where the sizes are measured from
  const Vec2 w(d.along.y(), -d.along.x());
  c.offset = (d.b - d.centre).dot(w);
  return std::nullopt;
}

// The drawing is the follower's lowest position (the spec's rules).
std::optional<Fault> lowest(const CamJoint& c) {
  const cam::Place& d = c.drawn;
  const double reach = c.kind.base + c.kind.roller;
  if (c.kind.oscillating) {
    const double r = (d.b - d.centre).norm();
    if (std::abs(r - reach) > kDrawn)
      return Fault{"b", "b is " + mm(r) + " mm from a, not base + roller = " + mm(reach) +
                            " mm: the drawing is the follower's lowest position, on the base "
                            "circle"};
    return std::nullopt;
  }
  double distance = c.kind.base;
  if (!c.kind.flat) {
    if (!(std::abs(c.offset) < reach))
      return Fault{"b", "the offset " + mm(c.offset) + " mm is not less than base + roller = " +
                            mm(reach) + " mm: the slot's line misses the base circle"};
    distance = std::sqrt(reach * reach - c.offset * c.offset);
  }
  const double off = (d.b - (d.pivot + distance * d.along)).norm();
  if (off > kDrawn)
    return Fault{"b", "b is " + mm(off) + " mm from where the follower touches the base circle" +
                          " (on the slot's line, " + mm(distance) +
                          " mm from the foot of the perpendicular from a): the drawing is the "
                          "follower's lowest position"};
  return std::nullopt;
}

std::optional<Fault> sizes(const Joint& j, cam::Follower& f) {
  f.base = j.number(0);
  if (!(f.base > 0) || !std::isfinite(f.base))
    return Fault{"base_mm", "expected the base circle's radius, a number above 0"};
  f.flat = j.number(2) != 0;
  if (f.flat && j.given(1))
    return Fault{"flat", "a flat face has no roller: give \"roller_mm\" or \"flat\": true"};
  if (!f.flat && !j.given(1))
    return Fault{"roller_mm",
                 "missing: the roller's radius (0 for a knife edge), or \"flat\": "
                 "true"};
  f.roller = f.flat ? 0.0 : j.number(1);
  if (!(f.roller >= 0) || !std::isfinite(f.roller))
    return Fault{"roller_mm", "expected a radius of 0 (a knife edge) or more"};
  return std::nullopt;
}

// With `drawn` false, the sizes are not checked against the drawing (camJointAsDrawn).
std::optional<Fault> read(const Mechanism& m, const Joint& j, CamJoint& c, bool drawn = true) {
  if (auto f = sizes(j, c.kind)) return f;
  const Point *a = m.point(j.a), *b = m.point(j.b);
  c.cam = a->body;
  c.follower = b->body;
  c.drawn.centre = a->pos;
  c.drawn.b = b->pos;
  c.guide = pinnedAt(m, *a, c.follower);
  if (!c.guide)
    return Fault{"a", quoted(m.pointLabel(a->id)) +
                          " is not where the cam's body is pinned: a cam turns on a pin at its "
                          "centre, on the body that guides its follower"};
  if (auto f = followerJoint(m, c)) return f;
  std::vector<cam::Segment> segs;
  if (auto f = segments(j, c.kind.oscillating, segs)) return f;
  if (auto f = orient(c)) return f;
  if (drawn)
    if (auto f = lowest(c)) return f;
  c.program = cam::Program(std::move(segs), c.kind.oscillating ? M_PI / 180 : 1.0);
  return std::nullopt;
}

std::string check(const Mechanism& m, const Joint& j, const char*& where) {
  // The key at fault may be a record's ("motion[2].law"): kept here for the caller's message.
  static thread_local std::string place;
  std::string why;
  if (!camJoint(m, j, &why, &place)) where = place.c_str();
  return why;
}

bool compile(const Mechanism& m, const Joint& j, const Frames& f, std::vector<Row>& rows,
             std::string& why) {
  std::string where;
  const std::optional<CamJoint> c = camJoint(m, j, &why, &where);
  if (!c) {
    why = where + ": " + why;
    return false;
  }
  const int guide = f.body(c->guide), cam = f.body(c->cam);
  auto k = std::make_shared<CamRow>();
  k->program = c->program;
  k->kind = c->kind;
  k->centre = f.local(cam, c->drawn.centre);
  k->along = c->drawn.along;  // bodies are at angle 0 as drawn: directions are the drawing's
  k->pivot = f.local(guide, c->drawn.pivot);
  k->face = c->drawn.face;
  Row r;
  r.kind = Primitive::Cam;
  r.body[0] = f.point(j.b)->body;
  r.body[1] = cam;
  r.body[2] = guide;
  r.s[0] = f.point(j.b)->s;
  r.s[1] = f.local(guide, c->drawn.b);
  r.cam = std::move(k);
  rows.push_back(r);
  return true;
}

CentreData centre(const Mechanism& m, const Joint& j) {
  CentreData c;
  c.rule = CentreRule::PoseLine;
  c.bodies[0] = m.point(j.a)->body;
  c.bodies[1] = m.point(j.b)->body;
  return c;
}

bool centreLine(const Mechanism& m, const Joint& j, const Pose& pose, Vec2& through, Vec2& along) {
  const std::optional<CamJoint> c = camJoint(m, j);
  if (!c) return false;
  const Transform G = pose.body(c->guide), F = pose.body(c->follower);
  cam::Place at;
  at.centre = pose.point(j.a);
  at.b = pose.point(j.b);
  at.along = G.R * c->drawn.along;
  at.pivot = G * c->drawn.pivot;
  at.face = F.R * c->drawn.face;
  const double theta = camAngle(pose.body(c->cam).R, G.R);
  const cam::Contact k = cam::contact(c->kind, at, c->program.at(theta).v);
  through = k.point;
  along = k.normal;
  return true;
}

void symbol(const Mechanism& m, const Joint& j, JointSymbol& s) {
  const Point *a = m.point(j.a), *b = m.point(j.b);
  s.bodies[0] = a ? a->body : BodyId{};
  s.bodies[1] = b ? b->body : BodyId{};
  if (!a || !b) return;
  const std::optional<CamJoint> c = camJoint(m, j);
  // A cam not (yet) sound is drawn as a circle through b.
  s.radius[0] = c ? c->kind.base : (b->pos - a->pos).norm();
  s.radius[1] = c ? c->kind.roller : 0.0;
  s.face = c && c->kind.flat;
  if (c && c->kind.flat) s.direction = c->kind.oscillating ? c->drawn.face : c->drawn.along;
  if (!c) return;
  // A degree a point: the canvas's profile, the checks' own points (linkage/cam_geometry.h).
  for (const cam::CamPoint& p : cam::camPoints(cam::geometryOf(*c), 360)) {
    s.curve.push_back(p.surface);
    if (!c->kind.flat && c->kind.roller > 0) s.curve2.push_back(p.pitch);
  }
}

void place(const Mechanism&, const Joint& j, const Pose& pose, JointSymbol& s) {
  s.at = pose.point(j.a);
  s.at2 = pose.point(j.b);
  for (int k = 0; k < 2; ++k) s.angle[k] = pose.body(s.bodies[k]).R.angle();
}

}  // namespace

namespace {

std::optional<CamJoint> readCam(const Mechanism& m, const Joint& j, std::string* why,
                                std::string* where, bool drawn) {
  CamJoint c;
  if (!m.point(j.a) || !m.point(j.b)) {
    if (why) *why = "unknown reference";
    if (where) where->assign(1, m.point(j.a) ? 'b' : 'a');  // (GCC 12's -Wrestrict: bug 105329)
    return std::nullopt;
  }
  if (std::optional<Fault> f = read(m, j, c, drawn)) {
    if (why) *why = f->why;
    if (where) *where = f->where;
    return std::nullopt;
  }
  return c;
}

}  // namespace

std::optional<CamJoint> camJoint(const Mechanism& m, const Joint& j, std::string* why,
                                 std::string* where) {
  return readCam(m, j, why, where, true);
}

std::optional<CamJoint> camJointAsDrawn(const Mechanism& m, const Joint& j, std::string* why,
                                        std::string* where) {
  return readCam(m, j, why, where, false);
}

ElementKind camElement(JointType t) {
  ElementKind k{t,
                "cam",
                "moves the follower of point \"b\" by the cam of point \"a\"",
                Role::Contact,
                1,
                kFields,
                check,
                compile,
                centre,
                symbol,
                place,
                kForceColumns,
                nullptr,
                false};
  k.centreLine = centreLine;
  return k;
}

}  // namespace linkage
