// A point's motion seen from a body that carries a slot, and the point's place relative to the
// slot's curve (along it, or its signed distance from it), each with its first and second
// derivatives per degree of crank, exact: the relative velocity and acceleration come from the
// solved motion of both bodies (a_rel = a_P - a_B(P) - 2 omega_B x v_rel), never differences.
#pragma once

#include "analysis/cycle_sweep.h"
#include "linkage/guide.h"

namespace linkage {

// Sketch coordinates of a world point in body b, and their derivatives per degree of crank.
struct RelativeMotion {
  Vec2 r, dr, ddr;
};
RelativeMotion relativeMotion(const Kinematics& k, const Kinematics::PointMotion& p, BodyId b);

// Arc length from the slot's first end (the slot's `along`), exact for a point on the curve.
CycleReading alongGuide(const Guide& g, const RelativeMotion& m);
// Signed distance from the line (along its normal) or from the circle (positive outside).
CycleReading offGuide(const Guide& g, const RelativeMotion& m);

// The distance from the slot as drawn: from its line or circle beside it, from the nearer end
// beyond its ends (so, never negative; |d|' jumps where the point crosses the slot itself).
CycleReading offDrawnSlot(const Guide& g, const RelativeMotion& m);

// The length |d| of a vector with its derivatives d', d'' (per degree), and |d|', |d|''.
CycleReading lengthOf(const Vec2& d, const Vec2& dd, const Vec2& ddd);
CycleReading lengthInSpace(const Vec3& d, const Vec3& dd, const Vec3& ddd);

}  // namespace linkage
