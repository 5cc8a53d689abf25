#include "linkage/groups.h"

#include "structure/decomposition.h"
#include "system/system.h"

namespace linkage {

const char* toString(GroupKind k) {
  static const char* const names[] = {"crank", "geared", "RRR",   "RRP", "RP",
                                      "PR",    "RS",     "triad", "cam", "other"};
  return names[static_cast<int>(k)];
}

int AssurDecomposition::groupOf(BodyId b) const {
  if (b == ground) return -1;
  for (const auto& [id, group] : solvedBy)
    if (id == b) return group;
  return static_cast<int>(groups.size());
}

AssurDecomposition decomposeAssur(const Mechanism& m) {
  AssurDecomposition out;
  if (const Body* g = m.ground()) out.ground = g->id;
  Status status;
  const std::optional<System> sys = compile(m, status);
  if (!sys) return out;
  const Decomposition d = decompose(*sys);
  for (const Group& g : d.groups) {
    AssurGroup a;
    a.kind = g.kind;
    for (int b : g.bodies) a.bodies.push_back(sys->bodyIds[b]);
    for (int j : g.joints) a.joints.push_back(m.joints[j].id);
    for (int b : g.bodies) out.solvedBy.emplace_back(sys->bodyIds[b], out.groups.size());
    out.groups.push_back(std::move(a));
  }
  for (int b : d.unresolved) out.unresolved.push_back(sys->bodyIds[b]);
  return out;
}

}  // namespace linkage
