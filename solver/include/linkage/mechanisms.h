// The mechanisms of a machine: the parts that move together once the main shaft's angle is
// given. One driver turns a main shaft; gears and belts turn other shafts at their ratios; each
// shaft carries cranks and eccentrics that drive linkages of their own. A mechanism is a
// connected component of the moving bodies joined by joints (pins, slider blocks, pins in
// slots), with the ground and the shafts taken out first:
// - a shaft is a moving body pinned to the ground whose angle the driver or a gear or belt
//   (carried by the ground) sets;
// - a gear or a belt is not a joint of a linkage: it ties two shafts' angles, not their bodies;
// - a shaft that drives exactly one linkage belongs to it (a four-bar's crank is part of the
//   four-bar); a shaft that drives several, or none, is a mechanism of its own (the arm shaft of
//   a sewing machine with its needle bar and take-up lever on it; the rotary hook).
// A joint belongs to the mechanism of its bodies; between a shaft of its own and a linkage, to
// the linkage (the crank pin of a rod); a coupling to the mechanism of the shaft it drives (b).
#pragma once

#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage {

struct SubMechanism {
  std::vector<BodyId> bodies;   // file order
  std::vector<JointId> joints;  // file order
  bool shaft = false;           // a shaft on its own
  // From the file's entry (Mechanism::mechanismEntries) that shares the most bodies with it,
  // else the defaults: its first body's name, no colour, shown.
  int entry = -1;  // index in mechanismEntries, -1: none
  std::string name;
  std::string colour;  // "#rrggbb" or ""
  bool hidden = false;
};

// The mechanisms in the order of their first body in the file. Entries are matched greedily by
// the number of bodies in common (ties: the earlier mechanism, then the earlier entry); each
// entry names at most one mechanism, so after a split the larger part keeps the name.
std::vector<SubMechanism> subMechanisms(const Mechanism& m);

// The index of the mechanism a body belongs to; -1 for the ground or an unknown body.
int subMechanismOf(const std::vector<SubMechanism>& all, BodyId body);

// Sets the name, colour and visibility of a mechanism in the design: its entry (made when it has
// none) takes them and the mechanism's bodies as they are now. An entry left with the defaults
// (no name, no colour, shown, no unknown fields) is removed, so a file gains no empty entries.
void setSubMechanismLook(Mechanism& m, const SubMechanism& s, const std::string& name,
                         const std::string& colour, bool hidden);

}  // namespace linkage
