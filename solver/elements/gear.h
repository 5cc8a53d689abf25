// The gear element: see gear.cpp (its equations on top) and linkage/elements.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

const ElementKind& gearElement();

}  // namespace linkage
