// The one structural decomposition of a mechanism: the driven crank, then groups attached one
// after another to bodies already known, from the ground outwards, as a designer decomposes it
// by hand (seed 001: crank 1, groups 2-3, 4-5, 6-7). The closed-form solve (kinematics/
// closed_form.h) solves these groups in this order; the transmission angles and the four-bar
// loops (linkage/transmission.h, linkage/grashof.h) read their kinds and order; so they agree.
//
// Topology only, over the rows the elements compile to (elements/rows.h): a group is a smallest
// connected set S of unknown bodies whose rows to S and to known bodies give at least 3 |S|
// scalar equations (a pin or a slider 2, a pin-in-slot or a gear 1, the driver's row 1), the
// generic count that fixes S once its neighbours are known. Sets are tried by size (1 to
// kMaxGroupBodies), among one size in order of the bodies (file order), preferring a set of a
// kind the closed form solves; so the order is the same every time. What no such set reaches
// (a class-IV group, a body the driver does not move) is left unresolved rather than guessed.
#pragma once

#include <vector>

#include "linkage/groups.h"
#include "system/system.h"

namespace linkage {

// Four bodies: the class-III triad with its three slider blocks (the Wanzer needle bar).
constexpr int kMaxGroupBodies = 4;

struct Group {
  // The bodies and rows of each kind, in this order (rows: indices into System::cons):
  // Crank:  {B}; the driver's pin, the driver's row.
  // Geared: {B}; B's pin to a known body, the coupling's Angles row that fixes B's angle.
  // RRR:    {B1, B2}; B1's outer pin, the pin B1-B2, B2's outer pin (a block in an arc slot is
  //         pinned at the arc's centre: its Coincident row).
  // RRP:    {rod B1, block B2}; B1's outer pin, the pin B1-B2, the block's OnLine and Angles
  //         rows in a known body's straight slot.
  // RP:     {B1}; B1's pin, the OnLine or OnCircle row of B1's point in a known body's slot.
  // PR:     {B1}; B1's pin, the OnLine row of a known body's point in B1's straight slot (a
  //         swinging slotted link: a feed bar on its eccentric).
  // RS:     {B1}; B1's pin, the Distance3 row of a ball rod from B1's point to a known body's.
  // Cam:    {follower B}; B's own joint to the cam's guide (a pin's Coincident row, or a
  //         slider's OnLine and Angles rows), then the Cam row over the known cam and guide.
  // Triad:  {core, its blocks}; one body held by three scalar conditions to known bodies:
  //         pins (two), its points on known bodies' straight slots (one), and slider blocks
  //         pinned to it running in known bodies' straight slots (one); rows in body order.
  // Other:  any other group; rows in order.
  using Kind = GroupKind;  // the one list of kinds, public (linkage/groups.h)
  Kind kind = Kind::Other;
  std::vector<int> bodies;
  std::vector<int> rows;
  // The elements (indices into Mechanism::joints) of those rows, each once, in row order.
  std::vector<int> joints;
};

struct Decomposition {
  std::vector<Group> groups;    // in solving order
  std::vector<int> unresolved;  // moving bodies no group reached, ascending
  // The group that solves each body (system index): groups.size() when unresolved.
  std::vector<int> groupOfBody;
  // Whether every body is in a group of a kind the closed form solves.
  bool closedForm() const;
};

// Hold rows (idle freedoms) are not the mechanism's and are left out.
Decomposition decompose(const System& sys);

}  // namespace linkage
