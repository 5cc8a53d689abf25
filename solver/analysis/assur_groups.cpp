#include "analysis/assur_groups.h"

#include <algorithm>

namespace linkage {

namespace {

// A joint as the count sees it: the two bodies it holds together (indices into m.bodies) and
// its scalar equations.
struct Link {
  int a = -1, b = -1;
  int equations = 0;
  JointId id;
  JointType type = JointType::Pin;
  bool driver = false;
};

int bodyIndex(const Mechanism& m, BodyId id) {
  for (size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].id == id) return static_cast<int>(i);
  return -1;
}

int pointBody(const Mechanism& m, PointId p) {
  const Point* pt = m.point(p);
  return pt ? bodyIndex(m, pt->body) : -1;
}

std::vector<Link> links(const Mechanism& m) {
  std::vector<Link> out;
  for (const Joint& j : m.joints) {
    Link l;
    l.id = j.id;
    l.type = j.type;
    l.a = pointBody(m, j.a);
    if (j.type == JointType::Pin) {
      l.b = pointBody(m, j.b);
      l.driver = m.driver && m.driver->joint == j.id;
      l.equations = l.driver ? 3 : 2;
    } else {
      const Slot* s = m.slot(j.slot);
      l.b = s ? bodyIndex(m, s->body) : -1;
      l.equations = j.type == JointType::Slider ? 2 : 1;
    }
    if (l.a >= 0 && l.b >= 0 && l.a != l.b) out.push_back(l);
  }
  return out;
}

class Search {
 public:
  Search(const Mechanism& m, std::vector<Link> l) : links_(std::move(l)) {
    const int n = static_cast<int>(m.bodies.size());
    known_.assign(n, false);
    inSet_.assign(n, false);
    adjacent_.resize(n);
    for (int i = 0; i < n; ++i) known_[i] = m.bodies[i].ground;
    for (size_t k = 0; k < links_.size(); ++k) {
      adjacent_[links_[k].a].push_back(static_cast<int>(k));
      adjacent_[links_[k].b].push_back(static_cast<int>(k));
    }
  }

  // The next group, smallest first; empty when none is left.
  std::vector<int> next() {
    std::vector<int> frontier;
    for (int i = 0; i < static_cast<int>(known_.size()); ++i) {
      if (known_[i]) continue;
      for (int k : adjacent_[i])
        if (known_[other(k, i)]) {
          frontier.push_back(i);
          break;
        }
    }
    for (int size = 1; size <= kMaxGroupBodies; ++size)
      for (int f : frontier) {
        set_ = {f};
        inSet_[f] = true;
        const bool found = grow(size);
        if (found) return set_;
        inSet_[f] = false;
      }
    return {};
  }

  void markKnown(const std::vector<int>& s) {
    for (int b : s) {
      known_[b] = true;
      inSet_[b] = false;
    }
  }

  // The joints the group's count used: at least one end in the set, the other known or in it.
  std::vector<int> groupLinks(const std::vector<int>& s) const {
    std::vector<int> out;
    for (size_t k = 0; k < links_.size(); ++k) {
      const Link& l = links_[k];
      const bool ina = contains(s, l.a), inb = contains(s, l.b);
      if ((ina && (inb || known_[l.b])) || (inb && known_[l.a])) out.push_back(static_cast<int>(k));
    }
    return out;
  }

  const Link& link(int k) const { return links_[k]; }
  bool known(int b) const { return known_[b]; }

 private:
  int other(int k, int b) const { return links_[k].a == b ? links_[k].b : links_[k].a; }
  static bool contains(const std::vector<int>& s, int b) {
    return std::find(s.begin(), s.end(), b) != s.end();
  }

  // Grows set_ by unknown neighbours to `size` bodies and tests it; true with set_ the group.
  bool grow(int size) {
    if (static_cast<int>(set_.size()) == size) return fixes();
    for (size_t i = 0; i < set_.size(); ++i)
      for (int k : adjacent_[set_[i]]) {
        const int u = other(k, set_[i]);
        if (known_[u] || inSet_[u]) continue;
        set_.push_back(u);
        inSet_[u] = true;
        if (grow(size)) return true;
        inSet_[u] = false;
        set_.pop_back();
      }
    return false;
  }

  // The equations of the joints with an end in the set and the other known or in it, each
  // counted once (from its first end in the set).
  bool fixes() const {
    int equations = 0;
    for (int b : set_)
      for (int k : adjacent_[b]) {
        const Link& l = links_[k];
        const int other = l.a == b ? l.b : l.a;
        if (known_[other] || (inSet_[other] && (l.a == b))) equations += l.equations;
      }
    return equations >= 3 * static_cast<int>(set_.size());
  }

