// Building a closed-form plan (ClosedFormPlan::build) from the structural decomposition
// (structure/decomposition.h): each group of a kind the closed form solves becomes its numeric
// group, with its local directions and drawn branch taken from the assembled configuration.
// Linear in the size of the mechanism.
#include <algorithm>

#include "elements/cam_row.h"
#include "kinematics/closed_form.h"

namespace linkage {

class ClosedFormPlan::Builder {
 public:
  Builder(const System& sys, int joints) : sys_(sys), nj_(joints) {}

  std::optional<ClosedFormPlan> run(const Decomposition& d, const Motion& at) {
    if (!sys_.hasDriver || sys_.nRows != sys_.nCoords() || sys_.nJointRows + 1 != sys_.nCoords())
      return std::nullopt;  // holds, redundant or missing equations: the general solve
    if (!d.closedForm()) return std::nullopt;
    plan_.jointGroup_.assign(nj_, -1);
    for (const linkage::Group& g : d.groups) {
      if (!add(g, at)) return std::nullopt;
      for (int j : g.joints) plan_.jointGroup_[j] = static_cast<int>(plan_.groups_.size()) - 1;
    }
    branches(at);
    plan_.bodyGroup_.assign(sys_.nBodies, -1);
    std::vector<int> unknown, known;
    for (size_t i = 0; i < plan_.groups_.size(); ++i) {
      plan_.bodiesOf(plan_.groups_[i], unknown, known);
      for (int b : unknown) plan_.bodyGroup_[b] = static_cast<int>(i);
    }
    return std::move(plan_);
  }

 private:
  const Row& row(int r) const { return sys_.cons[r]; }
  static const Vec2& on(const Row& c, int b) { return c.body[0] == b ? c.s[0] : c.s[1]; }
  static const Vec2& across(const Row& c, int b) { return c.body[0] == b ? c.s[1] : c.s[0]; }
  static int other(const Row& c, int b) { return c.body[0] == b ? c.body[1] : c.body[0]; }

  // Body b's pin to a known body, as the group's first: k1, p1 (on b), p1k (on k1).
  static void outerPin(Group& g, const Row& pin) {
    g.k1 = other(pin, g.b1);
    g.p1 = on(pin, g.b1);
    g.p1k = across(pin, g.b1);
  }

  bool add(const linkage::Group& d, const Motion& at) {
    using K = linkage::Group::Kind;
    Group g;
    g.b1 = d.bodies[0];
    switch (d.kind) {
      case K::Crank: {
        g.kind = Kind::Crank;
        outerPin(g, row(d.rows[0]));
        // theta_B = theta_K + sigma phi on the driver's b side, - sigma phi on its a side.
        g.sign = row(d.rows[1]).body[0] == g.b1 ? sys_.sigma : -sys_.sigma;
        break;
      }
      case K::Geared: {
        g.kind = Kind::Geared;
        outerPin(g, row(d.rows[0]));
        g.angles = d.rows[1];
        const Row& a = row(g.angles);
        int* others[] = {&g.k2, &g.k3};
        int n = 0;
        for (int k = 0; k < 3; ++k)
          if (a.body[k] != g.b1 && n < 2) *others[n++] = a.body[k];
        break;
      }
      case K::RRR:
      case K::RRP: {
        g.kind = d.kind == K::RRR ? Kind::RRR : Kind::RRP;
        g.b2 = d.bodies[1];
        outerPin(g, row(d.rows[0]));
        const Row& mid = row(d.rows[1]);
        g.c1 = on(mid, g.b1);
        g.c2 = on(mid, g.b2);
        const Row& out = row(d.rows[2]);
        if (g.kind == Kind::RRR) {
          g.k2 = other(out, g.b2);
          g.p2 = on(out, g.b2);
          g.p2k = across(out, g.b2);
        } else {
          g.k2 = out.body[1];
          g.q2 = out.s[0];
          g.u = out.s[1];
          g.n = out.n;
        }
        break;
      }
      case K::RP:
        inSlot(g, row(d.rows[0]), row(d.rows[1]));
        break;
      case K::PR: {
        g.kind = Kind::PR;
        outerPin(g, row(d.rows[0]));
        const Row& s = row(d.rows[1]);  // the known body's point on b1's line
        g.k2 = s.body[0];
        g.p2k = s.s[0];
        g.u = s.s[1];
        g.n = s.n;
        break;
      }
      case K::RS:
        if (!rocker(g, row(d.rows[0]), row(d.rows[1]))) return false;
        break;
      case K::Cam:
        if (!follower(g, d)) return false;
        break;
      case K::Triad:
        return core(d, at);
      case K::Other:
        return false;
    }
    plan_.groups_.push_back(g);
    return true;
  }

