// The position solve (Newton-Raphson on the independent equations, analytic Jacobian) and the
// exact velocity and acceleration solves with the same Jacobian. Kinematics are in the crank
// angle phi: J q' = -Phi_phi and J q'' = gamma(q'), so q' and q'' do not depend on the speed.
//
// J is factored with its theta columns divided by the mechanism size L (every entry O(1)), so
// that the pivot ratio used to detect singular positions means the same at any scale.
// Newton reuses the factorisation of its first iterate (chord steps) while the corrections
// shrink at least fourfold; a poorer contraction refactors once, and a second one fails: near a
// solution Newton contracts far faster, so a slow contraction means the start was not close.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "system/dense_lu.h"
#include "system/sparse_lu.h"
#include "system/system.h"

namespace linkage {

enum class NewtonFailure { None, Singular, Diverged, TooFar, MaxIterations };

// Pivot ratio of the scaled J below which it counts as singular (newton.cpp says why 1e-8).
constexpr double kSingularPivot = 1e-8;

// The residual a solve at q accepts: relTol of the larger of L and the coordinates' magnitude.
double newtonTolerance(const System& sys, const Eigen::VectorXd& q, double relTol);

// An estimate of the smallest singular value of a factored O(1) matrix of order n, given the
// solve with its factors (in place): |z| / |A^-1 z| for a fixed pseudo-random z (the probe;
// newton.cpp says why it is so chosen).
Eigen::VectorXd inverseEstimateProbe(int n);
template <class SolveInPlace>
double inverseEstimate(int n, const SolveInPlace& solveInPlace) {
  if (n == 0) return 1;
  Eigen::VectorXd z = inverseEstimateProbe(n);
  solveInPlace(z);
  const double norm = z.cwiseAbs().maxCoeff();
  return std::isfinite(norm) && norm > 0 ? 1 / norm : 0;
}

struct NewtonResult {
  bool converged = false;
  NewtonFailure failure = NewtonFailure::None;
  int iterations = 0;
  int factorizations = 0;
  double residual = 0;  // max |Phi| at the end, mm
};

class NewtonSolver {
 public:
  // Prepares for the given rows (they must be independent and as many as coordinates). J is
  // factored as a sparse matrix from `sparseFrom` coordinates on.
  void reset(const System& sys, const std::vector<int>& activeRows, int sparseFrom = kSparseFrom);
  bool sparse() const { return sparse_; }

  // Every call takes the system it was reset for: the solver keeps no pointer to it, so the
  // objects that own both can be copied and moved freely.
  NewtonResult solve(const System& sys, Eigen::VectorXd& q, double phi, const NewtonOptions& opt);

  // Factors J at q and solves q' and q''. False when J is singular there.
  bool derivatives(const System& sys, const Eigen::VectorXd& q, Eigen::VectorXd& dq,
                   Eigen::VectorXd& ddq);

  // Of the last factorisation: sign of det J and min/max pivot magnitude.
  int detSign() const { return sparse_ ? slu_.detSign() : lu_.detSign(); }
  double pivotRatio() const { return sparse_ ? slu_.pivotRatio() : lu_.pivotRatio(); }
  // Of the last derivatives(): the smaller of the pivot ratio and an inverse-iteration estimate
  // of the smallest singular value of the scaled J (how close to singular the position is).
  double nearness() const { return std::min(pivotRatio(), estimate_); }

  // One full Newton correction at q (J factored there): q_next = q - delta. False if singular.
  bool correction(const System& sys, const Eigen::VectorXd& q, double phi, Eigen::VectorXd& delta);

  // Was J last factored at q (exactly)? Then the forces at q can reuse the factors.
  bool factoredAt(const Eigen::VectorXd& q) const {
    return factoredQ_.size() == q.size() && factoredQ_ == q;
  }
  // Solves J^T lambda = b with the last factors, in place: b by coordinates (forces in N, moments
  // in N mm), lambda by active row (rowMap()). J here is unscaled: J_s = J D, D dividing theta
  // columns by L, so J_s^T lambda = D b.
  void solveTransposedInPlace(const System& sys, Eigen::VectorXd& b) const;

  // An edit solved without this solver (a block edit) may change q, or only L (the theta
  // scaling and the angle rows), under factors that would look current: drop them.
  void forgetFactors() {
    factoredQ_.resize(0);
    viewsQ_.resize(0);
  }

  // Residual of the active rows at q (mm), for reports.
  double residualNorm(const System& sys, const Eigen::VectorXd& q, double phi);
  const std::vector<int>& rowMap() const { return rowMap_; }

 private:
  double estimate_ = 1;
  bool factor(const System& sys, const Eigen::VectorXd& q);
  void solveInPlace(Eigen::VectorXd& b) const;
  // Body views at q; sin and cos are evaluated again only when q changed.
  void viewsAt(const System& sys, const Eigen::VectorXd& q);

  std::vector<int> rowMap_;
  std::vector<BodyView> views_;
  bool sparse_ = false;
  Eigen::MatrixXd J_;
  DenseLU lu_;
  SparseJacobian Js_;
  SparseLU slu_;
  Eigen::VectorXd phi_, delta_, rhs_, viewsQ_, factoredQ_;
};

}  // namespace linkage
