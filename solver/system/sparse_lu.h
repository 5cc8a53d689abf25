// LU of the Jacobians of large mechanisms, where a dense LU costs n^3 but every row touches at
// most two bodies (six columns): Eigen's supernodal SparseLU with COLAMD column ordering. The
// pattern is fixed by the joints, so it is analysed once per system and only factorised at each
// Newton iterate. It answers what DenseLU answers, for the same uses: the sign of det J (to
// refuse crossing a singular position) and the range of U's pivots (the singularity test).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <memory>

#include "linkage/options.h"

namespace linkage {

// kSparseFrom (linkage/options.h): coordinates from which the solver's factorisations are sparse
// (NewtonSolver, and the structure analysis tries its sparse proof first). Measured on a full step
// of chains of four-bars (docs/benchmarks.md, Scale): below 64 DenseLU's unblocked LU is faster (63
// coordinates: 19 against 23 us); from 64 on DenseLU is Eigen's blocked LU, which the sparse LU
// beats at once (75: 82 against 28 us). An unblocked LU kept beyond 64 would gain at most 10 %
// up to about 80 coordinates on chains numbered in order and lose from about 70 when the file
// numbers bodies at random, which COLAMD's ordering does not mind.
class SparseLU {
 public:
  SparseLU();
  ~SparseLU();
  // Eigen's factors point into their own buffers and cannot be copied: a copy keeps the results
  // (sign, pivot ratio) and analyses the pattern again at its next compute().
  SparseLU(const SparseLU& other);
  SparseLU& operator=(const SparseLU& other);
  SparseLU(SparseLU&&) noexcept;
  SparseLU& operator=(SparseLU&&) noexcept;

  // The column ordering for A's pattern; every later compute() must pass the same pattern.
  void analyzePattern(const Eigen::SparseMatrix<double>& A);
  // Factors A. An exactly singular column leaves no usable factors: pivotRatio() is then 0.
  void compute(const Eigen::SparseMatrix<double>& A);
  // x = A^-1 b, in place.
  void solveInPlace(Eigen::VectorXd& b) const;
  // x = A^-T b, in place.
  void solveTransposedInPlace(Eigen::VectorXd& b) const;

  double pivotRatio() const { return pivotRatio_; }
  int detSign() const { return detSign_; }

 private:
  using Factor = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;
  std::unique_ptr<Factor> lu_;
  bool analysed_ = false;
  bool factored_ = false;
  mutable Eigen::VectorXd tmp_;
  double pivotRatio_ = 0;
  int detSign_ = 1;
};

}  // namespace linkage
