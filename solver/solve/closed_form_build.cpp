// The search for a closed-form plan (ClosedFormPlan::build): the groups found one after
// another from the ground outwards, as a designer does by hand (the crank, then any body that
// two joints to known bodies fix, any dyad, any core), then their local directions and their
// drawn branches from the assembled configuration. Each body's joints are listed once, so the
// search looks only at a body's own joints: linear in the size of a mechanism that decomposes.
#include "solve/closed_form.h"

namespace linkage {

class ClosedFormPlan::Builder {
 public:
  Builder(const Mechanism& m, const System& sys)
      : sys_(sys), nj_(static_cast<int>(m.joints.size())) {}

  std::optional<ClosedFormPlan> run(const Motion& at) {
    if (!sys_.hasDriver || sys_.nRows != sys_.nCoords() || sys_.nJointRows + 1 != sys_.nCoords())
      return std::nullopt;  // holds, redundant or missing equations: the general solve
    rows();
    plan_.jointGroup_.assign(nj_, -1);
    known_.assign(sys_.nBodies, false);
    int remaining = sys_.nBodies;
    bool crankDone = false;
    while (remaining > 0) {
      int solved = 0;
      if (!crankDone && (solved = crank()) > 0) crankDone = true;
      for (int b = 0; b < sys_.nBodies && solved == 0; ++b)
        if (!known_[b] && (solved = rp(b)) == 0) solved = dyad(b);
      for (int b = 0; b < sys_.nBodies && solved == 0; ++b)
        if (!known_[b] && (solved = core(b, at)) < 0) return std::nullopt;
      if (solved == 0) return std::nullopt;
      remaining -= solved;
    }
    for (int j = 0; j < nj_; ++j)
      if (!used_[j]) return std::nullopt;
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
  // The compiled rows of each joint, and each body's joints in file order.
  void rows() {
    pin_.assign(nj_, nullptr);
    line_.assign(nj_, nullptr);
    isSlider_.assign(nj_, false);
    used_.assign(nj_, false);
    for (const Constraint& c : sys_.cons) {
      if (c.kind == RowKind::Pin) pin_[c.joint] = &c;
      if (c.kind == RowKind::Line) line_[c.joint] = &c;
      if (c.kind == RowKind::Angle) isSlider_[c.joint] = true;
      if (c.kind == RowKind::Driver) driver_ = &c;
    }
    // Compressed: body b's joints are jointList_[first_[b]] to jointList_[first_[b + 1] - 1].
    first_.assign(sys_.nBodies + 1, 0);
    for (int j = 0; j < nj_; ++j)
      if (const Constraint* c = joint(j))
        for (int b : {c->bi, c->bj})
          if (b >= 0) ++first_[b + 1];
    for (int b = 0; b < sys_.nBodies; ++b) first_[b + 1] += first_[b];
    jointList_.resize(first_[sys_.nBodies]);
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (int j = 0; j < nj_; ++j)
      if (const Constraint* c = joint(j))
        for (int b : {c->bi, c->bj})
          if (b >= 0) jointList_[fill[b]++] = j;
  }

  // Body b's joints, in file order.
  struct Range {
    const int *b, *e;
    const int* begin() const { return b; }
    const int* end() const { return e; }
  };
  Range jointsOf(int b) const {
    return {jointList_.data() + first_[b], jointList_.data() + first_[b + 1]};
  }

  const Constraint* joint(int j) const { return pin_[j] ? pin_[j] : line_[j]; }
  bool isKnown(int b) const { return b < 0 || known_[b]; }
  static const Vec2& pinOn(const Constraint* c, int b) { return c->bi == b ? c->si : c->sj; }
  static const Vec2& pinOther(const Constraint* c, int b) { return c->bi == b ? c->sj : c->si; }
  static int otherBody(const Constraint* c, int b) { return c->bi == b ? c->bj : c->bi; }

  // Joints of body b not used yet whose other side is known.
  void toKnown(int b, std::vector<int>& out) const {
    out.clear();
    for (int j : jointsOf(b)) {
      if (used_[j]) continue;
      const Constraint* c = joint(j);
      if ((c->bi == b && isKnown(c->bj)) || (c->bj == b && isKnown(c->bi))) out.push_back(j);
    }
  }

  // Adds a group, with the joints it uses and the bodies it solves; returns their number.
  int add(const Group& g, std::initializer_list<int> joints, std::initializer_list<int> bodies) {
    plan_.groups_.push_back(g);
    for (int j : joints) {
      used_[j] = true;
      plan_.jointGroup_[j] = static_cast<int>(plan_.groups_.size()) - 1;
    }
    for (int b : bodies) known_[b] = true;
    return static_cast<int>(bodies.size());
  }

  // The driven body, pinned to a known one by the driver's joint and nothing else known.
  int crank() {
    const Constraint* p = pin_[driver_->joint];
    const int unknownSide = !isKnown(driver_->bi) ? driver_->bi : driver_->bj;
    const int knownSide = unknownSide == driver_->bi ? driver_->bj : driver_->bi;
    if (!isKnown(knownSide) || isKnown(unknownSide)) return 0;
    toKnown(unknownSide, k1j_);
    if (k1j_.size() != 1 || k1j_[0] != driver_->joint) return 0;
    Group g;
    g.kind = Kind::Crank;
    g.b1 = unknownSide;
    g.k1 = knownSide;
    g.p1 = pinOn(p, unknownSide);
    g.p1k = pinOther(p, unknownSide);
    g.sign = unknownSide == driver_->bi ? sys_.sigma : -sys_.sigma;
    return add(g, {driver_->joint}, {unknownSide});
  }

  // RP: a pin and a pin-in-slot (point on b1) to known bodies.
  int rp(int b1) {
    toKnown(b1, k1j_);
    if (k1j_.size() != 2) return 0;
    for (int order = 0; order < 2; ++order) {
      const int jp = k1j_[order], js = k1j_[1 - order];
      if (!pin_[jp] || !line_[js] || isSlider_[js] || line_[js]->bi != b1) continue;
      Group g;
      g.kind = Kind::RP;
      g.b1 = b1;
      g.k1 = otherBody(pin_[jp], b1);
      g.p1 = pinOn(pin_[jp], b1);
      g.p1k = pinOther(pin_[jp], b1);
      g.c1 = line_[js]->si;
      g.k2 = line_[js]->bj;
      g.u = line_[js]->sj;
      g.n = line_[js]->nj;
      return add(g, {jp, js}, {b1});
    }
    return 0;
  }

  // A dyad: b1 pinned to a known body and to b2, b2 with exactly one joint to known bodies, a
  // pin (RRR) or a slider in its slot (RRP).
  int dyad(int b1) {
    toKnown(b1, k1j_);
    if (k1j_.size() != 1 || !pin_[k1j_[0]]) return 0;
    const Constraint* to1 = pin_[k1j_[0]];
    for (int j : jointsOf(b1)) {
      const Constraint* c = pin_[j];
      if (used_[j] || !c) continue;
      const int b2 = otherBody(c, b1);
      if (b2 < 0 || known_[b2]) continue;
      toKnown(b2, k2j_);
      if (k2j_.size() != 1) continue;
      const int j2 = k2j_[0];
      Group g;
      g.b1 = b1;
      g.b2 = b2;
      g.k1 = otherBody(to1, b1);
      g.p1 = pinOn(to1, b1);
      g.p1k = pinOther(to1, b1);
      g.c1 = pinOn(c, b1);
      g.c2 = pinOn(c, b2);
      if (pin_[j2]) {
        g.kind = Kind::RRR;
        g.k2 = otherBody(pin_[j2], b2);
        g.p2 = pinOn(pin_[j2], b2);
        g.p2k = pinOther(pin_[j2], b2);
      } else if (isSlider_[j2] && line_[j2]->bi == b2) {
        g.kind = Kind::RRP;
        g.k2 = line_[j2]->bj;
        g.q2 = line_[j2]->si;
        g.u = line_[j2]->sj;
        g.n = line_[j2]->nj;
      } else {
        continue;
      }
      return add(g, {k1j_[0], j, j2}, {b1, b2});
    }
    return 0;
  }

  // A core body c held by three conditions, its blocks eliminated (core_group.h). -1 where it
  // is one but singular as assembled (no branch to keep).
  int core(int c, const Motion& at) {
    CoreGroup core;
    core.core = c;
    std::vector<int> joints, blocks;
    int rows = 0;
    for (int j : jointsOf(c)) {
      if (used_[j]) continue;
      const Constraint* p = pin_[j];
      const Constraint* l = line_[j];
      if (p) {
        const int other = otherBody(p, c);
        CoreLink link;
        link.s = pinOn(p, c);
        if (isKnown(other)) {
          link.pin = true;
          link.known = other;
          link.ks = pinOther(p, c);
          rows += 2;
          joints.push_back(j);
        } else {
          // A block: this pin and one slider in a known slot, nothing else.
          const int slide = blockSlider(other, j);
          if (slide < 0) continue;  // not a block: a joint for a later group
          const Constraint* sl = line_[slide];
          link.known = sl->bj;
          link.ks = sl->sj - (sl->si - pinOther(p, c));  // the line the pin point keeps to
          link.n = sl->nj;
          link.block = other;
          link.blockPin = pinOther(p, c);
          rows += 1;
          joints.push_back(j);
          joints.push_back(slide);
          blocks.push_back(other);
        }
        core.links.push_back(link);
      } else if (l->bi == c && !isSlider_[j] && isKnown(l->bj)) {
        CoreLink link;
        link.known = l->bj;
        link.s = l->si;
        link.ks = l->sj;
        link.n = l->nj;
        rows += 1;
        joints.push_back(j);
        core.links.push_back(link);
      } else if (isKnown(otherBody(l, c))) {
        return 0;  // a slider or a slot of its own on a known body: not this kind
      }
    }
    if (rows != 3) return 0;
    core.detSign = coreDetSign(core, at);
    if (core.detSign == 0) return -1;
    Group g;
    g.kind = Kind::Core;
    g.b1 = c;
    g.core = static_cast<int>(plan_.cores_.size());
    plan_.cores_.push_back(core);
    plan_.groups_.push_back(g);
    const int index = static_cast<int>(plan_.groups_.size()) - 1;
    for (int j : joints) {
      used_[j] = true;
      plan_.jointGroup_[j] = index;
    }
    known_[c] = true;
    for (int b : blocks) known_[b] = true;
    return 1 + static_cast<int>(blocks.size());
  }

  // The slider joint of a block body pinned by `pin` (and slid in a known slot, nothing
  // else), or -1.
  int blockSlider(int block, int pin) const {
    int slide = -1;
    for (int j : jointsOf(block)) {
      if (used_[j] || j == pin) continue;
      if (slide >= 0) return -1;
      slide = j;
    }
    if (slide < 0 || !isSlider_[slide] || line_[slide]->bi != block || !isKnown(line_[slide]->bj))
      return -1;
    return slide;
  }

  // Local directions and the drawn branches, from the assembled configuration.
  void branches(const Motion& at) {
    for (Group& g : plan_.groups_) {
      if (g.kind == Kind::Crank || g.kind == Kind::Core) continue;
      g.rot1 = direction(g.c1 - g.p1);
      g.d1 = (g.c1 - g.p1).norm();
      const BodyState& k1 = at.of(g.k1);
      const BodyState& b1 = at.of(g.b1);
      const Vec2 P1 = k1.pos(g.p1k), C = b1.pos(g.c1);
      if (g.kind == Kind::RRR) {
        g.rot2 = direction(g.c2 - g.p2);
        g.d2 = (g.c2 - g.p2).norm();
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
  std::vector<const Constraint*> pin_, line_;
  const Constraint* driver_ = nullptr;
  std::vector<bool> isSlider_, used_, known_;
  std::vector<int> first_, jointList_;
  std::vector<int> k1j_, k2j_;
};

std::optional<ClosedFormPlan> ClosedFormPlan::build(const Mechanism& m, const System& sys,
                                                    const Motion& at) {
  return Builder(m, sys).run(at);
}

}  // namespace linkage
