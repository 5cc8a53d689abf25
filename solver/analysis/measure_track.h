// A LimitMeasure followed over a sweep of the crank (linkage/limits.h): its value at each sample,
// the root channel of its derivative, and the Limits made of them once the roots are found.
// Shared by findLimits and the parameter study, which follows several measures in one sweep.
#pragma once

#include <vector>

#include "analysis/crank_roots.h"
#include "analysis/cycle_sweep.h"
#include "linkage/limits.h"

namespace linkage {

// BadModel naming the problem when `what` cannot be followed on k (unknown ids, a direction
// that is not a finite non-zero vector, no driver speed), else success. A point must also be
// determined by the driver (Underconstrained otherwise).
Status checkMeasure(const Kinematics& k, const LimitMeasure& what);

// The measure's value (mm, or degrees for a body), and its first and second derivatives per
// degree of crank, exact at k's pose.
CycleReading readMeasure(const Kinematics& k, const LimitMeasure& what);

class MeasureTrack {
 public:
  // `what.direction` is normalised here.
  MeasureTrack(const Kinematics& k, LimitMeasure what);
  // Appends the sample at k's pose.
  void sample(const Kinematics& k);
  // Whether the last sample repeats the first (value modulo whole turns for a body, and g).
  bool repeats() const;
  // Makes the last sample the first one exactly, for a periodic sweep.
  void closePeriod() { channel.samples.back() = channel.samples.front(); }
  // False when the rate never rises above rounding: then there is no channel to search (its
  // sign changes would be noise), no extreme, and the stroke is 0 to rounding.
  bool moves() const;
  std::vector<RootChannel*> channels();
  // The Limits, after findRoots has searched channels().
  Limits result(bool periodic) const;

  RootChannel channel;
  std::vector<double> values;

 private:
  LimitMeasure what_;
  double size_;   // the mechanism's length scale
  double noise_;  // |rate| at or below this is rounding of a zero
};

}  // namespace linkage
