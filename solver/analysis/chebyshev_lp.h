// The linear programme of a Chebyshev (minimax) fit, on COIN-OR CLP: minimise t over x and t
// subject to rows  c . x - t <= rhs  and bounds  d . (x_2k, x_2k+1) <= limit,  added as the
// exchange finds them and re-solved from the last basis (the dual simplex: a row added keeps
// the old optimum dual feasible).
#pragma once

#include <memory>
#include <vector>

#include "linkage/geometry.h"

class ClpSimplex;

namespace linkage {

class ChebyshevLP {
 public:
  explicit ChebyshevLP(int unknowns);
  ~ChebyshevLP();
  void addRow(const double* c, double rhs);
  void addBound(int k, const Vec2& d, double limit);
  // False when the programme has no optimum (it is unbounded: no rows yet).
  bool solve(std::vector<double>& x, double& t);
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
