// The optimiser's objective differenced centrally in variable i (in the tests only: what the
// exact gradient of linkage/optimize.h is checked against).
#pragma once

#include <vector>

#include "linkage/optimize.h"

namespace linkage::test {

inline double centralDifference(const Kinematics& base, const OptimizeSpec& spec,
                                const std::vector<double>& x, size_t i, double h) {
  std::vector<double> up = x, down = x;
  up[i] += h;
  down[i] -= h;
  return (evaluate(base, spec, up, false).objective - evaluate(base, spec, down, false).objective) /
         (2 * h);
}

}  // namespace linkage::test
