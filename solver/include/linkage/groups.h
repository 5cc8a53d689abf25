// The structural decomposition of a mechanism as drawn, by ids: the driven crank, then groups
// attached one after another to bodies already known, from the ground outwards (the one
// decomposition, structure/decomposition.h, that the closed-form solve uses too): what the
// transmission angles and the four-bar loops read (linkage/transmission.h, linkage/grashof.h)
// and what `linkage-cli info` lists.
#pragma once

#include <utility>
#include <vector>

#include "linkage/model.h"

namespace linkage {

// Crank: the driven body. Geared: a body pinned to a known one whose angle a gear or belt fixes.
// RRR: two links and three pins (a block in an arc slot counts as pinned at the arc's centre).
// RRP: a rod and a block in a straight slot. RP: a body pinned to a known one with a point in a
// known body's slot (straight or arc). PR: a body pinned to a known one whose straight slot
// holds a known body's point (a swinging slotted link: the feed bar on its eccentric). RS: a
// body pinned to a known one with a point kept by a ball rod at its length from a known body's
// point in space (the rocker of an RSSR: seed 004's W1 on its inclined axis). Triad:
// one body held by three conditions, with its slider blocks (the Wanzer triangle). Cam: a cam's
// follower, held to the cam's guide by its own pin or slider and moved by the cam. Other:
// anything else (solved by the general Newton).
enum class GroupKind { Crank, Geared, RRR, RRP, RP, PR, RS, Triad, Cam, Other };
// "crank", "geared", "RRR", "RRP", "RP", "PR", "RS", "triad", "cam", "other"
const char* toString(GroupKind k);

struct AssurGroup {
  using Kind = GroupKind;
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
