// Limit positions and stroke: the extremes over one turn of the crank of a point's position
// along a direction, or of a body's angle, each where that velocity component vanishes.
//
// The quantity is sampled over the turn with its exact first and second derivatives with respect
// to the crank angle (the velocity and acceleration solves), and every sign change of the
// derivative, or pair of them within one sampling interval, is narrowed by safeguarded Newton to
// 1e-9 degree of crank (analysis/crank_roots.h): the extremes are found, not sampled. Every local
// extreme is reported, so a needle with a dwell (Wanzer, inversion 2) shows all four.
#pragma once

#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

// What to follow: a LimitMeasure (linkage/model.h).

// The direction a point's stroke is measured along by default: that of the ground slot it runs
// in (its own pin-in-slot, or a slider that carries its body, either way round), turned to
// point up, or right when it is horizontal; else +y. A slot on a moving body turns with it and
// gives no fixed direction, so it is not used.
Vec2 defaultDirection(const Mechanism& m, PointId p);

struct LocalExtreme {
  bool max = false;  // else a minimum
  double crankDeg = 0;
  double value = 0;  // mm, or degrees for a body
};

struct Limits {
  // BadModel (ids, options), Underconstrained (the point's motion is not determined), or the
  // solver's status where the crank cannot turn fully (Unreachable, Singular): then nothing
  // else is set.
  Status status;
  std::vector<LocalExtreme> extremes;  // every local extreme, crank order, angles in [0, 360)
  double min = 0, minDeg = 0;          // the smallest and largest value over the turn
  double max = 0, maxDeg = 0;
  double stroke = 0;  // max - min (a body that turns fully: 360)
  // False when the quantity does not change with the crank (no extremes, stroke 0).
  bool moves = true;
  // False when the motion does not repeat after one turn: extremes are then those inside
  // [0, 360] and the ends count for min and max.
  bool periodic = true;
};

struct LimitOptions {
  int steps = 360;  // sampling intervals over the turn (at least 4)
  double toleranceDeg = 1e-9;
};

// Follows `what` over crank angles 0 to 360 on a copy of k (k itself does not move).
Limits findLimits(const Kinematics& k, const LimitMeasure& what, const LimitOptions& opt = {});

}  // namespace linkage
