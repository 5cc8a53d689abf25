#include "structure/structure.h"

#include <cmath>

#include "structure/independent_rows.h"

namespace linkage {

namespace {

// Gram-Schmidt with one re-orthogonalisation ("twice is enough"): a row whose remainder is below
// kDependent of its norm is in the span of the accepted rows. Rows are O(1) after scaling, so
// 1e-8 separates rounding (1e-15) from a genuinely independent row at any sane position.
constexpr double kDependent = 1e-8;

struct Basis {
  explicit Basis(int n) : Q(n, n) {}  // room for all n columns: no reallocation per row
  Eigen::MatrixXd Q;                  // the first `count` columns are orthonormal
  int count = 0;
  int size() const { return count; }
  auto basis() const { return Q.leftCols(count); }

  // Returns true and extends the basis if v is independent.
  bool add(Eigen::VectorXd v) {
    const double n0 = v.norm();
    if (n0 == 0 || count == Q.cols()) return false;
    v /= n0;
    for (int pass = 0; pass < 2; ++pass)
      if (count > 0) v -= basis() * (basis().transpose() * v);
    const double n1 = v.norm();
    if (n1 < kDependent) return false;
    Q.col(count++) = v / n1;
    return true;
  }
};

// The joint rows and the driver row: are they as many as the coordinates and independent with
// a margin that Gram-Schmidt could not dispute? Every remainder of the Gram-Schmidt below is at
// least the smallest singular value of the unit rows (in any order), so above 1e-5 it accepts
// them all; closer to singular than that is left to it.
constexpr double kProvedIndependent = 1e-5;
static_assert(kProvedIndependent > 100 * kDependent);

bool allRowsIndependent(const System& sys, const Eigen::VectorXd& q) {
  const int n = sys.nCoords();
  const int m = sys.nJointRows + (sys.driverRow >= 0 ? 1 : 0);
  if (m != n || (sys.driverRow >= 0 && sys.driverRow != sys.nJointRows)) return false;
  std::vector<int> rowMap(sys.nRows, -1);
  for (int r = 0; r < m; ++r) rowMap[r] = r;
  std::vector<BodyView> views;
  makeViews(sys, q, nullptr, views);
  SparseJacobian J = sparseJacobian(sys, rowMap, m);
  evalJacobian(sys, views, rowMap, J);
  for (int k = 0; k < sys.nBodies; ++k) J.J.col(3 * k + 2) /= sys.size;
  return rowsIndependent(J.J, kProvedIndependent);
}

}  // namespace

Structure analyzeStructure(const System& sys, const Eigen::VectorXd& q, int sparseFrom) {
  Structure s;
  const int n = sys.nCoords();
  s.coordinates = n;
  s.jointEquations = sys.nJointRows;
  s.gruebler = n - sys.nJointRows;

  if (n >= sparseFrom && allRowsIndependent(sys, q)) {
    // What the Gram-Schmidt below gives when it accepts every row.
    s.rank = sys.nJointRows;
    s.mobility = n - s.rank;
    for (int r = 0; r < sys.nJointRows; ++r) s.activeRows.push_back(r);
    s.driverMoves = sys.driverRow >= 0;
    if (s.driverMoves) s.activeRows.push_back(sys.driverRow);
    s.freeAfterDriver = 0;
    return s;
  }

  std::vector<BodyView> views;
  makeViews(sys, q, nullptr, views);
  std::vector<int> identity(sys.nRows);
  for (int r = 0; r < sys.nRows; ++r) identity[r] = r;
  Eigen::MatrixXd J(sys.nRows, n);
  evalJacobian(sys, views, identity, J);
  for (int k = 0; k < sys.nBodies; ++k) J.col(3 * k + 2) /= sys.size;

  Basis basis(n);
  for (int r = 0; r < sys.nJointRows; ++r) {
    if (basis.add(J.row(r).transpose())) {
      s.activeRows.push_back(r);
    } else {
      s.dependentRows.push_back(r);
    }
  }
  s.rank = basis.size();
  s.mobility = n - s.rank;
  for (int r : s.dependentRows) {
    for (const Row& c : sys.cons) {
      if (c.kind == Primitive::Hold || c.isDriver()) continue;
      if (r >= c.row && r < c.row + c.rows() &&
          (s.redundantJoints.empty() || s.redundantJoints.back() != c.joint))
        s.redundantJoints.push_back(c.joint);
    }
  }
  if (sys.driverRow >= 0) {
    s.driverMoves = basis.add(J.row(sys.driverRow).transpose());
    if (s.driverMoves) s.activeRows.push_back(sys.driverRow);
  }
  s.freeAfterDriver = n - basis.size();
  if (s.freeAfterDriver > 0) {
    // Complete the basis with unit vectors, angles first: an idle freedom is most often a body
    // spinning about a pin, and holding its angle is the natural fix. The accepted remainders
    // span the motions the driver leaves free.
    std::vector<int> order;
    for (int k = 0; k < sys.nBodies; ++k) order.push_back(3 * k + 2);
    for (int k = 0; k < sys.nBodies; ++k) {
      order.push_back(3 * k);
      order.push_back(3 * k + 1);
    }
    const int before = basis.size();
    for (int col : order) {
      if (basis.add(Eigen::VectorXd::Unit(n, col))) s.holdCoordinates.push_back(col);
      if (basis.size() == n) break;
    }
    s.nullBasis = basis.Q.middleCols(before, basis.size() - before);
    for (int k = 0; k < sys.nBodies; ++k)
      if (s.nullBasis.middleRows(3 * k, 3).norm() > 1e-7) s.freeBodies.push_back(k);
  }
  return s;
}

bool Structure::pointDetermined(const System& sys, const Eigen::VectorXd& q,
                                const PointLocation& p) const {
  if (freeAfterDriver == 0 || p.body < 0) return true;
  const int k = 3 * p.body;
  const Rot R{std::cos(q[k + 2]), std::sin(q[k + 2])};
  const Vec2 lever = perp(R * p.s) / sys.size;  // theta columns are scaled by 1 / size
  for (int z = 0; z < nullBasis.cols(); ++z) {
    const Vec2 v = Vec2(nullBasis(k, z), nullBasis(k + 1, z)) + nullBasis(k + 2, z) * lever;
    if (v.norm() > 1e-7) return false;
  }
  return true;
}

std::string describe(const Structure& s) {
  std::string out = std::to_string(s.coordinates / 3) + " moving bodies, " +
                    std::to_string(s.jointEquations) + " joint equations, Gruebler mobility " +
                    std::to_string(s.gruebler) + ", rank " + std::to_string(s.rank) +
                    ", mobility " + std::to_string(s.mobility);
  if (!s.dependentRows.empty())
    out += ", " + std::to_string(s.dependentRows.size()) + " redundant equation(s)";
  return out;
}

}  // namespace linkage
