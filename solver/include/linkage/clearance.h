// Clearance between moving parts over one turn of the crank: the distance from a point to
// another part (linkage/model.h's ClearancePart): a point of another body, a segment of another
// body (the part between two of its points: a needle, a blade), or another body's slot as
// drawn (its line or arc between its ends); beyond a segment's or a slot's ends, to the nearer
// end. Every local minimum, the closest approach, and where the point crosses the segment's or
// slot's line or circle (on the part itself: the two meet).
//
// A machine in space: the distance in the world, between points of any planes, or from a
// point to a segment (a slot there is refused); no crossings (the point need not be in the
// segment's plane).
//
// The distance and its first two derivatives with respect to the crank angle are exact at each
// pose (from the solved velocities and accelerations; for a slot, the point's motion relative
// to the slot's body). Every local minimum is a root of the distance's derivative, rising (where
// the two touch, the derivative jumps through zero there), bracketed on samples and refined to
// 1e-9 degree of crank by safeguarded Newton (analysis/crank_roots.h).
#pragma once

#include <cmath>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/timing.h"

namespace linkage {

struct ClearanceEvent {
  double crankDeg = NAN;  // in [0, 360)
  double distance = NAN;  // mm, >= 0
};

// Where the point crosses the line (or circle) of a segment or slot: `alongMm` from the part's
// first end (a segment's first point, a slot's first end) towards the other, in the part's
// body; on the part itself when 0 <= alongMm <= its length (the two meet there).
struct ClearanceCrossing {
  double crankDeg = NAN;
  double alongMm = NAN;
  bool onPart = false;
};

struct Clearance {
  // BadModel (unknown ids, no point on either side, a point to its own body's segment or slot),
  // Underconstrained (a point the driver does not determine), or the solver's status where the
  // crank cannot turn fully.
  Status status;
  std::vector<ClearanceEvent> minima;  // every local minimum, crank order
  ClearanceEvent closest;              // the smallest distance over the turn (one of the minima
                                       // when the motion repeats)
  std::vector<ClearanceCrossing> crossings;  // a segment's or slot's, crank order
  double partLengthMm = 0;                   // the segment's or slot's drawn length
  // A point that runs along the segment's or slot's line (a block's point in its own slot, a
  // needle point in its guide): its distance from the line is 0 throughout, and these are the
  // crank intervals where it is on the part itself (distance 0); each one's start is a minimum.
  bool runsAlong = false;
  std::vector<AngleInterval> onPart;
  // False when the motion does not repeat after one turn: then the ends of the turn count for
  // the closest, and minima are those inside it.
  bool periodic = true;
  // The distance at the sampled crank angles (0 to 360, for a curve; its minima are above).
  std::vector<double> crankDeg, distance;
  // Where the two things are at the closest approach (world coordinates, mm): the point, and
  // the other point or the nearest point of the segment or slot as drawn.
  Vec2 closestPoint = Vec2::Zero(), closestOther = Vec2::Zero();
  // The segment or slot as drawn at the closest approach (world, mm, from its first end): its
  // two ends, or points along an arc; empty for a point. The pose shown is seldom that one: a
  // figure draws the part where the point comes closest to it.
  std::vector<Vec2> closestPart;
  // A machine in space (linkage/space.h): the two at the closest approach in the world (mm);
  // the 2D ones above are then each in its own plane class's frame.
  Vec3 closestPoint3 = Vec3::Zero(), closestOther3 = Vec3::Zero();
};

struct ClearanceOptions {
  int steps = 360;  // sampling intervals over the turn that bracket the minima (at least 4)
};

// The distance between the two at k's pose (NaN when they are not a point and another part
// of k's mechanism that findClearance measures).
double clearanceAt(const Kinematics& k, const ClearancePart& a, const ClearancePart& b);

// Over crank angles 0 to 360 on a copy of k (k does not move).
Clearance findClearance(const Kinematics& k, const ClearancePart& a, const ClearancePart& b,
                        const ClearanceOptions& opt = {});

}  // namespace linkage
