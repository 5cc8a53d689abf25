#include "linkage/grashof.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "linkage/elements.h"
#include "linkage/groups.h"
#include "linkage/space.h"

namespace linkage {

const char* toString(GrashofClass c) {
  switch (c) {
    case GrashofClass::CrankRocker:
      return "crank-rocker";
    case GrashofClass::DoubleCrank:
      return "double-crank";
    case GrashofClass::GrashofDoubleRocker:
      return "double-rocker (Grashof)";
    case GrashofClass::RockerCrank:
      return "rocker-crank";
    case GrashofClass::NonGrashofDoubleRocker:
      return "double-rocker (non-Grashof)";
    case GrashofClass::ChangePoint:
      return "change point";
  }
  return "?";
}

GrashofClass grashofClass(double frame, double input, double coupler, double output) {
  std::array<double, 4> sorted{frame, input, coupler, output};
  std::sort(sorted.begin(), sorted.end());
  const double sl = sorted[0] + sorted[3], pq = sorted[1] + sorted[2];
  if (std::abs(sl - pq) <= kChangePointTolerance * sorted[3]) return GrashofClass::ChangePoint;
  if (sl > pq) return GrashofClass::NonGrashofDoubleRocker;
  // s + l < p + q leaves one shortest link: two equal shortest would need l < p.
  if (input == sorted[0]) return GrashofClass::CrankRocker;
  if (frame == sorted[0]) return GrashofClass::DoubleCrank;
  if (coupler == sorted[0]) return GrashofClass::GrashofDoubleRocker;
  return GrashofClass::RockerCrank;
}

namespace {

struct Pin {
  JointId id;
  int index = 0;  // file order
  BodyId a, b;
  Vec2 pa, pb;  // the pin's point on body a and on body b, as drawn
  Vec2 on(BodyId body) const { return body == a ? pa : pb; }
  BodyId other(BodyId body) const { return body == a ? b : a; }
};

// In space a pin joins bodies of parallel planes, and the ground's point of it is taken in the
// other body's class frame (projected along its normal), as the solver takes it: a loop's frame
// is then the distance of its pivots in the loop's plane, not in the drawing plane.
std::vector<Pin> pins(const Mechanism& m) {
  std::vector<Pin> out;
  const bool spatial = isSpatial(m);
  const PlaneClasses classes = spatial ? planeClasses(m) : PlaneClasses{};
  auto drawn = [&](const Point& p, const Point& other) {
    const Body *on = m.body(p.body), *by = m.body(other.body);
    if (!spatial || !on || !on->ground || !by || by->ground) return p.pos;
    return classes.project(classes.of(by->plane).cls, worldOf(m, p));
  };
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    if (kindOf(j).role != Role::Revolute) continue;
    const Point *a = m.point(j.a), *b = m.point(j.b);
    if (!a || !b || a->body == b->body) continue;
    out.push_back({j.id, static_cast<int>(i), a->body, b->body, drawn(*a, *b), drawn(*b, *a)});
  }
  return out;
}

}  // namespace

std::vector<FourBarLoop> fourBarLoops(const Mechanism& m) {
  const std::vector<Pin> ps = pins(m);
  const AssurDecomposition d = decomposeAssur(m);
  std::map<BodyId, std::pair<int, int>> ranks;  // the structure's order, then file order
  std::map<BodyId, std::vector<int>> at;        // the pins at each body
  for (size_t i = 0; i < m.bodies.size(); ++i)
    ranks[m.bodies[i].id] = {d.groupOf(m.bodies[i].id), static_cast<int>(i)};
  for (size_t i = 0; i < ps.size(); ++i) {
    at[ps[i].a].push_back(static_cast<int>(i));
    at[ps[i].b].push_back(static_cast<int>(i));
  }
  auto rank = [&](BodyId b) { return ranks[b]; };
  std::set<std::array<int, 4>> seen;
  std::vector<std::pair<std::array<std::pair<int, int>, 2>, std::array<int, 4>>> keys;
  std::vector<FourBarLoop> loops;
  // Rings b0 -p0- b1 -p1- b2 -p2- b3 -p3- b0 of distinct bodies and pins, walked from each pin.
  for (size_t i0 = 0; i0 < ps.size(); ++i0) {
    std::array<const Pin*, 4> p{&ps[i0]};
    std::array<BodyId, 4> b{ps[i0].a, ps[i0].b};
    for (int i1 : at[b[1]]) {
      p[1] = &ps[i1];
      if (p[1] == p[0]) continue;
      b[2] = p[1]->other(b[1]);
      if (b[2] == b[0]) continue;
      for (int i2 : at[b[2]]) {
        p[2] = &ps[i2];
        if (p[2] == p[1]) continue;
        b[3] = p[2]->other(b[2]);
        if (b[3] == b[0] || b[3] == b[1]) continue;
        for (int i3 : at[b[3]]) {
          p[3] = &ps[i3];
          if (p[3] == p[2] || p[3] == p[0] || p[3]->other(b[3]) != b[0]) continue;
          std::array<int, 4> key{p[0]->index, p[1]->index, p[2]->index, p[3]->index};
          std::sort(key.begin(), key.end());
          if (!seen.insert(key).second) continue;
          // Body b[k] between the pin that enters it, p[k - 1], and the one that leaves, p[k].
          std::array<double, 4> len;
          for (int k = 0; k < 4; ++k) len[k] = (p[k]->on(b[k]) - p[(k + 3) % 4]->on(b[k])).norm();
          if (*std::min_element(len.begin(), len.end()) == 0) continue;
          // Turn the ring so that the frame comes first and the input second.
          int f = 0;
          for (int k = 1; k < 4; ++k)
            if (rank(b[k]) < rank(b[f])) f = k;
          const int dir = rank(b[(f + 1) % 4]) < rank(b[(f + 3) % 4]) ? 1 : 3;
          FourBarLoop loop;
          for (int k = 0; k < 4; ++k) {
            const int j = (f + dir * k) % 4;
            loop.bodies[k] = b[j];
            loop.lengths[k] = len[j];
            // The pin between loop.bodies[k] and loop.bodies[k + 1].
            loop.joints[k] = dir == 1 ? p[j]->id : p[(j + 3) % 4]->id;
          }
          std::array<double, 4> s = loop.lengths;
          std::sort(s.begin(), s.end());
          loop.margin = (s[1] + s[2]) - (s[0] + s[3]);
          loop.kind =
              grashofClass(loop.lengths[0], loop.lengths[1], loop.lengths[2], loop.lengths[3]);
          keys.push_back({{rank(loop.bodies[0]), rank(loop.bodies[1])}, key});
          loops.push_back(loop);
        }
      }
    }
  }
  std::vector<size_t> order(loops.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return keys[x] < keys[y]; });
  std::vector<FourBarLoop> sorted;
  for (size_t i : order) sorted.push_back(loops[i]);
  return sorted;
}

}  // namespace linkage
