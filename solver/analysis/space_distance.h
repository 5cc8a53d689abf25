// Distances in space between moving parts of a machine whose bodies move in planes placed in
// space (linkage/space.h), with their first two derivatives per degree of crank, exact: from
// the points' motion in the world (Kinematics::motionInSpace), never from differences. What
// clearances and timing windows follow on such a machine, whatever planes the parts are in.
#pragma once

#include "analysis/cycle_sweep.h"

namespace linkage {

// A point's world position and its derivatives per degree of crank.
struct SpaceMotion {
  Vec3 r, dr, ddr;
};
SpaceMotion spaceMotion(const Kinematics& k, PointId p);

// |p - q|.
CycleReading spaceDistance(const Kinematics& k, PointId p, PointId q);

// From p to the segment a-b (two points of one body: a needle's blade): from its line beside
// it, from the nearer end beyond its ends (never negative; |d|' jumps where the two meet).
// `nearest`, when given: the segment's point nearest p (world).
CycleReading spaceDistanceToSegment(const Kinematics& k, PointId p, PointId a, PointId b,
                                    Vec3* nearest = nullptr);

// A straight slot's ends in the world at k's pose, with their derivatives per degree of crank: a
// moving body's slot in its body's plane (at the plane's depth), the ground's where it is
// written (x, y, z; at rest).
void slotEndsInSpace(const Kinematics& k, const Slot& s, SpaceMotion ends[2]);

// From p to the straight slot s as to the segment between its ends (spaceDistanceToSegment).
CycleReading spaceDistanceToSlot(const Kinematics& k, PointId p, const Slot& s,
                                 Vec3* nearest = nullptr);

// From p to the arc slot s: in its plane (its body's, at the plane's depth; the ground's where
// its points are written) the nearest point of the arc is on p's radius when p's foot in the
// plane is within the arc's span, so the distance is |(h, rho - R)|, h p's height off the plane
// and rho its foot's distance from the centre; beyond the span the nearer end's.
// `end`, when given: the end nearest is at (0: p0, 1: p1), -1 a point within the span.
CycleReading spaceDistanceToArc(const Kinematics& k, PointId p, const Slot& s,
                                Vec3* nearest = nullptr, int* end = nullptr);

// A slot at k's pose in its class's frame, as the canvas draws it: its two ends, or an arc in
// `pieces` pieces; and a world point of its plane in that frame.
std::vector<Vec2> slotCurveInClass(const Kinematics& k, const Slot& s, int pieces);
Vec2 intoSlotClass(const Mechanism& m, const Slot& s, const Vec3& w);

}  // namespace linkage
