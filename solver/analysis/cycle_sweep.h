// Scalar quantities followed over one machine cycle (crank angle 0 to 360 of the driver) in one
// sweep, with the crank angles where each is stationary (its extremes) and where it crosses
// given levels, found by root finding on the exact motion (analysis/crank_roots.h), not by
// sampling. Shared by slot travel, clearance and the cycle (timing) diagram; the limits
// (measure_track.h) are the same idea for one measure.
#pragma once

#include <functional>
#include <vector>

#include "analysis/crank_roots.h"

namespace linkage {

// A quantity's value and its first and second derivatives per degree of crank, exact at a pose
// (from the solved velocities and accelerations).
struct CycleReading {
  double value = 0, d1 = 0, d2 = 0;
};
using CycleQuantity = std::function<CycleReading(const Kinematics&)>;

struct CycleTrack {
  CycleQuantity quantity;
  bool extremes = false;       // find the roots of d1 (only when d1 rises above `noise`)
  std::vector<double> levels;  // find where value crosses each (only when it moves)
  // Where d1 crosses +-each of these (dwells: the speed below a threshold).
  std::vector<double> slopeLevels;
  double noise = 0;  // |d1| at or below this everywhere: the quantity does not move
  // Called once the samples are in, before the roots are searched: may set the levels from them.
  std::function<void(CycleTrack&)> onSampled;

  // Filled by sweepCycle:
  std::vector<CycleReading> samples;  // at CycleSweep::crank
  bool periodic = false;  // the last sample repeats the first (value and d1, to 1e-9 of scale)
  std::vector<Root> stationary;                   // roots of d1, ascending
  std::vector<std::vector<Root>> crossings;       // per level, ascending
  std::vector<std::vector<Root>> slopeCrossings;  // per slope level: d1 = +level, then -level
  bool moves() const;
};

struct CycleSweep {
  Status status;              // the solver's, where the crank cannot turn fully
  std::vector<double> crank;  // the sampled angles, 0 to 360
};

// Samples every track at `steps` + 1 angles from 0 to 360 on a copy of k (k does not move),
// then finds the roots asked for, to `toleranceDeg`. A track repeats when its last sample's
// value and d1 equal the first's to 1e-9 of their largest size.
CycleSweep sweepCycle(const Kinematics& k, const std::vector<CycleTrack*>& tracks, int steps,
                      double toleranceDeg = kRootToleranceDeg);

// Seconds per degree of crank at the driver's speed: what turns time derivatives into
// derivatives per degree of crank.
double secondsPerDegree(const Kinematics& k);

}  // namespace linkage
