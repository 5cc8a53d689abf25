// The optimiser's objective differenced centrally in variable i (in the tests only: what the
// exact gradient of linkage/optimize.h is checked against).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "linkage/optimize.h"
#include "linkage/sensitivity.h"

namespace linkage::test {

inline double centralDifference(const Kinematics& base, const OptimizeSpec& spec,
                                const std::vector<double>& x, size_t i, double h) {
  std::vector<double> up = x, down = x;
  up[i] += h;
  down[i] -= h;
  return (evaluate(base, spec, up, false).objective - evaluate(base, spec, down, false).objective) /
         (2 * h);
}

// A dimension's value as dimensions() reads it from m's drawing; NaN for a name m does not have.
inline double dimensionValue(const Mechanism& m, const std::string& name) {
  for (const Dimension& d : dimensions(m))
    if (d.name == name) return d.value;
  return NAN;
}

}  // namespace linkage::test
