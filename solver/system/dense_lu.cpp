#include "system/dense_lu.h"

#include <cmath>

namespace linkage {

void DenseLU::resize(int n) {
  n_ = n;
  if (n >= kBlockedFrom) {
    blocked_ = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  } else {
    lu_.resize(n, n);
    perm_.resize(n);
  }
  tmp_.resize(n);
}

void DenseLU::compute(const Eigen::MatrixXd& A) {
  const int n = n_;
  double lo = INFINITY, hi = 0;
  int sign = 1;
  if (n >= kBlockedFrom) {
    blocked_.compute(A);
    const auto& m = blocked_.matrixLU();
    for (int i = 0; i < n; ++i) {
      const double d = m(i, i);
      lo = std::min(lo, std::abs(d));
      hi = std::max(hi, std::abs(d));
      if (d < 0) sign = -sign;
    }
    // Parity of the permutation: n minus its number of cycles.
    const auto& idx = blocked_.permutationP().indices();
    std::vector<char> seen(n, 0);
    for (int i = 0; i < n; ++i) {
      int len = 0;
      for (int j = i; !seen[j]; j = idx[j], ++len) seen[j] = 1;
      if (len > 0 && len % 2 == 0) sign = -sign;
    }
  } else {
    lu_ = A;
    for (int k = 0; k < n; ++k) perm_[k] = k;
    for (int k = 0; k < n; ++k) {
      int p = k;
      double best = std::abs(lu_(k, k));
      for (int i = k + 1; i < n; ++i)
        if (std::abs(lu_(i, k)) > best) best = std::abs(lu_(i, k)), p = i;
      if (p != k) {
        lu_.row(k).swap(lu_.row(p));
        std::swap(perm_[k], perm_[p]);
        sign = -sign;
      }
      const double d = lu_(k, k);
      lo = std::min(lo, std::abs(d));
      hi = std::max(hi, std::abs(d));
      if (d < 0) sign = -sign;
      if (d == 0) continue;
      const double inv = 1.0 / d;
      for (int i = k + 1; i < n; ++i) lu_(i, k) *= inv;
      // Column-major: the inner loop runs down a column, contiguous in memory.
      for (int j = k + 1; j < n; ++j) {
        const double a = lu_(k, j);
        if (a == 0) continue;
        double* col = &lu_(0, j);
        const double* l = &lu_(0, k);
        for (int i = k + 1; i < n; ++i) col[i] -= l[i] * a;
      }
    }
  }
  pivotRatio_ = n == 0 ? 1.0 : (hi > 0 ? lo / hi : 0.0);
  detSign_ = sign;
}

void DenseLU::solveInPlace(Eigen::VectorXd& b) const {
  const int n = n_;
  if (n >= kBlockedFrom) {
    tmp_ = blocked_.solve(b);
    b = tmp_;
    return;
  }
  for (int k = 0; k < n; ++k) tmp_[k] = b[perm_[k]];
  // Forward (unit lower), then back substitution, column by column.
  for (int j = 0; j < n; ++j) {
    const double x = tmp_[j];
    if (x != 0)
      for (int i = j + 1; i < n; ++i) tmp_[i] -= lu_(i, j) * x;
  }
  for (int j = n - 1; j >= 0; --j) {
    tmp_[j] /= lu_(j, j);
    const double x = tmp_[j];
    if (x != 0)
      for (int i = 0; i < j; ++i) tmp_[i] -= lu_(i, j) * x;
  }
  b = tmp_;
}

// P A = L U, so A^T = U^T L^T P: U^T w = b (forward), L^T y = w (back), x[perm[k]] = y[k]. Both
// run down the factors' columns, contiguous in memory.
void DenseLU::solveTransposedInPlace(Eigen::VectorXd& b) const {
  const int n = n_;
  if (n >= kBlockedFrom) {
    tmp_ = blocked_.transpose().solve(b);
    b = tmp_;
    return;
  }
  for (int j = 0; j < n; ++j) tmp_[j] = (b[j] - lu_.col(j).head(j).dot(tmp_.head(j))) / lu_(j, j);
  for (int j = n - 2; j >= 0; --j) tmp_[j] -= lu_.col(j).tail(n - 1 - j).dot(tmp_.tail(n - 1 - j));
  for (int k = 0; k < n; ++k) b[perm_[k]] = tmp_[k];
}

}  // namespace linkage
