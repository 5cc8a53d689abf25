#include "system/sparse_lu.h"

#include <cassert>
#include <cmath>

namespace linkage {

SparseLU::SparseLU() : lu_(std::make_unique<Factor>()) {}
SparseLU::~SparseLU() = default;
SparseLU::SparseLU(SparseLU&&) noexcept = default;
SparseLU& SparseLU::operator=(SparseLU&&) noexcept = default;

SparseLU::SparseLU(const SparseLU& other)
    : lu_(std::make_unique<Factor>()), pivotRatio_(other.pivotRatio_), detSign_(other.detSign_) {}

SparseLU& SparseLU::operator=(const SparseLU& other) {
  if (this != &other) *this = SparseLU(other);
  return *this;
}

void SparseLU::analyzePattern(const Eigen::SparseMatrix<double>& A) {
  if (!lu_) lu_ = std::make_unique<Factor>();
  lu_->analyzePattern(A);
  analysed_ = true;
  factored_ = false;
  tmp_.resize(A.rows());
}

void SparseLU::compute(const Eigen::SparseMatrix<double>& A) {
  if (!analysed_) analyzePattern(A);
  lu_->factorize(A);
  factored_ = lu_->info() == Eigen::Success;
  if (!factored_) {
    // A column with no usable pivot at all: det J = 0.
    pivotRatio_ = 0;
    detSign_ = 0;
    return;
  }
  // The singularity measure is the one DenseLU gives, min |u_ii| / max |u_ii| of an LU with
  // partial pivoting (SparseLU's default diagonal threshold of 1 is plain partial pivoting), of
  // J with its columns in COLAMD order instead of their natural order. Pivots depend on that
  // order, so the two ratios differ (on chains of four-bars the sparse one is about a third of
  // the dense one), but both fall to rounding level (1e-12 and below) at a singular J and are
  // proportional to the distance from it nearby, while kSingularPivot (newton.cpp) sits four
  // orders of magnitude from either: the verdicts agree. A condition estimate would cost several
  // more triangular solves per factorisation and be a different number from the one the
  // thresholds were measured on. Eigen has no accessor for U's diagonal: it is read as
  // SparseLU::absDeterminant() reads it, from the supernodes' diagonal blocks stored with L
  // (matrixL() exposes that supernodal matrix and its InnerIterator).
  const auto L = lu_->matrixL();
  const Eigen::Index n = A.cols();
  double lo = INFINITY, hi = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Factor::SCMatrix::InnerIterator it(L.m_mapL, j); it; ++it) {
      if (it.index() == j) {
        lo = std::min(lo, std::abs(it.value()));
        hi = std::max(hi, std::abs(it.value()));
        break;
      }
    }
  }
  pivotRatio_ = n == 0 ? 1.0 : (hi > 0 ? lo / hi : 0.0);
  detSign_ = static_cast<int>(lu_->signDeterminant());
}

void SparseLU::solveInPlace(Eigen::VectorXd& b) const {
  assert(factored_ && "SparseLU: solve without a usable factorisation");
  if (!factored_) {
    b.setConstant(NAN);  // as DenseLU with a zero pivot: callers reject non-finite results
    return;
  }
  tmp_ = lu_->solve(b);
  b = tmp_;
}

void SparseLU::solveTransposedInPlace(Eigen::VectorXd& b) const {
  if (!factored_) {
    b.setConstant(NAN);
    return;
  }
  tmp_ = lu_->transpose().solve(b);
  b = tmp_;
}

}  // namespace linkage
