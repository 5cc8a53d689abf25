// The extremes of a sampled curve, placed between the samples with the solver's exact values:
// the stroke of a needle (the range of its position), its peak velocity and acceleration, and
// the crank angles where they happen.
#pragma once

#include <cmath>

#include "linkage/motion_samples.h"

namespace linkage {

struct Extreme {
  double crankDeg = NAN;  // in [0, 360) when the curve is periodic
  double value = NAN;
  // How it was found. Root: a zero of the exact derivative (the velocity for a position, the
  // acceleration for a velocity) by Brent's method: the angle to 1e-10 degrees. Minimised:
  // Brent's minimisation of the exact value between the two neighbouring samples (accelerations,
  // whose derivative the solver does not give): the value to rounding, the angle to about 1e-6
  // degrees (the curve is flat there). Sample: the largest sample (jerk, and the ends of a
  // sweep that stopped early or of a curve that does not repeat).
  enum class Method { Sample, Root, Minimised };
  Method method = Method::Sample;
};

struct Extremes {
  Status status;  // why there are none (the curve's status)
  Extreme max, min;
  double range() const { return max.value - min.value; }
  // The extreme of larger size (the peak velocity or acceleration, either sign).
  const Extreme& peak() const { return std::abs(max.value) >= std::abs(min.value) ? max : min; }
};

// Over the first revolution of periodic samples, else over all the samples there are.
Extremes extremesOf(const MotionSamples& s, const Quantity& q, Order order);

}  // namespace linkage
