// The linear programme of a Chebyshev (minimax) fit, on COIN-OR CLP: minimise t over x and t
// subject to rows  c . x - t <= rhs  and plain rows  a . x <= limit,  added as the exchange finds
// them and re-solved from the last basis (the dual simplex: a row added keeps the old optimum
// dual feasible). Unknowns may be bounded below (a counterweight's mass is never negative).
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "linkage/geometry.h"

class ClpSimplex;

namespace linkage {

class ChebyshevLP {
 public:
  explicit ChebyshevLP(int unknowns);
  ~ChebyshevLP();
  void addRow(const double* c, double rhs);
  // sum of coefficient * x[index] <= limit
  void addLimit(const std::vector<std::pair<int, double>>& terms, double limit);
  void setLowerBound(int i, double lower);
  // False when the programme has no optimum (it is unbounded: no rows yet).
  bool solve(std::vector<double>& x, double& t);
  // Of the solutions whose t is at most `t` (the optimum solve() found), one that minimises
  // sum weights[i] x[i]: where the peak does not depend on some unknowns (a counterweight's
  // mass when its weight is across the measured component), the lightest, not a vertex's
  // arbitrary value. False (x untouched) when the second programme fails.
  bool solveLeast(const std::vector<double>& weights, double t, std::vector<double>& x);
  int rows() const;

 private:
  // Rows wait here and join the programme together at the next solve: CLP copies its matrix on
  // every addition.
  void pending(const int* cols, const double* e, int n, double upper);
  void flush();
  int n_;
  std::unique_ptr<ClpSimplex> lp_;
  std::vector<int> starts_{0}, cols_;
  std::vector<double> elements_, lower_, upper_;
};

}  // namespace linkage
