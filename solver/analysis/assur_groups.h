// The structural decomposition (structure/decomposition.h) of a mechanism as drawn, by ids: what
// the transmission angles and the four-bar loops read (linkage/transmission.h,
// linkage/grashof.h). The same groups, in the same order, as the closed-form solve uses.
#pragma once

#include <utility>
#include <vector>

#include "linkage/model.h"
#include "structure/decomposition.h"

namespace linkage {

struct AssurGroup {
  using Kind = Group::Kind;
  Kind kind = Kind::Other;
  std::vector<BodyId> bodies;   // in the kind's order (structure/decomposition.h)
  std::vector<JointId> joints;  // the elements of its rows, in their order
};

struct AssurDecomposition {
  std::vector<AssurGroup> groups;  // in solving order
  std::vector<BodyId> unresolved;  // moving bodies no group reached, file order
  // The group that solves a body: -1 for the ground, groups.size() when unresolved or unknown.
  int groupOf(BodyId b) const;
  std::vector<std::pair<BodyId, int>> solvedBy;  // every moving body a group solves, and which
  BodyId ground;
};

// Empty when the mechanism does not compile (a reference or a slot it cannot use).
AssurDecomposition decomposeAssur(const Mechanism& m);

}  // namespace linkage