  // RP: b1's pin, then its point C in a known body's straight or arc slot (row s).
  static void inSlot(Group& g, const Row& pin, const Row& s) {
    outerPin(g, pin);
    g.c1 = s.s[0];
    g.k2 = s.body[1];
    if (s.kind == Primitive::OnCircle) {
      // The point runs on a circle of k2: an RRR whose second link is the radius.
      g.kind = Kind::RC;
      g.p2k = s.s[1];
      g.d2 = s.c[0];
    } else {
      g.kind = Kind::RP;
      g.u = s.s[1];
      g.n = s.n;
    }
  }

  // RS: b1's pin, then its ball rod to a known body. False where the rod's end is on the pin's
  // axis: it turns nothing, there is no angle to solve for.
  static bool rocker(Group& g, const Row& pin, const Row& rod) {
    g.kind = Kind::RS;
    outerPin(g, pin);
    const int e = rod.body[0] == g.b1 ? 0 : 1;
    g.c1 = rod.s[e];
    g.f1 = rod.frame[e];
    g.z1 = rod.depth[e];
    g.k2 = rod.body[1 - e];
    g.p2k = rod.s[1 - e];
    g.f2 = rod.frame[1 - e];
    g.z2 = rod.depth[1 - e];
    g.d2 = rod.c[0];
    return (g.c1 - g.p1).squaredNorm() > 1e-18 * g.d2 * g.d2;
  }

  // Cam: the follower's own joint to the cam's guide, then the cam's row (closed_form.h). False
  // where the rows are not the follower's as elements/cam.cpp compiles them (its slider keeps
  // the guide's angle).
  bool follower(Group& g, const linkage::Group& d) const {
    g.kind = Kind::Cam;
    const Row& c = row(d.rows.back());
    g.cam = c.cam;
    g.k2 = c.body[1];
    g.c2 = c.s[0];
    g.p2 = c.s[1];
    if (c.cam->kind.oscillating) {
      if (d.rows.size() != 2) return false;
      outerPin(g, row(d.rows[0]));
      return g.k1 == c.body[2];
    }
    if (d.rows.size() != 3) return false;
    g.k1 = c.body[2];
    const Row &line = row(d.rows[0]), &angle = row(d.rows[1]);
    const int e = line.body[0] == g.b1 ? 0 : 1;
    g.c1 = line.s[e];
    g.p2k = line.s[1 - e];
    g.n = line.n;
    double cf = 0, cg = 0;
    for (int k = 0; k < 3; ++k) {
      if (angle.c[k] == 0) continue;
      if (angle.body[k] != g.b1 && angle.body[k] != g.k1) return false;
      (angle.body[k] == g.b1 ? cf : cg) += angle.c[k];
    }
    return line.body[1 - e] == g.k1 && cf != 0 && cf + cg == 0 && angle.value == 0;
  }

