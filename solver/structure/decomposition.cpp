#include "structure/decomposition.h"

#include <algorithm>
#include <set>

namespace linkage {

namespace {

// The search over the rows' bodies: known bodies grow from the ground outwards.
class Search {
 public:
  explicit Search(const System& sys) : sys_(sys) {
    const int n = sys.nBodies;
    known_.assign(n, false);
    inSet_.assign(n, false);
    adjacent_.resize(n);
    for (int r = 0; r < static_cast<int>(sys.cons.size()); ++r) {
      const Row& row = sys.cons[r];
      if (row.kind == Primitive::Hold) continue;
      for (int k = 0; k < row.bodies(); ++k)
        if (row.body[k] >= 0 && !listed(adjacent_[row.body[k]], r))
          adjacent_[row.body[k]].push_back(r);
    }
    tried_.assign(n, 0);
    for (int b = 0; b < n; ++b)
      if (touchesKnown(b)) pending_.insert(b);
  }

  // The next group, smallest first, a closed-form kind preferred among one size; false when
  // none is left. Only candidates whose neighbourhood changed since they were last tried are
  // tried again (a set's count changes only when a body next to it becomes known), so the
  // search is linear in a mechanism of bounded degree.
  bool next(Group& out) {
    for (int size = 1; size <= kMaxGroupBodies; ++size) {
      bool fallback = false;
      Group other;
      for (int f : pending_) {
        if (tried_[f] >= size) continue;
        set_ = {f};
        inSet_[f] = true;
        Group g;
        const bool found = grow(size, g, fallback ? nullptr : &other);
        inSet_[f] = false;
        for (int b : set_) inSet_[b] = false;
        if (found) return settle(g, out);
        tried_[f] = size;
        fallback = fallback || !other.bodies.empty();
      }
      if (fallback) return settle(other, out);
    }
    return false;
  }

  bool known(int b) const { return known_[b]; }

 private:
  static bool listed(const std::vector<int>& v, int x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  }
  bool isKnown(int b) const { return b < 0 || known_[b]; }

  bool touchesKnown(int b) const {
    for (int r : adjacent_[b]) {
      const Row& row = sys_.cons[r];
      for (int k = 0; k < row.bodies(); ++k)
        if (row.body[k] != b && isKnown(row.body[k])) return true;
    }
    return false;
  }

  // The group's bodies become known; the unknown bodies within reach of a set that now counts
  // differently (kMaxGroupBodies steps through unknown bodies) are to be tried again.
  bool settle(const Group& g, Group& out) {
    out = g;
    for (int b : g.bodies) {
      known_[b] = true;
      pending_.erase(b);
    }
    std::vector<int> layer = g.bodies, nextLayer, reached;
    for (int step = 0; step < kMaxGroupBodies && !layer.empty(); ++step) {
      nextLayer.clear();
      for (int b : layer)
        for (int r : adjacent_[b]) {
          const Row& row = sys_.cons[r];
          for (int k = 0; k < row.bodies(); ++k) {
            const int u = row.body[k];
            if (u < 0 || known_[u] || inSet_[u]) continue;
            inSet_[u] = true;  // as a visited mark, cleared below
            reached.push_back(u);
            nextLayer.push_back(u);
          }
        }
      std::swap(layer, nextLayer);
    }
    for (int u : reached) {
      inSet_[u] = false;
      tried_[u] = 0;
      if (touchesKnown(u)) pending_.insert(u);
    }
    return true;
  }

  // The rows with a body in the set and every other body known or in it, each once.
  std::vector<int> setRows() const {
    std::vector<int> rows;
    for (int b : set_)
      for (int r : adjacent_[b]) {
        const Row& row = sys_.cons[r];
        bool inside = true;
        for (int k = 0; k < row.bodies(); ++k)
          inside = inside && (isKnown(row.body[k]) || inSet_[row.body[k]]);
        if (inside && !listed(rows, r)) rows.push_back(r);
      }
    std::sort(rows.begin(), rows.end());
    return rows;
  }

  // Grows set_ by unknown neighbours to `size` bodies and tests it: true with a closed-form
  // kind in g; an Other group that fixes the set goes to `other` (when given and still empty).
  bool grow(int size, Group& g, Group* other) {
    if (static_cast<int>(set_.size()) == size) return test(g, other);
    for (size_t i = 0; i < set_.size(); ++i)
      for (int r : adjacent_[set_[i]]) {
        const Row& row = sys_.cons[r];
        for (int k = 0; k < row.bodies(); ++k) {
          const int u = row.body[k];
          if (isKnown(u) || inSet_[u]) continue;
          set_.push_back(u);
          inSet_[u] = true;
          if (grow(size, g, other)) return true;
          inSet_[u] = false;
          set_.pop_back();
        }
      }
    return false;
  }

