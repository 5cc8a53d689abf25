// The slider element: see slider.cpp (its equations on top) and linkage/elements.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

// Its descriptor, at place t of the registry's table.
ElementKind sliderElement(JointType t);

}  // namespace linkage
