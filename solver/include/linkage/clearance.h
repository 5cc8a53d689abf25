// Clearance between moving parts over one turn of the crank: the distance between two points
// of (possibly different) moving bodies, or between a point and another body's slot as drawn
// (its line or arc between its ends; beyond them, its nearer end), with every local minimum
// and the closest approach.
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

namespace linkage {

// One side of a clearance: a point, or (with `slot` set) a slot.
struct ClearanceItem {
  PointId point;
  SlotId slot;
  static ClearanceItem of(PointId p) { return {p, {}}; }
  static ClearanceItem of(SlotId s) { return {{}, s}; }
};

struct ClearanceEvent {
  double crankDeg = NAN;  // in [0, 360)
  double distance = NAN;  // mm, >= 0
};

struct Clearance {
  // BadModel (unknown ids, two slots, a point and a slot of one body), Underconstrained (a point
  // the driver does not determine), or the solver's status where the crank cannot turn fully.
  Status status;
  std::vector<ClearanceEvent> minima;  // every local minimum, crank order
  ClearanceEvent closest;              // the smallest distance over the turn
  // False when the motion does not repeat after one turn: then the ends of the turn count for
  // the closest, and minima are those inside it.
  bool periodic = true;
  // The distance at the sampled crank angles (0 to 360, for a curve; its minima are above).
  std::vector<double> crankDeg, distance;
  // Where the two things are at the closest approach (world coordinates, mm): the point of
  // `a` (or of `b` when `a` is the slot), and the other point or the nearest point of the
  // slot as drawn.
  Vec2 closestPoint = Vec2::Zero(), closestOther = Vec2::Zero();
};

struct ClearanceOptions {
  int steps = 360;  // sampling intervals over the turn that bracket the minima (at least 4)
};

// The distance between the two at k's pose (NaN when they are not a point and another point
// or another body's slot of k's mechanism).
double clearanceAt(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b);

// Over crank angles 0 to 360 on a copy of k (k does not move).
Clearance findClearance(const Kinematics& k, const ClearanceItem& a, const ClearanceItem& b,
                        const ClearanceOptions& opt = {});

}  // namespace linkage
