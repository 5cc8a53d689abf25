#include "kinematics/newton.h"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

namespace linkage {

// kSingularPivot: landing exactly on a singular position in floating point leaves a pivot ratio
// of ~1e-12 (rounding of an O(1)-scaled J); the closest legitimate positions measured (1e-5 mm
// from a change point, 1e-6 degrees from a dead point, lambda = 0.999) stay above 1e-4. 1e-8
// sits between, so a rounding-level singular point is never taken as regular.

void NewtonSolver::reset(const System& sys, const std::vector<int>& activeRows, int sparseFrom) {
  const int n = sys.nCoords();
  assert(static_cast<int>(activeRows.size()) == n &&
         "NewtonSolver needs a square system: add holds for free coordinates first");
  rowMap_.assign(sys.nRows, -1);
  for (int i = 0; i < static_cast<int>(activeRows.size()); ++i) rowMap_[activeRows[i]] = i;
  sparse_ = n >= sparseFrom;
  if (sparse_) {
    J_.resize(0, 0);
    Js_ = sparseJacobian(sys, rowMap_, n);
    slu_.analyzePattern(Js_.J);
  } else {
    J_.resize(n, n);
    lu_.resize(n);
    Js_ = {};
  }
  phi_.resize(n);
  delta_.resize(n);
  rhs_.resize(n);
  viewsQ_.resize(0);
  factoredQ_.resize(0);
}

void NewtonSolver::viewsAt(const System& sys, const Eigen::VectorXd& q) {
  if (viewsQ_.size() == q.size() && viewsQ_ == q) return;
  makeViews(sys, q, nullptr, views_);
  viewsQ_ = q;
}

double newtonTolerance(const System& sys, const Eigen::VectorXd& q, double relTol) {
  // Rounding in a residual grows with the coordinates' magnitude, not only with L.
  double scale = sys.size;
  for (int k = 0; k < sys.nBodies; ++k)
    scale = std::max(scale, std::max(std::abs(q[3 * k]), std::abs(q[3 * k + 1])));
  return relTol * scale;
}

bool NewtonSolver::factor(const System& sys, const Eigen::VectorXd& q) {
  viewsAt(sys, q);
  factoredQ_ = q;
  const double invL = 1.0 / sys.size;
  if (sparse_) {
    evalJacobian(sys, views_, rowMap_, Js_);
    double* v = Js_.J.valuePtr();
    const int* start = Js_.J.outerIndexPtr();
    for (int k = 0; k < sys.nBodies; ++k)
      for (int p = start[3 * k + 2]; p < start[3 * k + 3]; ++p) v[p] *= invL;
    slu_.compute(Js_.J);
  } else {
    evalJacobian(sys, views_, rowMap_, J_);
    for (int k = 0; k < sys.nBodies; ++k) J_.col(3 * k + 2) *= invL;
    lu_.compute(J_);
  }
  return std::isfinite(pivotRatio()) && pivotRatio() > kSingularPivot;
}

void NewtonSolver::solveInPlace(Eigen::VectorXd& b) const {
  if (sparse_) {
    slu_.solveInPlace(b);
  } else {
    lu_.solveInPlace(b);
  }
}

void NewtonSolver::solveTransposedInPlace(const System& sys, Eigen::VectorXd& b) const {
  const double invL = 1.0 / sys.size;
  for (int k = 0; k < sys.nBodies; ++k) b[3 * k + 2] *= invL;
  if (sparse_) {
    slu_.solveTransposedInPlace(b);
  } else {
    lu_.solveTransposedInPlace(b);
  }
}

double NewtonSolver::residualNorm(const System& sys, const Eigen::VectorXd& q, double phi) {
  viewsAt(sys, q);
  evalResidual(sys, views_, phi, rowMap_, phi_);
  return phi_.size() ? phi_.cwiseAbs().maxCoeff() : 0.0;
}

NewtonResult NewtonSolver::solve(const System& sys, Eigen::VectorXd& q, double phi,
                                 const NewtonOptions& opt) {
  NewtonResult res;
  const double L = sys.size;
  const double invL = 1.0 / L;
  bool fresh = false;  // is the factorisation from the current iterate?
  bool haveLU = false;
  bool polished = false;
  double prevStep = std::numeric_limits<double>::infinity();
  for (int it = 0; it <= opt.maxIterations; ++it) {
    viewsAt(sys, q);
    evalResidual(sys, views_, phi, rowMap_, phi_);
    res.residual = phi_.size() ? phi_.cwiseAbs().maxCoeff() : 0.0;
    if (!std::isfinite(res.residual)) {
      res.failure = NewtonFailure::Diverged;
      return res;
    }
    const double tol = newtonTolerance(sys, q, opt.relTol);
    // Within tolerance but above rounding (a few eps of the coordinates): one more chord
    // correction, nearly free with the factorisation at hand, takes it to rounding level.
    if (res.residual <= tol && (polished || !haveLU || res.residual <= 0.05 * tol)) {
      res.converged = true;
      return res;
    }
    if (res.residual <= tol) polished = true;
    if (it == opt.maxIterations) break;
    if (!haveLU) {
      ++res.factorizations;
      if (!factor(sys, q)) {
        res.failure = NewtonFailure::Singular;
        return res;
      }
      haveLU = fresh = true;
    }
    delta_ = phi_;
    solveInPlace(delta_);
    double step = 0;
    for (int k = 0; k < sys.nBodies; ++k) {
      delta_[3 * k + 2] *= invL;
      step = std::max({step, std::abs(delta_[3 * k]), std::abs(delta_[3 * k + 1]),
                       std::abs(delta_[3 * k + 2]) * L});
    }
    if (it == 0 && step > opt.maxFirstStep * L) {
      res.failure = NewtonFailure::TooFar;
      return res;
    }
    if (step > 0.25 * prevStep) {
      if (fresh) {
        res.failure = NewtonFailure::Diverged;
        return res;
      }
      // A stale factorisation contracts too slowly: refactor here and retry this iteration.
      haveLU = false;
      --it;
      continue;
    }
    q -= delta_;
    ++res.iterations;
    prevStep = step;
    fresh = false;
  }
  res.failure = NewtonFailure::MaxIterations;
  return res;
}

bool NewtonSolver::correction(const System& sys, const Eigen::VectorXd& q, double phi,
                              Eigen::VectorXd& delta) {
  viewsAt(sys, q);
  evalResidual(sys, views_, phi, rowMap_, phi_);
  if (!factor(sys, q)) return false;
  delta = phi_;
  solveInPlace(delta);
  for (int k = 0; k < sys.nBodies; ++k) delta[3 * k + 2] /= sys.size;
  return delta.allFinite();
}

Eigen::VectorXd inverseEstimateProbe(int n) {
  // The pivots of a partial-pivot LU do not always show a singular J: on a long chain the
  // small factor can spread over many pivots (a change point 18 loops deep read as 5e-8 to
  // 1e-2). One step of inverse iteration from a fixed vector shows it: J^-1 z is
  // dominated by the direction of the smallest singular value, so |z| / |J^-1 z| estimates
  // it (J is O(1) after scaling). Cheap next to the factorisation: one more pair of solves.
  // z must not be orthogonal to that direction: a pattern of +-1 can be (a change point's
  // left singular vector is a difference of rows), so its entries are pseudo-random in
  // [-1, 1], the same every call.
  Eigen::VectorXd z(n);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    z[i] = static_cast<double>(state >> 11) * 0x1.0p-52 - 1.0;
  }
  return z;
}

bool NewtonSolver::derivatives(const System& sys, const Eigen::VectorXd& q, Eigen::VectorXd& dq,
                               Eigen::VectorXd& ddq) {
  if (!factor(sys, q)) return false;
  estimate_ = inverseEstimate(static_cast<int>(rhs_.size()),
                              [this](Eigen::VectorXd& z) { solveInPlace(z); });
  if (!(estimate_ > kSingularPivot)) return false;
  const double invL = 1.0 / sys.size;
  rhs_.setZero();
  if (sys.driverRow >= 0 && rowMap_[sys.driverRow] >= 0)
    rhs_[rowMap_[sys.driverRow]] = sys.size * sys.sigma;  // -Phi_phi
  dq = rhs_;
  solveInPlace(dq);
  for (int k = 0; k < sys.nBodies; ++k) dq[3 * k + 2] *= invL;
  setVelocities(sys, dq, views_);
  evalGamma(sys, views_, rowMap_, rhs_);
  ddq = rhs_;
  solveInPlace(ddq);
  for (int k = 0; k < sys.nBodies; ++k) ddq[3 * k + 2] *= invL;
  return dq.allFinite() && ddq.allFinite();
}

}  // namespace linkage
