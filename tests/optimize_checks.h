// The optimiser's objective differenced centrally in variable i (in the tests only: what the
// exact gradient of linkage/optimize.h is checked against).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

// The spec's gradient at m as drawn (moved by `offset` on every variable) against central
// differences of the objective, every variable.
inline void checkGradient(const Mechanism& m, const OptimizeSpec& spec, double offset) {
  Kinematics base;
  ASSERT_TRUE(base.load(m).ok());
  std::vector<double> x;
  for (const OptVariable& v : spec.variables) x.push_back(dimensionValue(m, v.name) + offset);
  const Evaluation e = evaluate(base, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  ASSERT_GT(e.objective, 1e-3);
  double largest = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = centralDifference(base, spec, x, i, 1e-5);
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (1 + std::abs(fd))) << spec.variables[i].name;
    largest = std::max(largest, std::abs(fd));
    std::printf("  %-26s gradient %.10g  central difference %.10g\n",
                spec.variables[i].name.c_str(), e.gradient[i], fd);
  }
  EXPECT_GT(largest, 1e-2);
}

// The objective's gradient at x against central differences (h 1e-5), every variable moving it,
// to 1e-6 of the difference and the objective.
inline void expectGradientAt(const Kinematics& k, const OptimizeSpec& spec,
                             const std::vector<double>& x) {
  const Evaluation e = evaluate(k, spec, x);
  ASSERT_TRUE(e.feasible) << e.why;
  ASSERT_GT(e.objective, 0);
  for (size_t i = 0; i < x.size(); ++i) {
    const double fd = centralDifference(k, spec, x, i, 1e-5);
    std::printf("  d objective / d %-24s %.9g (central differences %.9g)\n",
                spec.variables[i].name.c_str(), e.gradient[i], fd);
    EXPECT_GT(std::abs(fd), 1e-6 * e.objective) << spec.variables[i].name;
    EXPECT_NEAR(e.gradient[i], fd, 1e-6 * (std::abs(fd) + e.objective)) << spec.variables[i].name;
  }
}

// The result's design written in, at the crank angle where its first target's peak was found,
// with its accelerations: what the written design bears or feels there is what was reported.
inline ::testing::AssertionResult atThePeak(const OptimizeResult& r, Kinematics& after) {
  if (!after.load(r.design).ok()) return ::testing::AssertionFailure() << "the design loads not";
  after.setAccelerations(true);
  if (r.atAfter.measures.empty() || r.atAfter.measures[0].size() < 2)
    return ::testing::AssertionFailure() << "no peak's angle";
  const Status s = after.moveTo(r.atAfter.measures[0][1]);
  if (!s.ok()) return ::testing::AssertionFailure() << s.message;
  return ::testing::AssertionSuccess();
}

}  // namespace linkage::test
