// Constraint forces group by group: see group_forces.h.
#include "analysis/group_forces.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace linkage {

namespace {

// A group's unknowns: three a body, four bodies at most (structure/decomposition.h): storage
// on the stack, no allocation per pose.
using GroupMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
using GroupVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 12, 1>;
using Row3 = Eigen::Matrix<double, 1, 3>;

// Solves A x = b in place (b becomes x) by Gaussian elimination with partial pivoting: at a
// group's 3 to 12 unknowns a plain loop beats a general LU's dispatch (a fixed 6 x 6
// PartialPivLU cost half a pose's forces). False at a zero pivot.
template <int N, class Mat, class Vec>
bool eliminate(Mat& A, Vec& b, int size) {
  const int n = N == Eigen::Dynamic ? size : N;  // known at compile time: loops unrolled
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(A(i, k)) > std::abs(A(p, k))) p = i;
    if (A(p, k) == 0) return false;
    if (p != k) {
      A.row(k).swap(A.row(p));
      std::swap(b[k], b[p]);
    }
    const double inv = 1 / A(k, k);
    for (int i = k + 1; i < n; ++i) {
      const double f = A(i, k) * inv;
      if (f == 0) continue;
      for (int j = k + 1; j < n; ++j) A(i, j) -= f * A(k, j);
      b[i] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    double v = b[k];
    for (int j = k + 1; j < n; ++j) v -= A(k, j) * b[j];
    b[k] = v / A(k, k);
  }
  return true;
}

Row3 cross3(const Row3& a, const Row3& b) {
  return Row3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

// A^T x = r for a 2 x 3 block A of full rank whose null vector is n (r in A^T's range): the two
// equations whose minor is the largest, |n_i| for the one left out. False when n is zero.
bool solveTwoOfThree(const Eigen::Matrix<double, 2, 3>& A, const Row3& n, const Row3& r,
                     double* x) {
  int i = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[i])) i = k;
  const int j = i == 0 ? 1 : 0, l = i == 2 ? 1 : 2;
  const double det = A(0, j) * A(1, l) - A(1, j) * A(0, l);
  if (det == 0) return false;
  x[0] = (r[j] * A(1, l) - A(1, j) * r[l]) / det;
  x[1] = (A(0, j) * r[l] - r[j] * A(0, l)) / det;
  return true;
}

}  // namespace

// A dyad's rows: 0 those that touch only its first body, 1 both, 2 only its second.
int GroupForces::dyadPart(const PlannedRow& r) {
  bool touches[2] = {false, false};
  for (int b : r.local)
    if (b == 0 || b == 1) touches[b] = true;
  return touches[0] && touches[1] ? 1 : touches[1] ? 2 : 0;
}

void GroupForces::prepare(const System& sys, const Decomposition& d) {
  rows_.clear();
  plans_.clear();
  for (auto g = d.groups.rbegin(); g != d.groups.rend(); ++g) {
    Plan p;
    p.first = static_cast<int>(rows_.size());
    p.count = static_cast<int>(g->rows.size());
    p.nBodies = static_cast<int>(g->bodies.size());
    for (int i = 0; i < std::min(p.nBodies, 4); ++i) p.bodies[i] = g->bodies[i];
    int scalars[3] = {0, 0, 0};
    for (int r : g->rows) {
      PlannedRow pr;
      pr.row = r;
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < std::min(p.nBodies, 4); ++i)
          if (sys.cons[r].body[k] == g->bodies[i]) pr.local[k] = i;
      scalars[dyadPart(pr)] += sys.cons[r].rows();
      rows_.push_back(pr);
    }
    if (p.nBodies == 2 && scalars[0] == 2 && scalars[1] == 2 && scalars[2] == 2) {
      const auto first = rows_.begin() + p.first;
      std::stable_sort(first, rows_.end(), [](const PlannedRow& a, const PlannedRow& b) {
        return dyadPart(a) < dyadPart(b);
      });
      p.dyadShared = static_cast<int>(
          std::count_if(first, rows_.end(), [](const PlannedRow& r) { return dyadPart(r) == 0; }));
      p.dyadOwn2 =
          p.count - static_cast<int>(std::count_if(
                        first, rows_.end(), [](const PlannedRow& r) { return dyadPart(r) == 2; }));
    }
    plans_.push_back(p);
  }
  blocks_.resize(rows_.size());
  S_.setZero(3 * sys.nBodies);
}

void GroupForces::jacobians(const System& sys, const std::vector<BodyView>& views, const Plan& p) {
  for (int i = p.first; i < p.first + p.count; ++i)
    rowJacobian(sys, views, sys.cons[rows_[i].row], blocks_[i]);
}

