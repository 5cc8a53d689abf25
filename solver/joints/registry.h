// Every joint type, one entry each (registry.cpp): what the model, the compiler, the instant
// centres and the file format need to know of it. A joint type is its equations (a file in
// joints/: pin.h, pin_in_slot.h, slider.h) and its entry here; the rest of the solver reads the
// entry, not the type.
#pragma once

#include <string>
#include <string_view>

#include "linkage/model.h"
#include "solve/system.h"

namespace linkage {

// What a joint says by itself about the instant centre of the two bodies it joins.
enum class CentreRule : unsigned char {
  AtPoint,     // the joint's point (a pin)
  AtInfinity,  // at infinity, normal to the slot (a slider: relative translation)
  OnNormal,    // somewhere on the normal to the slot through the point (a pin-in-slot)
};

struct JointKind {
  JointType type;
  const char* name;  // in files and messages
  bool onSlot;       // joins point a to a slot; else point a to point b
  // The rows it compiles to, in order (solve/system.h; their equations are in joints/).
  RowKind rows[2];
  int rowKinds;
  CentreRule centre;
};

const JointKind& jointKind(JointType t);
// nullptr for a name no joint type has.
const JointKind* jointKindNamed(std::string_view name);
// The names for a message: "pin", "slider" or "pin-in-slot" (quoted).
std::string jointKindNames();

}  // namespace linkage
