// LU with partial pivoting for the small square Jacobians of mechanisms (up to a few tens of
// coordinates): unblocked, in preallocated storage, with the permutation parity and the pivot
// range kept for singularity tests and the sign of det J. Eigen's PartialPivLU spends more on
// its blocking and dispatch than on the arithmetic at these sizes (callgrind: 4x the flops
// for 9 x 9); above kBlockedFrom it is used instead, where blocking pays.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <vector>

namespace linkage {

class DenseLU {
 public:
  static constexpr int kBlockedFrom = 64;

  void resize(int n);
  // Factors A (n x n). Exactly singular pivots are kept (solve then gives inf/nan, which
  // callers reject); pivotRatio() tells how close to singular it is.
  void compute(const Eigen::MatrixXd& A);
  // x = A^-1 b, in place.
  void solveInPlace(Eigen::VectorXd& b) const;
  // x = A^-T b, in place (the same factors: forces from the kinematics' Jacobian).
  void solveTransposedInPlace(Eigen::VectorXd& b) const;

  double pivotRatio() const { return pivotRatio_; }
  int detSign() const { return detSign_; }

 private:
  int n_ = 0;
  Eigen::MatrixXd lu_;
  std::vector<int> perm_;  // row k of the factors is row perm_[k] of A
  Eigen::PartialPivLU<Eigen::MatrixXd> blocked_;
  mutable Eigen::VectorXd tmp_;
  double pivotRatio_ = 0;
  int detSign_ = 1;
};

}  // namespace linkage