  bool test(Group& g, Group* other) {
    const std::vector<int> rows = setRows();
    int equations = 0;
    for (int r : rows) equations += sys_.cons[r].rows();
    if (equations < 3 * static_cast<int>(set_.size())) return false;
    std::vector<int> bodies = set_;
    std::sort(bodies.begin(), bodies.end());
    g = classify(bodies, rows);
    if (g.kind != Group::Kind::Other) return true;
    if (other && other->bodies.empty()) *other = g;
    return false;
  }

  Group classify(const std::vector<int>& bodies, const std::vector<int>& rows) const;
  bool single(Group& g, int b, const std::vector<int>& rows) const;
  bool follower(Group& g, int b, const std::vector<int>& rows) const;
  bool dyad(Group& g, int b1, int b2, const std::vector<int>& rows) const;
  bool triad(Group& g, const std::vector<int>& bodies, const std::vector<int>& rows) const;

  // Rows of `rows` of a primitive joining exactly {x, y} (in either order).
  std::vector<int> between(const std::vector<int>& rows, Primitive kind, int x, int y) const {
    std::vector<int> out;
    for (int r : rows) {
      const Row& row = sys_.cons[r];
      if (row.kind != kind || row.bodies() != 2) continue;
      if ((row.body[0] == x && row.body[1] == y) || (row.body[0] == y && row.body[1] == x))
        out.push_back(r);
    }
    return out;
  }
  // The known body a row joins b to (two-body rows), or -2.
  int knownOther(const Row& row, int b) const {
    if (row.bodies() != 2) return -2;
    const int o = row.body[0] == b ? row.body[1] : row.body[1] == b ? row.body[0] : -2;
    return o >= -1 && isKnown(o) ? o : -2;
  }

