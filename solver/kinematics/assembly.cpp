#include "kinematics/assembly.h"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "linkage/elements.h"

namespace linkage {

namespace {

std::string mm(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g mm", v);
  return buf;
}

// How far each joint is from holding, in mm (angles as the arc they make over the size L).
std::vector<double> jointGaps(const Mechanism& m, const System& sys, const Eigen::VectorXd& q,
                              double phi) {
  std::vector<BodyView> views;
  makeViews(sys, q, nullptr, views);
  std::vector<int> all(sys.nRows);
  for (int r = 0; r < sys.nRows; ++r) all[r] = r;
  Eigen::VectorXd res(sys.nRows);
  evalResidual(sys, views, phi, all, res);
  std::vector<double> gaps(m.joints.size() + 1, 0.0);  // last entry: the driver
  for (const Row& c : sys.cons) {
    if (c.kind == Primitive::Hold) continue;
    const int slot = c.isDriver() ? static_cast<int>(m.joints.size()) : c.joint;
    const double g = res.segment(c.row, c.rows()).norm();
    gaps[slot] = std::hypot(gaps[slot], g);
  }
  return gaps;
}

// Levenberg-Marquardt on all equations: the closest the drawing can come to closing. The damped
// normal equations (J^T J + mu (I + diag J^T J)) d = J^T r are sparse for large systems, where
// forming and factoring them densely is cubic (a 101-body drawing that cannot close spent 0.66 s
// here, 19 ms sparse).
void leastSquares(const System& sys, Eigen::VectorXd& q, double phi, bool sparse) {
  const int n = sys.nCoords();
  std::vector<int> all(sys.nRows);
  for (int r = 0; r < sys.nRows; ++r) all[r] = r;
  std::vector<BodyView> views;
  Eigen::MatrixXd J, A;
  SparseJacobian Js;
  Eigen::SparseMatrix<double> As, M, damping(n, n);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sparseLdlt;
  if (sparse) {
    Js = sparseJacobian(sys, all, sys.nRows);
    damping.setIdentity();
  } else {
    J.resize(sys.nRows, n);
  }
  Eigen::VectorXd res(sys.nRows), trial(sys.nRows), g, diagA;
  double mu = 1e-3;
  auto cost = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    makeViews(sys, x, nullptr, views);
    evalResidual(sys, views, phi, all, r);
    return r.squaredNorm();
  };
  // The damped step for the current mu; false if the factorisation failed.
  auto step = [&](Eigen::VectorXd& d) {
    if (!sparse) {
      Eigen::MatrixXd Md = A;
      Md.diagonal().array() += mu * (1.0 + diagA.array());
      d = Md.ldlt().solve(g);
      return true;
    }
    damping.coeffs() = mu * (1.0 + diagA.array());
    M = As + damping;
    sparseLdlt.compute(M);
    if (sparseLdlt.info() != Eigen::Success) return false;
    d = sparseLdlt.solve(g);
    return true;
  };
  double f = cost(q, res);
  for (int it = 0; it < 200 && f > 0; ++it) {
    makeViews(sys, q, nullptr, views);
    if (sparse) {
      evalJacobian(sys, views, all, Js);
      for (int k = 0; k < sys.nBodies; ++k) Js.J.col(3 * k + 2) /= sys.size;
      As = Js.J.transpose() * Js.J;
      g = Js.J.transpose() * res;
      diagA = As.diagonal();
    } else {
      evalJacobian(sys, views, all, J);
      for (int k = 0; k < sys.nBodies; ++k) J.col(3 * k + 2) /= sys.size;
      A = J.transpose() * J;
      g = J.transpose() * res;
      diagA = A.diagonal();
    }
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::VectorXd d;
      if (!step(d)) return;
      for (int k = 0; k < sys.nBodies; ++k) d[3 * k + 2] /= sys.size;
      Eigen::VectorXd x = q - d;
      const double ft = cost(x, trial);
      if (std::isfinite(ft) && ft < f) {
        q = x;
        res = trial;
        improved = f - ft > 1e-14 * f;
        f = ft;
        mu = std::max(mu / 3, 1e-12);
        if (!improved) return;
      } else {
        mu *= 4;
      }
    }
    if (!improved) return;
  }
}

}  // namespace

