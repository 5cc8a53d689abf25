// A slot as the dimensions move it (issue 29): what a transmission angle at a slot and a
// clearance to one need besides the points' sensitivities (linkage/sensitivity.h). A dimension
// moves a slot in its body's drawing (Dimension::slots: its ends and an arc's point on the way);
// an arc's centre c and radius rho follow from its three points P, which stay on the circle:
// (P - c) . (dP - dc) = rho drho for each. A point of the slot then goes where its body takes it
// plus that move in the drawing (Sensitivity::point for a point of a body drawn at a place).
#pragma once

#include "linkage/sensitivity.h"

namespace linkage {

// A slot's move in its body's drawing per unit of a dimension; zero where it moves no slot.
struct SlotChange {
  Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();  // its ends
  Vec2 centre = Vec2::Zero();                 // an arc's (a straight slot's: zero)
  double radius = 0;
};

SlotChange slotChange(const Mechanism& m, SlotId s, const Dimension& d);

}  // namespace linkage
