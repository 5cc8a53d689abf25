// The cam element: see cam.cpp (its equations in cam_row.h) and linkage/cam_joint.h.
#pragma once

#include "linkage/elements.h"

namespace linkage {

// Its descriptor, at place t of the registry's table.
ElementKind camElement(JointType t);

}  // namespace linkage