  // A core body held by three conditions, its blocks eliminated (core_group.h). False where it
  // is singular as assembled (no branch to keep).
  bool core(const linkage::Group& d, const Motion& at) {
    CoreGroup core;
    const int c = d.bodies[0];
    core.core = c;
    auto isBlock = [&](int b) {
      return b != c && std::find(d.bodies.begin(), d.bodies.end(), b) != d.bodies.end();
    };
    for (int r : d.rows) {
      const Row& x = row(r);
      if (x.kind == Primitive::Coincident && (x.body[0] == c || x.body[1] == c)) {
        CoreLink link;
        link.s = on(x, c);
        const int o = other(x, c);
        if (!isBlock(o)) {
          link.pin = true;
          link.known = o;
          link.ks = across(x, c);
        } else {
          // The block's pin point keeps to its slot's line shifted by the block's offset.
          const Row* line = nullptr;
          for (int q : d.rows)
            if (row(q).kind == Primitive::OnLine && row(q).body[0] == o) line = &row(q);
          link.known = line->body[1];
          link.ks = line->s[1] - (line->s[0] - across(x, c));
          link.n = line->n;
          link.block = o;
          link.blockPin = across(x, c);
        }
        core.links.push_back(link);
      } else if (x.kind == Primitive::OnLine && x.body[0] == c) {
        CoreLink link;
        link.known = x.body[1];
        link.s = x.s[0];
        link.ks = x.s[1];
        link.n = x.n;
        core.links.push_back(link);
      }
    }
    core.detSign = coreDetSign(core, at);
    if (core.detSign == 0) return false;
    Group g;
    g.kind = Kind::Core;
    g.b1 = c;
    g.core = static_cast<int>(plan_.cores_.size());
    plan_.cores_.push_back(core);
    plan_.groups_.push_back(g);
    return true;
  }

  // Local directions and the drawn branches, from the assembled configuration.
  void branches(const Motion& at) {
    for (Group& g : plan_.groups_) {
      if (g.kind == Kind::Crank || g.kind == Kind::Core || g.kind == Kind::Geared ||
          g.kind == Kind::Cam)
        continue;
      if (g.kind == Kind::RS) {
        g.sign = plan_.rockerSide(g, sys_, at, at.of(g.b1).R) >= 0 ? 1 : -1;
        continue;
      }
      if (g.kind == Kind::PR) {
        // The side of D = C - P1 the slot's normal is on, as drawn.
        const Vec2 D = at.of(g.k2).pos(g.p2k) - at.of(g.k1).pos(g.p1k);
        g.rot1 = Rot{g.n.x(), g.n.y()};
        g.sign = cross(D, at.of(g.b1).R * g.n) >= 0 ? 1 : -1;
        continue;
      }
      g.rot1 = direction(g.c1 - g.p1);
      g.d1 = (g.c1 - g.p1).norm();
      const BodyState& k1 = at.of(g.k1);
      const BodyState& b1 = at.of(g.b1);
      const Vec2 P1 = k1.pos(g.p1k), C = b1.pos(g.c1);
      if (g.kind == Kind::RRR || g.kind == Kind::RC) {
        if (g.kind == Kind::RRR) {
          g.rot2 = direction(g.c2 - g.p2);
          g.d2 = (g.c2 - g.p2).norm();
        }
        const Vec2 P2 = at.of(g.k2).pos(g.p2k);
        g.sign = cross(P2 - P1, C - P1) >= 0 ? 1 : -1;
      } else {
        g.d = -perp(g.n);  // the slot's direction: n was made as perp(direction)
        const BodyState& k2 = at.of(g.k2);
        const Vec2 n = k2.R * g.n;
        const Vec2 foot = P1 + n.dot(C - P1) * n;  // C is on the (shifted) line: project P1 on it
        g.sign = (k2.R * g.d).dot(C - foot) >= 0 ? 1 : -1;
      }
    }
  }

  static Rot direction(const Vec2& v) {
    const double n = v.norm();
    return Rot{v.x() / n, v.y() / n};
  }

  const System& sys_;
  const int nj_;
  ClosedFormPlan plan_;
};

std::optional<ClosedFormPlan> ClosedFormPlan::build(const Decomposition& d, const System& sys,
                                                    int joints, const Motion& at) {
  return Builder(sys, joints).run(d, at);
}

}  // namespace linkage