  std::vector<Link> links_;
  std::vector<bool> known_, inSet_;
  std::vector<std::vector<int>> adjacent_;
  std::vector<int> set_;
};

// Names the group's kind from its joints (see AssurGroup).
AssurGroup classify(const Mechanism& m, const Search& s, std::vector<int> bodies) {
  AssurGroup g;
  const std::vector<int> ks = s.groupLinks(bodies);
  for (int k : ks) g.joints.push_back(s.link(k).id);
  auto outer = [&](int b) {  // the joints of b to bodies outside the group
    std::vector<int> out;
    for (int k : ks) {
      const Link& l = s.link(k);
      if ((l.a == b && std::find(bodies.begin(), bodies.end(), l.b) == bodies.end()) ||
          (l.b == b && std::find(bodies.begin(), bodies.end(), l.a) == bodies.end()))
        out.push_back(k);
    }
    return out;
  };
  if (bodies.size() == 1) {
    const int b = bodies[0];
    g.bodies = {m.bodies[b].id};
    if (ks.size() == 1 && s.link(ks[0]).driver) {
      g.kind = AssurGroup::Kind::Crank;
      return g;
    }
    if (ks.size() == 2) {
      int pin = -1, slot = -1;
      for (int k : ks) {
        const Link& l = s.link(k);
        if (l.type == JointType::Pin && !l.driver) pin = k;
        // The body's own point in the known body's slot: a is the point's body.
        if (l.type == JointType::PinInSlot && l.a == b) slot = k;
      }
      if (pin >= 0 && slot >= 0) {
        g.kind = AssurGroup::Kind::RP;
        g.joints = {s.link(pin).id, s.link(slot).id};
      }
    }
    return g;
  }
  for (int b : bodies) g.bodies.push_back(m.bodies[b].id);
  if (bodies.size() != 2 || ks.size() != 3) return g;
  int middle = -1;
  for (int k : ks) {
    const Link& l = s.link(k);
    if ((l.a == bodies[0] && l.b == bodies[1]) || (l.a == bodies[1] && l.b == bodies[0]))
      middle = k;
  }
  const std::vector<int> o1 = outer(bodies[0]), o2 = outer(bodies[1]);
  if (middle < 0 || s.link(middle).type != JointType::Pin || o1.size() != 1 || o2.size() != 1)
    return g;
  const Link &l1 = s.link(o1[0]), &l2 = s.link(o2[0]);
  auto pin = [](const Link& l) { return l.type == JointType::Pin && !l.driver; };
  auto set = [&](AssurGroup::Kind kind, int rod, const Link& rodLink, const Link& other) {
    g.kind = kind;
    g.bodies = {m.bodies[rod].id, m.bodies[rod == bodies[0] ? bodies[1] : bodies[0]].id};
    g.joints = {rodLink.id, s.link(middle).id, other.id};
  };
  if (pin(l1) && pin(l2))
    set(AssurGroup::Kind::RRR, bodies[0], l1, l2);
  else if (pin(l1) && l2.type == JointType::Slider)
    set(AssurGroup::Kind::RRP, bodies[0], l1, l2);
  else if (pin(l2) && l1.type == JointType::Slider)
    set(AssurGroup::Kind::RRP, bodies[1], l2, l1);
  return g;
}

}  // namespace

int AssurDecomposition::groupOf(BodyId b) const {
  if (b == ground) return -1;
  for (const auto& [id, group] : solvedBy)
    if (id == b) return group;
  return static_cast<int>(groups.size());
}

AssurDecomposition decomposeAssur(const Mechanism& m) {
  AssurDecomposition d;
  if (const Body* g = m.ground()) d.ground = g->id;
  Search search(m, links(m));
  for (std::vector<int> s = search.next(); !s.empty(); s = search.next()) {
    std::sort(s.begin(), s.end());
    d.groups.push_back(classify(m, search, s));
    for (int b : s) d.solvedBy.emplace_back(m.bodies[b].id, static_cast<int>(d.groups.size()) - 1);
    search.markKnown(s);
  }
  for (size_t i = 0; i < m.bodies.size(); ++i)
    if (!search.known(static_cast<int>(i))) d.unresolved.push_back(m.bodies[i].id);
  return d;
}

}  // namespace linkage
