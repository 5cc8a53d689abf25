// Exact finite changes of a mechanism's dimensions (linkage/dimension_change.h).
#include "linkage/dimension_change.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/dimension_change_space.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/elements.h"
#include "linkage/gear.h"
#include "linkage/guide.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"

namespace linkage {

namespace {

using Changes = std::map<std::string, double>;

double changeOf(const Changes& c, const std::string& name) {
  auto it = c.find(name);
  return it == c.end() ? 0.0 : it->second;
}

// The point at distances r0 from a and r1 from b, on the side `side` (+1 left of a->b); false
// when the circles do not meet.
bool circles(const Vec2& a, const Vec2& b, double r0, double r1, double side, Vec2& out) {
  const Vec2 ab = b - a;
  const double d = ab.norm();
  const double along = (r0 * r0 - r1 * r1 + d * d) / (2 * d);
  const double h2 = r0 * r0 - along * along;
  if (!(d > 0) || !(h2 >= 0)) return false;
  const Vec2 e = ab / d;
  out = a + along * e + side * std::sqrt(h2) * perp(e);
  return true;
}

Status changeBody(Mechanism& m, const Body& body, const Changes& c) {
  std::vector<Point*> p;
  for (Point& q : m.points)
    if (q.body == body.id) p.push_back(&q);
  if (p.size() < 2) return Status::success();
  const std::string pre = body.name + ".";
  const Vec2 a = p[0]->pos, b = p[1]->pos;
  const double len = (b - a).norm();
  if (!(len > 0)) {  // each later point by its own coordinates
    for (size_t k = 1; k < p.size(); ++k)
      p[k]->pos += Vec2(changeOf(c, pre + p[k]->name + ".x"), changeOf(c, pre + p[k]->name + ".y"));
    return Status::success();
  }
  const Vec2 e = (b - a) / len;
  const Vec2 b2 = a + (len + changeOf(c, pre + p[0]->name + "-" + p[1]->name)) * e;
  const bool base = c.count(pre + p[0]->name + "-" + p[1]->name) > 0;
  for (size_t k = 2; k < p.size(); ++k) {
    const Vec2 q = p[k]->pos;
    const std::string along = pre + p[k]->name + ".along";
    // A point none of whose dimensions change stays as drawn, to the bit: placing it again by
    // its two distances loses digits where it is near the line P0P1.
    if (!base && !c.count(along) && !c.count(pre + p[k]->name + ".across") &&
        !c.count(pre + p[0]->name + "-" + p[k]->name) &&
        !c.count(pre + p[1]->name + "-" + p[k]->name))
      continue;
    if (c.count(along) || c.count(pre + p[k]->name + ".across") || measuredAlongAcross(a, b, q)) {
      // Placed along and across P0->P1 (whose direction no dimension turns): so is a point
      // dimensions() measures so when P0-P1 changes (its distances would not meet again).
      p[k]->pos = a + (e.dot(q - a) + changeOf(c, along)) * e +
                  (cross(e, q - a) + changeOf(c, pre + p[k]->name + ".across")) * perp(e);
      continue;
    }
    const double r0 = (q - a).norm() + changeOf(c, pre + p[0]->name + "-" + p[k]->name);
    const double r1 = (q - b).norm() + changeOf(c, pre + p[1]->name + "-" + p[k]->name);
    const double side = cross(e, q - a) >= 0 ? 1.0 : -1.0;
    if (!circles(a, b2, r0, r1, side, p[k]->pos))
      return Status::badModel(body.name + "." + p[k]->name + ": its changed distances from " +
                              p[0]->name + " and " + p[1]->name + " do not meet");
  }
  p[1]->pos = b2;
  return Status::success();
}

Status changeSlot(Mechanism& m, Slot& s, const Changes& c) {
  const std::optional<Guide> g = guideOf(s);
  if (!g) return Status::success();
  const std::string pre = m.slotLabel(s.id) + ".";
  if (s.arc()) {  // its radius about its centre, then the whole arc moved
    if (!c.count(pre + "radius") && !c.count(pre + "centre.x") && !c.count(pre + "centre.y"))
      return Status::success();  // drawn as it was, to the bit
    const double radius = g->radius + changeOf(c, pre + "radius");
    if (!(radius > 0)) return Status::badModel(pre + "radius: an arc's radius must stay above 0");
    const Vec2 to = g->centre + Vec2(changeOf(c, pre + "centre.x"), changeOf(c, pre + "centre.y"));
    for (Vec2* p : {&s.p0, &*s.mid, &s.p1}) *p = to + radius / g->radius * (*p - g->centre);
    return Status::success();
  }
  const double turn = changeOf(c, pre + "angle") * M_PI / 180;
  const double offset = changeOf(c, pre + "offset");
  if (turn == 0 && offset == 0) return Status::success();
  const double cs = std::cos(turn), sn = std::sin(turn);
  auto rotate = [&](const Vec2& v) {
    return Vec2(cs * v.x() - sn * v.y(), sn * v.x() + cs * v.y());
  };
  const Vec2 normal = rotate(g->normal);
  s.p1 = s.p0 + rotate(s.p1 - s.p0) + offset * normal;
  s.p0 += offset * normal;
  return Status::success();
}

// A cam's changes as the Cam dock makes them (linkage/cam_edits.h): the rises by each
// dimension's own change of the programme (the segment and the one taking the difference), the
// roller on the same cam (setCamRoller keeps base + roller, so the base is set back after it)
// and the base, the follower moved to its new lowest position.
Status changeCam(Mechanism& m, JointId j, const std::vector<Dimension>& dims,
                 const std::vector<double>& delta) {
  const Joint* joint = m.joint(j);
  std::string why;
  const std::optional<CamJoint> c = joint ? camJointAsDrawn(m, *joint, &why) : std::nullopt;
  if (!c) return Status::badModel(jointLabel(m, j) + ": " + why);
  std::vector<cam::Segment> segs = c->program.segments();
  double base = c->kind.base, roller = c->kind.roller;
  std::string names;
  bool rises = false;
  for (size_t k = 0; k < dims.size(); ++k) {
    if (dims[k].camOf != j || delta[k] == 0) continue;
    names += (names.empty() ? "" : ", ") + dims[k].name;
    for (size_t i = 0; i < segs.size() && i < dims[k].camRises.size(); ++i) {
      segs[i].rise += delta[k] * dims[k].camRises[i];
      rises = true;
    }
    (dims[k].camRoller ? roller : base) += delta[k] * dims[k].camBase;
  }
  if (rises && !setCamMotion(m, j, segs, &why)) return Status::badModel(names + ": " + why);
  if (roller != c->kind.roller && !setCamRoller(m, j, roller, &why))
    return Status::badModel(names + ": " + why);
  if ((base != c->kind.base || roller != c->kind.roller) && !setCamBase(m, j, base, &why))
    return Status::badModel(names + ": " + why);
  return Status::success();
}

// The cams whose parts the other changes took off what they rest on (the guide's pin under the
// cam's centre, the follower's pivot or slot, its lowest position): put back, as the
// derivatives place them (replaceCam).
Status replaceFollowers(Mechanism& m) {
  for (const Joint& j : m.joints) {
    if (std::string_view(kindOf(j).name) != "cam") continue;
    std::string why;
    if (!replaceCam(m, j.id, &why)) return Status::badModel(jointLabel(m, j.id) + ": " + why);
  }
  return Status::success();
}

}  // namespace

Status changeDimensions(Mechanism& m, const std::vector<Dimension>& dims,
                        const std::vector<double>& delta) {
  if (dims.size() != delta.size())
    return Status::badModel("changeDimensions: a change for each dimension");
  Changes c;
  for (size_t k = 0; k < dims.size(); ++k)
    if (delta[k] != 0) c[dims[k].name] = delta[k];
  if (c.empty()) return Status::success();
  const std::vector<internal::RodLength> rods = internal::rodLengths(m, dims, delta);
  for (size_t k = 0; k < dims.size(); ++k) {
    if (!dims[k].ratioOf || delta[k] == 0) continue;
    for (Joint& j : m.joints)
      if (j.id == dims[k].ratioOf) setGearRatio(j, gearRatio(j) + delta[k]);
  }
  // The cams first: their lowest positions are placed from the drawing as it is.
  std::vector<JointId> cams;
  for (size_t k = 0; k < dims.size(); ++k)
    if (dims[k].camOf && delta[k] != 0 &&
        std::find(cams.begin(), cams.end(), dims[k].camOf) == cams.end())
      cams.push_back(dims[k].camOf);
  for (JointId j : cams)
    if (Status s = changeCam(m, j, dims, delta); !s.ok()) return s;
  const Body* ground = isSpatial(m) ? m.ground() : nullptr;
  for (Slot& s : m.slots)
    if (!ground || s.body != ground->id)  // else changeInSpace's
      if (Status st = changeSlot(m, s, c); !st.ok()) return st;
  if (Status s = internal::changeInSpace(m, dims, delta); !s.ok()) return s;
  for (const Body& b : m.bodies) {
    if (!b.ground) {
      if (Status s = changeBody(m, b, c); !s.ok()) return s;
      continue;
    }
    for (Point& q : m.points)
      if (q.body == b.id)
        q.pos += Vec2(changeOf(c, b.name + "." + q.name + ".x"),
                      changeOf(c, b.name + "." + q.name + ".y"));
  }
  if (Status s = replaceFollowers(m); !s.ok()) return s;
  std::string names;
  for (const auto& [name, by] : c) names += (names.empty() ? "" : ", ") + name;
  return internal::keepRodLengths(m, rods, names);
}

Status pinPlay(const Mechanism& m, const std::string& pin, PinPlay& out) {
  for (const Joint& j : m.joints) {
    if (j.type != JointType::Pin || !j.a || !j.b) continue;
    const std::string a = m.pointLabel(j.a), b = m.pointLabel(j.b);
    if (pin != a + "-" + b && pin != b + "-" + a) continue;
    auto uses = [&](PointId p) {
      int n = 0;
      for (const Joint& o : m.joints)
        if (o.a == p || o.b == p) ++n;
      return n;
    };
    // The point no other joint holds: moving it opens this pin alone.
    const PointId p = uses(j.b) == 1 ? j.b : uses(j.a) == 1 ? j.a : PointId{};
    if (!p)
      return Status::badModel("pin " + pin +
                              ": both its points serve other joints too, so "
                              "moving either would open them as well");
    out.joint = j.id;
    out.point = p;
    out.x = out.y = Dimension{};
    out.x.name = pin + ".play.x";
    out.x.points = {{p, Vec2::UnitX()}};
    out.y.name = pin + ".play.y";
    out.y.points = {{p, Vec2::UnitY()}};
    return Status::success();
  }
  return Status::badModel("no pin joint " + pin +
                          " (a pin is named by its two points, "
                          "body.P-body.Q)");
}

}  // namespace linkage
