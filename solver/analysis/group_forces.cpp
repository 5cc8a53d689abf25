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
using Row3 = Eigen::Matrix<double, 1, 3>;                   // (GroupForces::Row3)
using Pair = Eigen::Matrix<double, 2, 3, Eigen::RowMajor>;  // two scalar rows on one body

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
bool solveTwoOfThree(const Pair& A, const Row3& n, const Row3& r, double* x) {
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
  uses_.clear();
  spills_.clear();
  lambdaRow_.clear();
  for (auto g = d.groups.rbegin(); g != d.groups.rend(); ++g) {
    Plan p;
    p.first = static_cast<int>(rows_.size());
    p.count = static_cast<int>(g->rows.size());
    p.nBodies = static_cast<int>(g->bodies.size());
    for (int i = 0; i < std::min(p.nBodies, 4); ++i) p.bodies[i] = g->bodies[i];
    for (int r : g->rows) {
      PlannedRow pr;
      pr.row = r;
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < std::min(p.nBodies, 4); ++i)
          if (sys.cons[r].body[k] == g->bodies[i]) pr.local[k] = i;
      rows_.push_back(pr);
    }
    plan(sys, p);
    plans_.push_back(p);
  }
  forces_.resize(rows_.size());
  plannedOf_.assign(sys.cons.size(), -1);
  for (size_t i = 0; i < rows_.size(); ++i) plannedOf_[rows_[i].row] = static_cast<int>(i);
  S_.setZero(3 * sys.nBodies);
}

// Orders a dyad's or a held body's rows as their solves read them, and lists where each scalar
// row acts.
void GroupForces::plan(const System& sys, Plan& p) {
  const auto first = rows_.begin() + p.first, last = first + p.count;
  int scalars[3] = {0, 0, 0};
  for (auto r = first; r != last; ++r) scalars[dyadPart(*r)] += sys.cons[r->row].rows();
  p.dyad = p.nBodies == 2 && scalars[0] == 2 && scalars[1] == 2 && scalars[2] == 2;
  if (p.dyad)
    std::stable_sort(first, last, [](const PlannedRow& a, const PlannedRow& b) {
      return dyadPart(a) < dyadPart(b);
    });
  if (p.nBodies == 1 && p.count == 2) {
    const int one = sys.cons[first->row].rows(), two = sys.cons[(first + 1)->row].rows();
    if (one == 1 && two == 2) std::iter_swap(first, first + 1);
    p.heldBody = one + two == 3;
  }
  p.firstScalar = static_cast<int>(lambdaRow_.size());
  p.firstUse = static_cast<int>(uses_.size());
  p.firstSpill = static_cast<int>(spills_.size());
  for (int i = p.first; i < p.first + p.count; ++i) {
    const Row& row = sys.cons[rows_[i].row];
    for (int e = 0; e < row.rows(); ++e, ++p.scalars) {
      lambdaRow_.push_back(row.row + e);
      for (int k = 0; k < 3; ++k) {
        if (row.body[k] < 0) continue;
        const int local = rows_[i].local[k];
        (local >= 0 ? uses_ : spills_).push_back({i, e, k, row.body[k], local, p.scalars});
      }
    }
  }
  p.uses = static_cast<int>(uses_.size()) - p.firstUse;
  p.spills = static_cast<int>(spills_.size()) - p.firstSpill;
}

GroupForces::Row3 GroupForces::remaining(int body) const {
  return (Q_->segment<3>(3 * body) - S_.segment<3>(3 * body)).transpose();
}

// x: the group's scalar rows' multipliers in plan order. Into lambda; and what each row puts on
// the bodies outside the group (groups solved later) into S.
void GroupForces::distribute(const Plan& p, const double* x) {
  for (int o = 0; o < p.scalars; ++o) (*lambda_)[lambdaRow_[p.firstScalar + o]] = x[o];
  for (int i = p.firstSpill; i < p.firstSpill + p.spills; ++i) {
    const Use& u = spills_[i];
    S_.segment<3>(3 * u.body) += on(u).transpose() * x[u.o];
  }
}

