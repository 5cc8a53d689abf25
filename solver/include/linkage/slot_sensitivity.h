// A slot as the dimensions move it (issue 29): what a transmission angle at a slot and a
// clearance to one need besides the points' sensitivities (linkage/sensitivity.h). A dimension
// moves a slot in its body's drawing (Dimension::slots: its ends and an arc's point on the way);
// an arc's centre c and radius rho follow from its three points P, which stay on the circle:
// (P - c) . (dP - dc) = rho drho for each. A point of the slot then goes where its body takes it
// plus that move in the drawing (Sensitivity::point for a point of a body drawn at a place).
#pragma once

#include "linkage/guide.h"
#include "linkage/sensitivity.h"

namespace linkage {

// A slot's move in its body's drawing per unit of a dimension; zero where it moves no slot.
struct SlotChange {
  Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();  // its ends
  Vec2 centre = Vec2::Zero();                 // an arc's (a straight slot's: zero)
  double radius = 0;
};

SlotChange slotChange(const Mechanism& m, SlotId s, const Dimension& d);

// An arc's centre's and radius's moves for moves dp of its three points p (start, on the way,
// end), g the arc through them: what slotChange solves for each of a dimension's moves, in
// whatever frame p, dp and g share (a class frame on a machine in space).
void arcChange(const Guide& g, const Vec2 (&p)[3], const Vec2 (&dp)[3], Vec2& dc, double& drho);

}  // namespace linkage
