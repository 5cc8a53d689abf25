// The pin element: see pin.cpp (its equations on top) and linkage/elements.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

const ElementKind& pinElement();

}  // namespace linkage
