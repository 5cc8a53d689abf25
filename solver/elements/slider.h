// The slider element: see slider.cpp (its equations on top) and linkage/elements.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

const ElementKind& sliderElement();

}  // namespace linkage
