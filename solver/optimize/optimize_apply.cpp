// Dimensions set to values exactly (linkage/optimize.h): what dimensions() differentiates, done
// for a finite change. Written for the optimiser (the tolerance work had not landed one).
#include <algorithm>
#include <cmath>
#include <map>

#include "linkage/gear.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"

namespace linkage {

namespace {

using Values = std::map<std::string, double>;

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The point at distances r0 from a and r1 from b on the side `side` (> 0: left of a->b).
bool placed(const Vec2& a, const Vec2& b, double r0, double r1, double side, Vec2& out) {
  const double len = (b - a).norm();
  const Vec2 e = (b - a) / len;
  const double along = (r0 * r0 - r1 * r1 + len * len) / (2 * len);
  const double h2 = r0 * r0 - along * along;
  if (!(h2 >= 0) || !(r0 > 0) || !(r1 > 0)) return false;
  out = a + along * e + (side < 0 ? -1.0 : 1.0) * std::sqrt(h2) * perp(e);
  return true;
}

// A body drawn again from all its dimensions at once (the new values where given, the others as
// they are), so that the order of the changes does not matter: P1 at P0-P1 along P0->P1, each
// later point by its two distances (its side of P0P1 kept) or along and across P0->P1.
Status redrawBody(Mechanism& m, BodyId body, const Values& all) {
  std::vector<Point*> p;
  for (Point& q : m.points)
    if (q.body == body) p.push_back(&q);
  const std::string pre = m.body(body)->name + ".";
  auto value = [&](const std::string& n) { return all.at(pre + n); };
  if (all.count(pre + p[0]->name + "-" + p[1]->name) == 0) {  // P0 on P1: each point's x, y
    for (size_t k = 1; k < p.size(); ++k)
      p[k]->pos = Vec2(value(p[k]->name + ".x"), value(p[k]->name + ".y"));
    return Status::success();
  }
  const double len = value(p[0]->name + "-" + p[1]->name);
  if (!(len > 0))
    return Status::badModel("'" + pre + p[0]->name + "-" + p[1]->name + "' must be positive");
  const Vec2 a = p[0]->pos, b = p[1]->pos, e = (b - a).normalized(), nb = a + len * e;
  std::vector<Vec2> at(p.size());
  at[1] = nb;
  for (size_t k = 2; k < p.size(); ++k) {
    const std::string n = p[k]->name;
    if (all.count(pre + n + ".along")) {
      at[k] = a + value(n + ".along") * e + value(n + ".across") * perp(e);
    } else if (!placed(a, nb, value(p[0]->name + "-" + n), value(p[1]->name + "-" + n),
                       cross(b - a, p[k]->pos - a), at[k])) {
      return Status::badModel("the sides of '" + pre + n + "' do not make a triangle");
    }
  }
  for (size_t k = 1; k < p.size(); ++k) p[k]->pos = at[k];
  return Status::success();
}

void setSlot(Mechanism& m, const Dimension& d, double value) {
  Slot* s = m.slot(d.slots.front().slot);
  if (endsWith(d.name, ".offset")) {
    const Vec2 n = d.slots.front().p0;  // per unit of offset both ends move along the normal
    s->p0 += (value - d.value) * n;
    s->p1 += (value - d.value) * n;
  } else {
    const double len = (s->p1 - s->p0).norm(), rad = value * M_PI / 180;
    s->p1 = s->p0 + len * Vec2(std::cos(rad), std::sin(rad));
  }
}

// Ground points, slots (angles before offsets: an offset is along the turned normal), gears.
void setOthers(Mechanism& m, const Values& given) {
  for (int pass = 0; pass < 2; ++pass)
    for (const Dimension& d : dimensions(m)) {
      auto it = given.find(d.name);
      if (it == given.end()) continue;
      if (!d.slots.empty()) {
        if (endsWith(d.name, ".angle") == (pass == 0)) setSlot(m, d, it->second);
      } else if (pass == 0 && d.ratioOf) {
        setGearRatio(*m.joint(d.ratioOf), it->second);
      } else if (pass == 0 && m.body(m.point(d.points.front().first)->body)->ground) {
        m.point(d.points.front().first)->pos[endsWith(d.name, ".y") ? 1 : 0] = it->second;
      }
    }
}

}  // namespace

Status setDimensions(Mechanism& m, const std::vector<std::pair<std::string, double>>& values) {
  const std::vector<Dimension> dims = dimensions(m);
  Values all, given;
  for (const Dimension& d : dims) all[d.name] = d.value;
  std::vector<BodyId> bodies;
  for (const auto& [name, value] : values) {
    auto it = all.find(name);
    if (it == all.end()) return Status::badModel("no dimension '" + name + "' in the mechanism");
    if (!std::isfinite(value))
      return Status::badModel("'" + name + "': the value is not a finite number");
    it->second = given[name] = value;
  }
  Mechanism next = m;
  for (const Dimension& d : dims) {
    if (!given.count(d.name) || d.points.empty()) continue;
    const BodyId b = m.point(d.points.front().first)->body;
    if (m.body(b)->ground || std::find(bodies.begin(), bodies.end(), b) != bodies.end()) continue;
    bodies.push_back(b);
    if (Status s = redrawBody(next, b, all); !s.ok()) return s;
  }
  for (const Dimension& d : dims)
    if (given.count(d.name) && d.ratioOf && !(given[d.name] != 0))
      return Status::badModel("'" + d.name + "': a gear ratio cannot be 0");
  setOthers(next, given);
  m = std::move(next);
  return Status::success();
}

Status setDimension(Mechanism& m, const std::string& name, double value) {
  return setDimensions(m, {{name, value}});
}

}  // namespace linkage
