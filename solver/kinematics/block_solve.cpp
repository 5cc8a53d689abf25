// Newton on a block of bodies, the others held: see block_solve.h.
#include "kinematics/block_solve.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkage {

std::optional<Block> makeBlock(const System& sys, const std::vector<int>& activeRowMap,
                               std::vector<int> bodies) {
  std::sort(bodies.begin(), bodies.end());
  std::vector<char> in(sys.nBodies, 0);
  for (int k : bodies) in[k] = 1;
  Block b;
  b.rowMap.assign(sys.nRows, -1);
  for (const Row& c : sys.cons) {
    bool touches = c.kind == Primitive::Hold && in[c.col / 3];
    if (c.kind != Primitive::Hold)
      for (int i = 0; i < c.bodies(); ++i) touches = touches || (c.body[i] >= 0 && in[c.body[i]]);
    if (!touches) continue;
    // Each scalar row on its own: one of a pin's two can be dependent and the other not.
    for (int i = c.row; i < c.row + c.rows(); ++i)
      if (activeRowMap[i] >= 0) b.rowMap[i] = b.rows++;
  }
  if (b.rows != 3 * static_cast<int>(bodies.size())) return std::nullopt;
  for (int k : bodies)
    for (int j = 0; j < 3; ++j) b.cols.push_back(3 * k + j);
  b.bodies = std::move(bodies);
  return b;
}

bool BlockSolver::factor(const System& sys, const Block& b, const Eigen::VectorXd& q) {
  makeViews(sys, q, nullptr, views_);
  Jrows_.resize(b.rows, sys.nCoords());
  evalJacobian(sys, views_, b.rowMap, Jrows_);
  Jss_.resize(b.rows, b.rows);
  for (int j = 0; j < b.rows; ++j) Jss_.col(j) = Jrows_.col(b.cols[j]);
  // Scaled as NewtonSolver scales J, so that the pivot ratio means the same.
  for (int j = 2; j < b.rows; j += 3) Jss_.col(j) /= sys.size;
  lu_.resize(b.rows);
  lu_.compute(Jss_);
  return std::isfinite(lu_.pivotRatio()) && lu_.pivotRatio() > kSingularPivot;
}

int BlockSolver::signAt(const System& sys, const Block& b, const Eigen::VectorXd& q) {
  return factor(sys, b, q) ? lu_.detSign() : 0;
}

NewtonResult BlockSolver::solve(const System& sys, const Block& b, Eigen::VectorXd& q, double phi,
                                const NewtonOptions& opt) {
  NewtonResult res;
  const double L = sys.size;
  res_.resize(b.rows);
  bool polished = false;
  double prevStep = std::numeric_limits<double>::infinity();
  for (int it = 0; it <= opt.maxIterations; ++it) {
    makeViews(sys, q, nullptr, views_);
    evalResidual(sys, views_, phi, b.rowMap, res_);
    res.residual = b.rows ? res_.cwiseAbs().maxCoeff() : 0.0;
    if (!std::isfinite(res.residual)) {
      res.failure = NewtonFailure::Diverged;
      return res;
    }
    // As NewtonSolver::solve: within tolerance but above rounding, one more correction.
    const double tol = newtonTolerance(sys, q, opt.relTol);
    if (res.residual <= tol && (polished || it == 0 || res.residual <= 0.05 * tol)) {
      res.converged = true;
      return res;
    }
    if (res.residual <= tol) polished = true;
    if (it == opt.maxIterations) break;
    ++res.factorizations;
    if (!factor(sys, b, q)) {
      res.failure = NewtonFailure::Singular;
      return res;
    }
    lu_.solveInPlace(res_);
    double step = 0;
    for (int j = 0; j < b.rows; ++j) {
      if (j % 3 == 2) res_[j] /= L;
      step = std::max(step, std::abs(res_[j]) * (j % 3 == 2 ? L : 1.0));
    }
    if (it == 0 && step > opt.maxFirstStep * L) {
      res.failure = NewtonFailure::TooFar;
      return res;
    }
    // Every step is a full Newton step: one that does not contract fourfold is not converging.
    if (step > 0.25 * prevStep) {
      res.failure = NewtonFailure::Diverged;
      return res;
    }
    for (int j = 0; j < b.rows; ++j) q[b.cols[j]] -= res_[j];
    ++res.iterations;
    prevStep = step;
  }
  res.failure = NewtonFailure::MaxIterations;
  return res;
}

void BlockSolver::solveInto(const Block& b, double L, Eigen::VectorXd& rhs,
                            const Eigen::VectorXd& known, Eigen::VectorXd& out) {
  Eigen::VectorXd rest = known;
  for (int c : b.cols) rest[c] = 0;
  rhs.noalias() -= Jrows_ * rest;
  lu_.solveInPlace(rhs);
  for (int j = 0; j < b.rows; ++j) out[b.cols[j]] = j % 3 == 2 ? rhs[j] / L : rhs[j];
}

bool BlockSolver::derivatives(const System& sys, const Block& b, const Eigen::VectorXd& q,
                              Eigen::VectorXd& dq, Eigen::VectorXd& ddq) {
  if (!factor(sys, b, q)) return false;
  const double near = inverseEstimate(b.rows, [this](Eigen::VectorXd& z) { lu_.solveInPlace(z); });
  if (!(near > kSingularPivot)) return false;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(b.rows);
  if (sys.driverRow >= 0 && b.rowMap[sys.driverRow] >= 0)
    rhs[b.rowMap[sys.driverRow]] = sys.size * sys.sigma;  // -Phi_phi
  solveInto(b, sys.size, rhs, dq, dq);
  setVelocities(sys, dq, views_);
  evalGamma(sys, views_, b.rowMap, rhs);
  solveInto(b, sys.size, rhs, ddq, ddq);
  for (int c : b.cols)
    if (!std::isfinite(dq[c]) || !std::isfinite(ddq[c])) return false;
  return true;
}

}  // namespace linkage
