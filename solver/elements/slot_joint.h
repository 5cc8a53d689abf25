// What the kinds that run in a slot (slider, pin-in-slot) share: their fields, the guide of
// their slot, the bodies they join and where they are drawn.
#pragma once

#include <optional>

#include "linkage/elements.h"
#include "linkage/guide.h"

namespace linkage::slot_joint {

inline constexpr FieldSpec kFields[] = {{"a", FieldType::Point, 0, true},
                                        {"slot", FieldType::Slot, 0, true}};

inline std::string noCheck(const Mechanism&, const Joint&, const char*&) {
  return {};
}

// The guide of the joint's slot (its drawn curve), or none with why.
std::optional<Guide> guide(const Frames& f, const Joint& j, std::string& why);

// The pair the joint is about (the body of a, the slot's body), for its centre's data.
CentreData pair(const Mechanism& m, const Joint& j);

// The bodies and the slot; placed at a (a block along its slot there).
void symbol(const Mechanism& m, const Joint& j, JointSymbol& s);
void place(const Mechanism& m, const Joint& j, const Pose& pose, JointSymbol& s);

}  // namespace linkage::slot_joint
