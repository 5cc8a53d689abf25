// The pin-in-slot element: see pin_in_slot.cpp (its equations on top) and linkage/elements.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

// Its descriptor, at place t of the registry's table.
ElementKind pinInSlotElement(JointType t);

}  // namespace linkage
