#include "analysis/chebyshev_lp.h"

#include <ClpSimplex.hpp>
#include <algorithm>
#include <cmath>

namespace linkage {

ChebyshevLP::ChebyshevLP(int unknowns) : n_(unknowns), lp_(std::make_unique<ClpSimplex>()) {
  lp_->setLogLevel(0);
  // The exchange asks for peaks to 1e-9 of their size: CLP's default tolerances (1e-7) would let
  // a row stay violated by more than that and the exchange add it again and again.
  lp_->setPrimalTolerance(1e-11);
  lp_->setDualTolerance(1e-11);
  lp_->scaling(0);
  lp_->resize(0, n_ + 1);
  for (int i = 0; i < n_; ++i) lp_->setColumnBounds(i, -COIN_DBL_MAX, COIN_DBL_MAX);
  lp_->setColumnBounds(n_, 0, COIN_DBL_MAX);  // t: a peak is never negative
  lp_->setObjectiveCoefficient(n_, 1);
}

ChebyshevLP::~ChebyshevLP() = default;

void ChebyshevLP::pending(const int* cols, const double* e, int n, double upper) {
  cols_.insert(cols_.end(), cols, cols + n);
  elements_.insert(elements_.end(), e, e + n);
  starts_.push_back(static_cast<int>(cols_.size()));
  lower_.push_back(-COIN_DBL_MAX);
  upper_.push_back(upper);
}

void ChebyshevLP::flush() {
  if (upper_.empty()) return;
  lp_->addRows(static_cast<int>(upper_.size()), lower_.data(), upper_.data(), starts_.data(),
               cols_.data(), elements_.data());
  starts_.assign(1, 0);
  cols_.clear();
  elements_.clear();
  lower_.clear();
  upper_.clear();
}

void ChebyshevLP::addRow(const double* c, double rhs) {
  std::vector<int> cols(n_ + 1);
  std::vector<double> e(c, c + n_);
  for (int i = 0; i <= n_; ++i) cols[i] = i;
  e.push_back(-1);
  pending(cols.data(), e.data(), n_ + 1, rhs);
}

void ChebyshevLP::addLimit(const std::vector<std::pair<int, double>>& terms, double limit) {
  std::vector<int> cols;
  std::vector<double> e;
  for (const auto& [i, c] : terms) {
    cols.push_back(i);
    e.push_back(c);
  }
  pending(cols.data(), e.data(), static_cast<int>(cols.size()), limit);
}

void ChebyshevLP::setLowerBound(int i, double lower) {
  lp_->setColumnLower(i, lower);
}

int ChebyshevLP::rows() const {
  return lp_->numberRows() + static_cast<int>(upper_.size());
}

bool ChebyshevLP::solve(std::vector<double>& x, double& t) {
  flush();
  lp_->dual();
  if (!lp_->isProvenOptimal()) lp_->primal();
  if (!lp_->isProvenOptimal()) return false;
  const double* s = lp_->primalColumnSolution();
  x.assign(s, s + n_);
  t = s[n_];
  return true;
}

bool ChebyshevLP::solveLeast(const std::vector<double>& weights, double t, std::vector<double>& x) {
  flush();
  // t held at its optimum (and CLP's tolerance above it), the objective moved to the weights;
  // both put back for the next exchange.
  lp_->setColumnUpper(n_, t + std::max(1e-12, 1e-12 * std::abs(t)));
  lp_->setObjectiveCoefficient(n_, 0);
  for (int i = 0; i < n_; ++i) lp_->setObjectiveCoefficient(i, weights[i]);
  lp_->primal();
  const bool ok = lp_->isProvenOptimal();
  if (ok) {
    const double* s = lp_->primalColumnSolution();
    x.assign(s, s + n_);
  }
  for (int i = 0; i < n_; ++i) lp_->setObjectiveCoefficient(i, 0);
  lp_->setObjectiveCoefficient(n_, 1);
  lp_->setColumnUpper(n_, COIN_DBL_MAX);
  return ok;
}

}  // namespace linkage