  const System& sys_;
  std::vector<bool> known_, inSet_;
  std::vector<std::vector<int>> adjacent_;
  std::set<int> pending_;   // unknown bodies next to known ones, in file order
  std::vector<int> tried_;  // the size up to which a body's sets were tried and fixed nothing
  std::vector<int> set_;
};

bool Search::single(Group& g, int b, const std::vector<int>& rows) const {
  if (rows.size() != 2) return false;
  for (int order = 0; order < 2; ++order) {
    const Row &pin = sys_.cons[rows[order]], &other = sys_.cons[rows[1 - order]];
    if (pin.kind != Primitive::Coincident || knownOther(pin, b) < -1) continue;
    g.rows = {rows[order], rows[1 - order]};
    if (other.kind == Primitive::Angles) {
      // The driver's row on its own pin, or a coupling that fixes b's angle.
      double cb = 0;
      for (int k = 0; k < 3; ++k) cb += other.body[k] == b ? other.c[k] : 0;
      if (cb == 0) continue;
      if (other.isDriver() && other.joint != pin.joint) continue;
      g.kind = other.isDriver() ? Group::Kind::Crank : Group::Kind::Geared;
      return true;
    }
    if ((other.kind == Primitive::OnLine || other.kind == Primitive::OnCircle) &&
        other.body[0] == b && knownOther(other, b) >= -1) {
      g.kind = Group::Kind::RP;
      return true;
    }
    if (other.kind == Primitive::OnLine && other.body[1] == b && knownOther(other, b) >= -1) {
      g.kind = Group::Kind::PR;
      return true;
    }
    if (other.kind == Primitive::Distance3 && knownOther(other, b) >= -1) {
      g.kind = Group::Kind::RS;
      return true;
    }
  }
  return false;
}

// A cam's follower: b held to the cam's guide by its own joint (a pin's Coincident row, or a
// slider's OnLine and Angles rows) and moved by the Cam row over the known cam and guide.
bool Search::follower(Group& g, int b, const std::vector<int>& rows) const {
  int cam = -1;
  for (int r : rows)
    if (sys_.cons[r].kind == Primitive::Cam && sys_.cons[r].body[0] == b) cam = r;
  if (cam < 0) return false;
  const int guide = sys_.cons[cam].body[2];
  int pin = -1, line = -1, angle = -1;
  for (int r : rows) {
    if (r == cam) continue;
    const Row& row = sys_.cons[r];
    if (knownOther(row, b) != guide) return false;
    if (row.kind == Primitive::Coincident) pin = r;
    if (row.kind == Primitive::OnLine) line = r;
    if (row.kind == Primitive::Angles && !row.isDriver()) angle = r;
  }
  if (pin >= 0 && rows.size() == 2)
    g.rows = {pin, cam};
  else if (line >= 0 && angle >= 0 && rows.size() == 3)
    g.rows = {line, angle, cam};
  else
    return false;
  g.kind = Group::Kind::Cam;
  return true;
}

bool Search::dyad(Group& g, int b1, int b2, const std::vector<int>& rows) const {
  const std::vector<int> middle = between(rows, Primitive::Coincident, b1, b2);
  if (middle.size() != 1) return false;
  std::vector<int> outer1, outer2;
  for (int r : rows) {
    if (r == middle[0]) continue;
    const Row& row = sys_.cons[r];
    const bool on1 = knownOther(row, b1) >= -1, on2 = knownOther(row, b2) >= -1;
    if (!on1 && !on2) return false;
    (on1 ? outer1 : outer2).push_back(r);
  }
  auto pinOut = [&](const std::vector<int>& o) {
    return o.size() == 1 && sys_.cons[o[0]].kind == Primitive::Coincident;
  };
  // The block's straight slider: its point on a known body's line and its angle to that body.
  auto slides = [&](const std::vector<int>& o, int block) {
    if (o.size() != 2) return false;
    const Row &line = sys_.cons[o[0]], &angle = sys_.cons[o[1]];
    return line.kind == Primitive::OnLine && line.body[0] == block &&
           angle.kind == Primitive::Angles && !angle.isDriver() &&
           knownOther(angle, block) == line.body[1];
  };
  if (pinOut(outer1) && pinOut(outer2)) {
    g.kind = Group::Kind::RRR;
    g.bodies = {b1, b2};
    g.rows = {outer1[0], middle[0], outer2[0]};
    return true;
  }
  for (int order = 0; order < 2; ++order) {
    const int rod = order ? b2 : b1, block = order ? b1 : b2;
    const std::vector<int>&ro = order ? outer2 : outer1, &bo = order ? outer1 : outer2;
    if (!pinOut(ro) || !slides(bo, block)) continue;
    g.kind = Group::Kind::RRP;
    g.bodies = {rod, block};
    g.rows = {ro[0], middle[0], bo[0], bo[1]};
    return true;
  }
  return false;
}

bool Search::triad(Group& g, const std::vector<int>& bodies, const std::vector<int>& rows) const {
  for (int core : bodies) {
    int conditions = 0;
    bool ok = true;
    for (int b : bodies) {
      if (b == core) continue;
      // A block: pinned to the core, running in a known body's straight slot, nothing else.
      std::vector<int> own;
      for (int r : rows)
        if (sys_.cons[r].body[0] == b || sys_.cons[r].body[1] == b) own.push_back(r);
      const std::vector<int> pin = between(rows, Primitive::Coincident, b, core);
      int line = -1, angle = -1;
      for (int r : own) {
        const Row& row = sys_.cons[r];
        if (row.kind == Primitive::OnLine && row.body[0] == b && knownOther(row, b) >= -1) line = r;
        if (row.kind == Primitive::Angles && !row.isDriver() && knownOther(row, b) >= -1) angle = r;
      }
      ok = ok && own.size() == 3 && pin.size() == 1 && line >= 0 && angle >= 0 &&
           sys_.cons[angle].body[0] + sys_.cons[angle].body[1] - b == sys_.cons[line].body[1];
      conditions += 1;
    }
    for (int r : rows) {
      const Row& row = sys_.cons[r];
      if (knownOther(row, core) < -1) continue;
      if (row.kind == Primitive::Coincident)
        conditions += 2;
      else if (row.kind == Primitive::OnLine && row.body[0] == core)
        conditions += 1;
      else
        ok = false;
    }
    if (!ok || conditions != 3) continue;
    g.kind = Group::Kind::Triad;
    g.bodies = {core};
    for (int b : bodies)
      if (b != core) g.bodies.push_back(b);
    g.rows = rows;
    return true;
  }
  return false;
}

Group Search::classify(const std::vector<int>& bodies, const std::vector<int>& rows) const {
  Group g;
  g.bodies = bodies;
  g.rows = rows;
  int equations = 0;
  for (int r : rows) equations += sys_.cons[r].rows();
  const bool exact = equations == 3 * static_cast<int>(bodies.size());
  Group t = g;
  if (exact && bodies.size() == 1 && (single(t, bodies[0], rows) || follower(t, bodies[0], rows)))
    return t;
  if (exact && bodies.size() == 2 && dyad(t, bodies[0], bodies[1], rows)) return t;
  if (exact && triad(t, bodies, rows)) return t;
  return g;
}

}  // namespace

bool Decomposition::closedForm() const {
  if (!unresolved.empty()) return false;
  return std::none_of(groups.begin(), groups.end(),
                      [](const Group& g) { return g.kind == Group::Kind::Other; });
}

Decomposition decompose(const System& sys) {
  Decomposition d;
  Search search(sys);
  d.groupOfBody.assign(sys.nBodies, -1);
  for (Group g; search.next(g);) {
    for (int r : g.rows) {
      const int j = sys.cons[r].joint;
      if (j >= 0 && std::find(g.joints.begin(), g.joints.end(), j) == g.joints.end())
        g.joints.push_back(j);
    }
    for (int b : g.bodies) d.groupOfBody[b] = static_cast<int>(d.groups.size());
    d.groups.push_back(std::move(g));
  }
  for (int b = 0; b < sys.nBodies; ++b)
    if (!search.known(b)) {
      d.unresolved.push_back(b);
      d.groupOfBody[b] = static_cast<int>(d.groups.size());
    }
  return d;
}

}  // namespace linkage