// x: the group's rows' multipliers in plan order. Into lambda; and what each row puts on the
// bodies outside the group (groups solved later) into S.
void GroupForces::distribute(const System& sys, const Plan& p, const double* x) {
  Eigen::VectorXd& lambda = *lambda_;
  int o = 0;
  for (int i = p.first; i < p.first + p.count; ++i) {
    const Row& row = sys.cons[rows_[i].row];
    const Block& B = blocks_[i];
    for (int e = 0; e < row.rows(); ++e, ++o) {
      lambda[row.row + e] = x[o];
      for (int k = 0; k < 3; ++k)
        if (row.body[k] >= 0 && rows_[i].local[k] < 0)
          S_.segment<3>(3 * row.body[k]) += B.block<1, 3>(e, 3 * k).transpose() * x[o];
    }
  }
}

bool GroupForces::solve(const System& sys, const std::vector<BodyView>& views,
                        const Eigen::VectorXd& Q, Eigen::VectorXd& lambda) {
  Q_ = &Q;
  lambda_ = &lambda;
  S_.setZero(3 * sys.nBodies);
  lambda.setConstant(sys.nRows, NAN);
  for (const Plan& p : plans_) {
    jacobians(sys, views, p);
    const bool ok = p.dyadShared >= 0 && solveDyad(sys, p) ? true
                    : p.nBodies == 1                       ? solveGroup<3>(sys, p)
                    : p.nBodies == 2                       ? solveGroup<6>(sys, p)
                                     : p.nBodies <= 4 && solveGroup<Eigen::Dynamic>(sys, p);
    if (!ok) return false;
  }
  return true;
}

// The group's rows' blocks transposed into A^T (its bodies' coordinates by its scalar rows);
// A^T x = Q - S over its bodies.
template <int N>
bool GroupForces::solveGroup(const System& sys, const Plan& p) {
  using Mat = std::conditional_t<N == Eigen::Dynamic, GroupMatrix, Eigen::Matrix<double, N, N>>;
  using Vec = std::conditional_t<N == Eigen::Dynamic, GroupVector, Eigen::Matrix<double, N, 1>>;
  const int m = 3 * p.nBodies;
  Mat At = Mat::Zero(m, m);
  int o = 0;
  for (int i = p.first; i < p.first + p.count; ++i) {
    const Row& row = sys.cons[rows_[i].row];
    if (o + row.rows() > m) return false;
    for (int k = 0; k < 3; ++k)
      if (const int b = rows_[i].local[k]; b >= 0)
        for (int e = 0; e < row.rows(); ++e)
          for (int c = 0; c < 3; ++c) At(3 * b + c, o + e) = blocks_[i](e, 3 * k + c);
    o += row.rows();
  }
  if (o != m) return false;
  Vec x(m);
  for (int i = 0; i < p.nBodies; ++i)
    x.template segment<3>(3 * i) = Q_->segment<3>(3 * p.bodies[i]) - S_.segment<3>(3 * p.bodies[i]);
  if (!eliminate<N>(At, x, m) || !x.allFinite()) return false;
  distribute(sys, p, x.data());
  return true;
}

// See group_forces.h: moments about each body's outer joint, then the outer joints.
bool GroupForces::solveDyad(const System& sys, const Plan& p) {
  // The scalar rows' blocks at body 0 and 1 of the dyad: own0 (2 x 3), shared at each, own1.
  Eigen::Matrix<double, 2, 3> A[2], C[2];
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < p.count; ++i) {
    const int part = i < p.dyadShared ? 0 : i < p.dyadOwn2 ? 1 : 2;
    const PlannedRow& pr = rows_[p.first + i];
    const Block& B = blocks_[p.first + i];
    for (int e = 0; e < sys.cons[pr.row].rows(); ++e, ++counts[part])
      for (int k = 0; k < 3; ++k) {
        if (pr.local[k] < 0) continue;
        const Row3 b = B.block<1, 3>(e, 3 * k);
        if (part == 1)
          C[pr.local[k]].row(counts[1]) = b;
        else
          A[part / 2].row(counts[part]) = b;
      }
  }
  Row3 n[2], r[2];
  double M[2][2], rhs[2];
  for (int i = 0; i < 2; ++i) {
    n[i] = cross3(A[i].row(0), A[i].row(1));
    r[i] = (Q_->segment<3>(3 * p.bodies[i]) - S_.segment<3>(3 * p.bodies[i])).transpose();
    const Eigen::Vector2d Cn = C[i] * n[i].transpose();
    M[i][0] = Cn[0];
    M[i][1] = Cn[1];
    rhs[i] = n[i].dot(r[i]);
  }
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  if (det == 0) return false;
  double x[6];  // own0, shared, own1: the plan's row order
  x[2] = (rhs[0] * M[1][1] - M[0][1] * rhs[1]) / det;
  x[3] = (M[0][0] * rhs[1] - rhs[0] * M[1][0]) / det;
  const Eigen::Vector2d mid(x[2], x[3]);
  for (int i = 0; i < 2; ++i)
    if (!solveTwoOfThree(A[i], n[i], r[i] - (C[i].transpose() * mid).transpose(), x + 4 * i))
      return false;
  for (double v : x)
    if (!std::isfinite(v)) return false;
  distribute(sys, p, x);
  return true;
}

}  // namespace linkage
