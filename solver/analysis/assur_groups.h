// The structure of a mechanism as a designer decomposes it: the driven crank, then Assur groups
// attached one after another to bodies already known, from the ground outwards (the paper of
// seed 001 does it by hand: crank 1, groups 2-3, 4-5, 6-7). Topology only: no positions.
//
// A group is a smallest connected set S of unknown bodies whose joints to S and to the known
// bodies give at least 3 |S| scalar equations (a pin or a slider 2, a pin-in-slot 1, the
// driver's pin 3): the generic count that fixes S once its neighbours are known. Sets are tried
// by size (1 to kMaxGroupBodies), and among one size in file order, so the order is the same
// every time. What no such set reaches (a class-IV group, a body the driver does not move) is
// left unresolved rather than guessed.
//
// The transmission angles (linkage/transmission.h) and the four-bar loops' frame and input
// (linkage/grashof.h) are read from this order.
#pragma once

#include <utility>
#include <vector>

#include "linkage/model.h"

namespace linkage {

// Four bodies: the class-III triad with its slider blocks (the Wanzer needle bar) is one group.
constexpr int kMaxGroupBodies = 4;

struct AssurGroup {
  // Crank: the body the driver turns relative to a known body.
  // RRR: links B1, B2, the outer pin of B1 to a known body, their middle pin, the outer pin of
  //      B2 to a known body.
  // RRP: rod B1 and block B2, the rod's outer pin, the rod-block pin, the block's slider on a
  //      known body's slot (or a known body's point in the block's slot).
  // RP:  B1 with its outer pin and a point of its own in a known body's slot (pin-in-slot).
  // Other: any other group; its joints are listed in file order.
  enum class Kind { Crank, RRR, RRP, RP, Other };
  Kind kind = Kind::Other;
  std::vector<BodyId> bodies;   // Crank, RP: {B1}; RRR, RRP: {B1, B2}
  std::vector<JointId> joints;  // as listed above
};

struct AssurDecomposition {
  std::vector<AssurGroup> groups;  // in solving order
  std::vector<BodyId> unresolved;  // moving bodies no group reached, file order
  // The group that solves a body: -1 for the ground, groups.size() when unresolved or unknown.
  int groupOf(BodyId b) const;
  std::vector<std::pair<BodyId, int>> solvedBy;  // every moving body a group solves, and which
  BodyId ground;
};

AssurDecomposition decomposeAssur(const Mechanism& m);

}  // namespace linkage
