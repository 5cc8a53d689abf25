// A proof, without a dense factorisation, that the rows of a large sparse matrix are independent
// with margin: the smallest singular value of A with each row scaled to unit length exceeds
// `sigma`. It exists so that the structure analysis (structure.h) can skip its dense
// Gram-Schmidt when every row is independent: each Gram-Schmidt remainder of unit rows, in any
// order, is at least that singular value, so all rows would be accepted there too.
//
// The test is an inertia count: A A^T - sigma^2 I (unit diagonal minus sigma^2) factored by
// sparse LDL^T has only positive pivots exactly when it is positive definite, i.e. when every
// singular value of A exceeds sigma. A rank-revealing QR would give per-column remainders in its
// own column order, which bound nothing about the singular values (triangular matrices can have
// all diagonal entries of 1 and be singular to rounding), so its verdict could differ from the
// ordered Gram-Schmidt's. Squaring costs half the digits: the rounding of the factorisation is
// bounded from the computed factors and must stay below a tenth of sigma^2, so sigma must be
// well above 1e-8 (1e-5 is safe at any size that fits in memory); false means "not proved".
#pragma once

#include <Eigen/SparseCore>

namespace linkage {

bool rowsIndependent(const Eigen::SparseMatrix<double>& A, double sigma);

}  // namespace linkage
