#include "linkage/mechanisms.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <tuple>

#include "linkage/elements.h"

namespace linkage {

namespace {

struct JointEnds {
  BodyId a, b;  // of point a; of point b or of the slot
};

JointEnds endsOf(const Mechanism& m, const Joint& j) {
  JointEnds e;
  if (const Point* p = m.point(j.a)) e.a = p->body;
  if (const Point* p = m.point(j.b))
    e.b = p->body;
  else if (const Slot* s = m.slot(j.slot))
    e.b = s->body;
  return e;
}

class Graph {
 public:
  explicit Graph(const Mechanism& m) : m_(m), parent_(m.bodies.size()) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (size_t i = 0; i < m.bodies.size(); ++i) index_[m.bodies[i].id] = static_cast<int>(i);
  }
  int index(BodyId id) const {
    auto it = index_.find(id);
    return it == index_.end() ? -1 : it->second;
  }
  bool moving(BodyId id) const {
    const int i = index(id);
    return i >= 0 && !m_.bodies[i].ground;
  }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(int a, int b) { parent_[find(a)] = find(b); }

 private:
  const Mechanism& m_;
  std::vector<int> parent_;
  std::map<BodyId, int> index_;
};

bool pinnedToGround(const Mechanism& m, const Graph& g, BodyId body) {
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const JointEnds e = endsOf(m, j);
    if ((e.a == body && e.b && !g.moving(e.b)) || (e.b == body && e.a && !g.moving(e.a)))
      return true;
  }
  return false;
}

// The bodies whose angle the driver or a coupling carried by the ground sets, pinned to it.
std::vector<bool> shafts(const Mechanism& m, const Graph& g) {
  std::vector<bool> out(m.bodies.size(), false);
  auto mark = [&](BodyId id) {
    if (g.moving(id) && pinnedToGround(m, g, id)) out[g.index(id)] = true;
  };
  if (m.driver)
    if (const Joint* d = m.joint(m.driver->joint)) {
      const JointEnds e = endsOf(m, *d);
      if (!g.moving(e.a)) mark(e.b);
      if (!g.moving(e.b)) mark(e.a);
    }
  for (const Joint& j : m.joints)
    if (kindOf(j).role == Role::Coupling && !g.moving(j.carrier)) {
      const JointEnds e = endsOf(m, j);
      mark(e.a);
      mark(e.b);
    }
  return out;
}

// Components of the linkages, then each shaft joined to the one linkage it drives.
void connect(const Mechanism& m, Graph& g, const std::vector<bool>& shaft) {
  std::vector<std::vector<int>> driven(m.bodies.size());
  for (const Joint& j : m.joints) {
    if (kindOf(j).role == Role::Coupling) continue;
    const JointEnds e = endsOf(m, j);
    if (!g.moving(e.a) || !g.moving(e.b)) continue;
    const int a = g.index(e.a), b = g.index(e.b);
    if (!shaft[a] && !shaft[b]) g.join(a, b);
    if (shaft[a] && !shaft[b]) driven[a].push_back(b);
    if (shaft[b] && !shaft[a]) driven[b].push_back(a);
  }
  for (size_t s = 0; s < driven.size(); ++s) {
    std::vector<int> roots;
    for (int b : driven[s]) roots.push_back(g.find(b));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.size() == 1) g.join(static_cast<int>(s), roots[0]);
  }
}

int ownerOfJoint(const Mechanism& m, const Joint& j, const Graph& g,
                 const std::vector<int>& mechOfBody, const std::vector<SubMechanism>& all) {
  const JointEnds e = endsOf(m, j);
  const int a = g.moving(e.a) ? mechOfBody[g.index(e.a)] : -1;
  const int b = g.moving(e.b) ? mechOfBody[g.index(e.b)] : -1;
  if (a < 0 || b < 0 || a == b) return std::max(a, b);
  if (kindOf(j).role == Role::Coupling) return b;
  return all[a].shaft ? b : a;
}

