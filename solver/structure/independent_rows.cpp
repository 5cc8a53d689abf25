#include "structure/independent_rows.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>

namespace linkage {

namespace {

// gamma_k of rounding analysis: a bound on the relative error of a k-term inner product.
double gamma(Eigen::Index k) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  return k * u / (1 - k * u);
}

}  // namespace

bool rowsIndependent(const Eigen::SparseMatrix<double>& A, double sigma) {
  using Sparse = Eigen::SparseMatrix<double>;
  const Eigen::Index m = A.rows();
  if (m > A.cols()) return false;
  Eigen::VectorXd norm2 = Eigen::VectorXd::Zero(m);
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it) norm2[it.row()] += it.value() * it.value();
  if (!(norm2.minCoeff() > 0) || !norm2.allFinite()) return false;
  const Eigen::VectorXd invNorm = norm2.cwiseSqrt().cwiseInverse();
  const Sparse U = invNorm.asDiagonal() * A;
  const Sparse UT = U.transpose();
  Sparse G = U * UT;
  const double tau = sigma * sigma;
  for (Eigen::Index i = 0; i < m; ++i) G.coeffRef(i, i) -= tau;

  Eigen::SimplicialLDLT<Sparse> ldlt(G);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) return false;

  // Computed L and D are the exact factors of G + E with |E| <= gamma_{k+1} |L| D |L^T|, k the
  // longest row of L; ||E||_2 <= || |L| D |L^T| 1 ||_inf (symmetric, non-negative). Forming the
  // unit rows and G adds at most gamma_{r+2} || |U| |U^T| 1 ||_inf, r the longest row of A.
  const Sparse& L = ldlt.matrixL().nestedExpression();  // strictly lower; the diagonal is 1
  Eigen::VectorXi rowLength = Eigen::VectorXi::Ones(m);
  const Sparse absL = L.cwiseAbs();
  for (Eigen::Index j = 0; j < absL.outerSize(); ++j)
    for (Sparse::InnerIterator it(absL, j); it; ++it) ++rowLength[it.row()];
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m);
  Eigen::VectorXd t = absL.transpose() * ones + ones;
  t = ldlt.vectorD().cwiseProduct(t);
  t = absL * t + t;
  double err = gamma(rowLength.maxCoeff() + 1) * t.maxCoeff();
  Eigen::Index longestRow = 0;
  Eigen::VectorXi nnz = Eigen::VectorXi::Zero(m);
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (Sparse::InnerIterator it(A, j); it; ++it)
      longestRow = std::max<Eigen::Index>(longestRow, ++nnz[it.row()]);
  const Sparse absU = U.cwiseAbs();
  err += gamma(longestRow + 2) * (absU * (absU.transpose() * ones)).maxCoeff();
  return err <= 0.1 * tau;
}

}  // namespace linkage
