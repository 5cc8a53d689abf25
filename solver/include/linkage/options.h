// Settings of the position solve and the tracker, for callers that measure what accuracy costs
// or compare the solver's paths on one mechanism (tests, benchmarks).
#pragma once

namespace linkage {

// Coordinates from which the solver's factorisations are sparse (solve/sparse_lu.h says why 64).
constexpr int kSparseFrom = 64;

struct NewtonOptions {
  int maxIterations = 12;
  // Converged when max |Phi| <= relTol * max(L, |x|, |y|): 1e-13 is a few hundred roundings of a
  // coordinate; looser values exist to measure what accuracy costs (docs/accuracy-and-speed.md).
  double relTol = 1e-13;
  // Tracking: a first correction larger than this fraction of L means the predictor is not near
  // this branch; the step is refused rather than let Newton wander to another branch.
  double maxFirstStep = 0.1;
};

struct KinematicsOptions {
  double maxStepDeg = 2.0;
  double minStepDeg = 1e-7;
  NewtonOptions newton;
  // Solve mechanisms made of a crank and dyads group by group in closed form (solve/closed_form.h)
  // instead of by Newton on all coordinates; the general solve remains the fallback.
  bool closedForm = true;
  // Compute accelerations at every step. Positions and velocities always are: the tracker's
  // predictor and its branch and dead-point checks need velocities, so accelerations are the
  // part of a step a caller can leave out. The closed-form groups then skip them (they come
  // back as NaN, never stale); the general solve computes them anyway, as its test that a step
  // stayed on its branch uses them.
  bool accelerations = true;
  // Coordinates from which the general solve factors J as a sparse matrix and the structure
  // analysis tries its sparse test first; tests set it to compare both on one mechanism.
  int sparseFrom = kSparseFrom;
};

}  // namespace linkage