double largestMove(const Mechanism& m, const System& sys, const Eigen::VectorXd& from,
                   const Eigen::VectorXd& to, BodyId* body) {
  double best = 0;
  auto consider = [&](BodyId b, const Vec2& p) {
    const int k = sys.bodyIndex(b);
    if (k < 0) return;
    const PointLocation loc{k, p - sys.frameOrigin[k]};
    const double d = (pointPosition(sys, to, loc) - pointPosition(sys, from, loc)).norm();
    if (d > best) {
      best = d;
      if (body) *body = b;
    }
  };
  for (const Point& p : m.points) consider(p.body, p.pos);
  for (const Slot& s : m.slots) {
    consider(s.body, s.p0);
    consider(s.body, s.p1);
  }
  return best;
}

Status assemble(const Mechanism& m, const System& sys, const Structure& st, NewtonSolver& newton,
                Eigen::VectorXd& q, double phi, AssemblyReport& report) {
  (void)st;
  const Eigen::VectorXd start = q;
  Eigen::VectorXd delta, trial;
  const double L = sys.size;
  bool closed = false;
  for (int it = 0; it < 100; ++it) {
    const double r = newton.residualNorm(sys, q, phi);
    if (r <= 1e-9 * L) {
      closed = true;
      break;
    }
    if (!newton.correction(sys, q, phi, delta)) break;
    // Damped: halve the step until the residual falls, so that a rough drawing is pulled in
    // gradually instead of thrown to another branch by a full step.
    double t = 1;
    for (; t > 1.0 / 4096; t /= 2) {
      trial = q - t * delta;
      if (newton.residualNorm(sys, trial, phi) < (1 - 0.25 * t) * r) break;
    }
    if (t <= 1.0 / 4096) break;
    q = trial;
    report.iterations = it + 1;
  }
  if (closed) {
    NewtonOptions polish;
    polish.maxFirstStep = 1e300;
    closed = newton.solve(sys, q, phi, polish).converged;
  }
  if (!closed) {
    Eigen::VectorXd fit = start;
    leastSquares(sys, fit, phi, newton.sparse());
    const std::vector<double> gaps = jointGaps(m, sys, fit, phi);
    int worst = 0;
    for (int j = 1; j < static_cast<int>(gaps.size()); ++j)
      if (gaps[j] > gaps[worst]) worst = j;
    Status s = Status::failure(StatusCode::AssemblyFailed, "");
    std::string what;
    const int nj = static_cast<int>(m.joints.size());
    auto idOf = [&](int j) { return j < nj ? m.joints[j].id : JointId{}; };
    if (worst < nj) {
      s.joints.push_back(m.joints[worst].id);
      what = jointName(m, m.joints[worst].id);
    } else {
      what = "the driver";
    }
    s.gaps.push_back({idOf(worst), gaps[worst]});
    std::vector<std::string> others;
    for (int j = 0; j <= nj; ++j)
      if (j != worst && gaps[j] > 1e-6 * L) {
        s.gaps.push_back({idOf(j), gaps[j]});
        if (j == nj) continue;
        s.joints.push_back(m.joints[j].id);
        others.push_back(jointName(m, m.joints[j].id));
      }
    s.message = "cannot assemble the mechanism as drawn: " + what + " stays " + mm(gaps[worst]) +
                " open at best";
    if (!others.empty()) {
      s.message += " (also open: ";
      for (size_t i = 0; i < others.size(); ++i) s.message += (i ? ", " : "") + others[i];
      s.message += ")";
    }
    s.message += "; a link is too short or too long to close the loop";
    q = start;
    return s;
  }
  report.maxMove = largestMove(m, sys, start, q, &report.body);
  report.moved = report.maxMove > 1e-9 * sys.size;
  return Status::success();
}

Status checkRedundant(const Mechanism& m, const System& sys, const Structure& st,
                      const Eigen::VectorXd& q, double phi) {
  if (st.dependentRows.empty()) return Status::success();
  const std::vector<double> gaps = jointGaps(m, sys, q, phi);
  Status s = Status::success();
  for (int j : st.redundantJoints) {
    if (gaps[j] > 1e-9 * sys.size) {
      if (s.ok()) {
        s = Status::failure(StatusCode::Conflicting, "");
        s.message = jointName(m, m.joints[j].id) +
                    " conflicts with the other joints: they hold but it stays " + mm(gaps[j]) +
                    " open";
      }
      s.joints.push_back(m.joints[j].id);
      s.gaps.push_back({m.joints[j].id, gaps[j]});
    }
  }
  return s;
}

}  // namespace linkage