void matchEntries(const Mechanism& m, std::vector<SubMechanism>& all) {
  std::vector<std::tuple<int, int, int>> pairs;  // -common bodies, mechanism, entry
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t e = 0; e < m.mechanismEntries.size(); ++e) {
      int common = 0;
      for (BodyId b : m.mechanismEntries[e].bodies)
        common += std::count(all[i].bodies.begin(), all[i].bodies.end(), b) > 0;
      if (common > 0) pairs.emplace_back(-common, static_cast<int>(i), static_cast<int>(e));
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> taken(m.mechanismEntries.size(), false);
  for (const auto& [negCommon, i, e] : pairs) {
    if (all[i].entry >= 0 || taken[e]) continue;
    taken[e] = true;
    all[i].entry = e;
    const MechanismEntry& entry = m.mechanismEntries[e];
    if (!entry.name.empty()) all[i].name = entry.name;
    all[i].colour = entry.colour;
    all[i].hidden = entry.hidden;
  }
}

}  // namespace

std::vector<SubMechanism> subMechanisms(const Mechanism& m) {
  Graph g(m);
  const std::vector<bool> shaft = shafts(m, g);
  connect(m, g, shaft);
  std::vector<SubMechanism> all;
  std::vector<int> mechOfBody(m.bodies.size(), -1);
  std::map<int, int> ofRoot;
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    if (m.bodies[i].ground) continue;
    const int root = g.find(static_cast<int>(i));
    auto [it, fresh] = ofRoot.emplace(root, static_cast<int>(all.size()));
    if (fresh) {
      all.emplace_back();
      all.back().name = m.bodies[i].name;
    }
    all[it->second].bodies.push_back(m.bodies[i].id);
    mechOfBody[i] = it->second;
  }
  for (SubMechanism& s : all) s.shaft = s.bodies.size() == 1 && shaft[g.index(s.bodies[0])];
  for (const Joint& j : m.joints) {
    const int owner = ownerOfJoint(m, j, g, mechOfBody, all);
    if (owner >= 0) all[owner].joints.push_back(j.id);
  }
  matchEntries(m, all);
  return all;
}

int subMechanismOf(const std::vector<SubMechanism>& all, BodyId body) {
  for (size_t i = 0; i < all.size(); ++i)
    if (std::find(all[i].bodies.begin(), all[i].bodies.end(), body) != all[i].bodies.end())
      return static_cast<int>(i);
  return -1;
}

void setSubMechanismLook(Mechanism& m, const SubMechanism& s, const std::string& name,
                         const std::string& colour, bool hidden) {
  const bool known = s.entry >= 0 && s.entry < static_cast<int>(m.mechanismEntries.size());
  MechanismEntry e = known ? m.mechanismEntries[s.entry] : MechanismEntry{};
  const Body* first = s.bodies.empty() ? nullptr : m.body(s.bodies[0]);
  e.bodies = s.bodies;
  // The default name is not written: it follows the first body when that is renamed.
  e.name = first && name == first->name ? std::string() : name;
  e.colour = colour;
  e.hidden = hidden;
  const bool defaults = e.name.empty() && e.colour.empty() && !e.hidden && e.extras.empty();
  // Other entries give up these bodies (mechanisms joined by an edit): a body in two entries
  // would make the file ambiguous, and the reader refuses it.
  for (size_t i = 0; i < m.mechanismEntries.size(); ++i) {
    if (known && int(i) == s.entry) continue;
    std::vector<BodyId>& other = m.mechanismEntries[i].bodies;
    other.erase(std::remove_if(other.begin(), other.end(),
                               [&](BodyId b) {
                                 return std::find(s.bodies.begin(), s.bodies.end(), b) !=
                                        s.bodies.end();
                               }),
                other.end());
  }
  if (known && defaults)
    m.mechanismEntries.erase(m.mechanismEntries.begin() + s.entry);
  else if (known)
    m.mechanismEntries[s.entry] = std::move(e);
  else if (!defaults)
    m.mechanismEntries.push_back(std::move(e));
}

}  // namespace linkage