bool GroupForces::solve(const System& sys, const std::vector<BodyView>& views,
                        const Eigen::VectorXd& Q, Eigen::VectorXd& lambda) {
  Q_ = &Q;
  lambda_ = &lambda;
  views_ = &views;
  S_.setZero(3 * sys.nBodies);
  lambda.setConstant(sys.nRows, NAN);
  for (size_t i = 0; i < rows_.size(); ++i)
    rowForce(sys, views, sys.cons[rows_[i].row], forces_[i]);
  for (const Plan& p : plans_) {
    const bool ok = p.dyad && solveDyad(p)           ? true
                    : p.heldBody && solveHeldBody(p) ? true
                    : p.nBodies == 1                 ? solveGroup<3>(p)
                    : p.nBodies == 2                 ? solveGroup<6>(p)
                                     : p.nBodies <= 4 && solveGroup<Eigen::Dynamic>(p);
    if (!ok) return false;
  }
  return true;
}

// A^T x = Q - S over the group's bodies, A^T's columns its scalar rows.
template <int N>
bool GroupForces::solveGroup(const Plan& p) {
  using Mat = std::conditional_t<N == Eigen::Dynamic, GroupMatrix, Eigen::Matrix<double, N, N>>;
  using Vec = std::conditional_t<N == Eigen::Dynamic, GroupVector, Eigen::Matrix<double, N, 1>>;
  const int m = 3 * p.nBodies;
  if (p.scalars != m) return false;
  Mat At = Mat::Zero(m, m);
  for (int i = p.firstUse; i < p.firstUse + p.uses; ++i) {
    const Use& u = uses_[i];
    At.template block<3, 1>(3 * u.local, u.o) = on(u).transpose();
  }
  Vec x(m);
  for (int i = 0; i < p.nBodies; ++i)
    x.template segment<3>(3 * i) = remaining(p.bodies[i]).transpose();
  if (!eliminate<N>(At, x, m) || !x.allFinite()) return false;
  distribute(p, x.data());
  return true;
}

// See group_forces.h: moments about each body's outer joint, then the outer joints. Uses in
// scalar order: own0 (2, on body 0), shared (2, each on both bodies), own1 (2, on body 1).
bool GroupForces::solveDyad(const Plan& p) {
  Pair A[2], C[2];
  for (int i = p.firstUse; i < p.firstUse + p.uses; ++i) {
    const Use& u = uses_[i];
    if (u.o >= 2 && u.o < 4)
      C[u.local].row(u.o - 2) = on(u);
    else
      A[u.local].row(u.o & 1) = on(u);
  }
  Row3 n[2], r[2];
  double M[2][2], rhs[2];
  for (int i = 0; i < 2; ++i) {
    n[i] = cross3(A[i].row(0), A[i].row(1));
    r[i] = remaining(p.bodies[i]);
    const Eigen::Vector2d Cn = C[i] * n[i].transpose();
    M[i][0] = Cn[0];
    M[i][1] = Cn[1];
    rhs[i] = n[i].dot(r[i]);
  }
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  if (det == 0) return false;
  double x[6];  // own0, shared, own1: the plan's scalar order
  x[2] = (rhs[0] * M[1][1] - M[0][1] * rhs[1]) / det;
  x[3] = (M[0][0] * rhs[1] - rhs[0] * M[1][0]) / det;
  const Eigen::Vector2d mid(x[2], x[3]);
  for (int i = 0; i < 2; ++i)
    if (!solveTwoOfThree(A[i], n[i], r[i] - (C[i].transpose() * mid).transpose(), x + 4 * i))
      return false;
  for (double v : x)
    if (!std::isfinite(v)) return false;
  distribute(p, x);
  return true;
}

// See group_forces.h: the body's moments about its two-row joint give the other row's
// multiplier, then two of its three equations the joint's. Uses in scalar order.
bool GroupForces::solveHeldBody(const Plan& p) {
  Pair A;
  A.row(0) = on(uses_[p.firstUse]);
  A.row(1) = on(uses_[p.firstUse + 1]);
  const Row3 a = on(uses_[p.firstUse + 2]);
  const Row3 n = cross3(A.row(0), A.row(1));
  const Row3 r = remaining(p.bodies[0]);
  const double an = a.dot(n);
  if (an == 0) return false;
  double x[3];
  x[2] = n.dot(r) / an;
  if (!solveTwoOfThree(A, n, r - x[2] * a, x)) return false;
  for (double v : x)
    if (!std::isfinite(v)) return false;
  distribute(p, x);
  return true;
}

}  // namespace linkage
