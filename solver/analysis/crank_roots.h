// Roots over a turn of the crank of quantities read from the pose: where a velocity component
// vanishes (limit positions), where a transmission angle is stationary or crosses a bound.
//
// The quantity g and its derivative dg with respect to the crank angle are exact at every pose
// (from the solved velocities and accelerations). Its samples at the sweep's angles bracket the
// roots: a change of sign between two angles, or, for a smooth g, a pair of roots inside one
// interval whose ends have the same sign, found where the cubic Hermite interpolant of (g, dg)
// dips through zero and confirmed by evaluating g there. Each bracket is narrowed by Newton on
// (g, dg), kept inside the bracket and halved instead whenever its step leaves the bracket or
// does not at least halve (a dwell's flat extreme is a multiple root, where Newton alone would
// crawl). A root is done when the bracket is narrower than the tolerance or a Newton step is
// below a tenth of it.
#pragma once

#include <functional>
#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

// g and dg/d(crank angle), per degree of crank, at one pose.
struct RootSample {
  double g = 0, dg = 0;
};
using RootFunction = std::function<RootSample(const Kinematics&)>;

struct Root {
  double crankDeg = 0;
  bool rising = false;  // g goes from negative to positive
  double value = 0;     // RootChannel::value at the root
};

struct RootChannel {
  RootFunction f;
  std::function<double(const Kinematics&)> value;  // optional: read at each root
  std::vector<RootSample> samples;                 // at the sweep's angles
  bool pairs = true;        // g is smooth: look for two roots within one interval
  std::vector<Root> roots;  // found, ascending
};

// The accuracy the design checks promise (degrees of crank).
constexpr double kRootToleranceDeg = 1e-9;

// Finds the roots of every channel between consecutive angles of `crank` (ascending; samples
// given at each). `probe` must stand at crank.front(); it is moved through the turn, forwards
// interval by interval, and stands at each root when its value is read. With `periodic`, the last
// sample is the first one again (the caller made it so), which decides the sign of a sample that is
// exactly zero at the end. A failure is the probe's: an angle it could not reach.
Status findRoots(Kinematics& probe, const std::vector<double>& crank,
                 const std::vector<RootChannel*>& channels, bool periodic,
                 double toleranceDeg = kRootToleranceDeg);

}  // namespace linkage
