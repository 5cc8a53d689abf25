#include "core_group.h"

#include <Eigen/LU>
#include <cmath>

#include "joint_pin.h"
#include "joint_pin_in_slot.h"

namespace linkage {

namespace {

BodyView viewOf(int body, const Eigen::VectorXd& q, const Eigen::VectorXd* v, int col) {
  BodyView b;
  b.col = col;
  if (body < 0) return b;
  const int k = 3 * body;
  b.r = Vec2(q[k], q[k + 1]);
  b.theta = q[k + 2];
  b.R = Rot{std::cos(b.theta), std::sin(b.theta)};
  if (v) {
    b.v = Vec2((*v)[k], (*v)[k + 1]);
    b.w = (*v)[k + 2];
  }
  return b;
}

// The three rows: residual, the core's 3 x 3 Jacobian (theta column as is), and optionally the
// known bodies' contributions J_K x_K for a given x (velocities or accelerations).
struct Rows {
  Eigen::Vector3d phi;
  Eigen::Matrix3d J;
};

void evalRows(const CoreGroup& g, const BodyView& core, const Eigen::VectorXd& q, Rows& out) {
  out.J.setZero();
  int row = 0;
  for (const CoreLink& l : g.links) {
    const BodyView k = viewOf(l.known, q, nullptr, -1);  // col -1: only the core's columns
    if (l.pin) {
      out.phi.segment<2>(row) = pin::residual(core, l.s, k, l.ks);
      pin::jacobian(out.J, row, core, l.s, k, l.ks);
      row += 2;
    } else {
      out.phi[row] = line::residual(core, l.s, k, l.ks, l.n);
      line::jacobian(out.J, row, core, l.s, k, l.n);
      row += 1;
    }
  }
}

// Right-hand side of J_core x_core = rhs: -J_K x_K for the known bodies (x = dq or ddq), plus
// gamma when the velocities are given (accelerations).
Eigen::Vector3d knownTerms(const CoreGroup& g, const BodyView& core, const Eigen::VectorXd& q,
                           const Eigen::VectorXd& x, const Eigen::VectorXd* v) {
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  BodyView noCore = core;
  noCore.col = -1;
  int row = 0;
  for (const CoreLink& l : g.links) {
    const int rows = l.pin ? 2 : 1;
    const BodyView k = viewOf(l.known, q, v, 0);
    if (l.known >= 0) {
      Eigen::Matrix3d Jk = Eigen::Matrix3d::Zero();
      if (l.pin)
        pin::jacobian(Jk, row, noCore, l.s, k, l.ks);
      else
        line::jacobian(Jk, row, noCore, l.s, k, l.n);
      rhs.segment(row, rows) -= Jk.middleRows(row, rows) * x.segment<3>(3 * l.known);
    }
    if (v) {
      if (l.pin)
        rhs.segment<2>(row) += pin::gamma(core, l.s, k, l.ks);
      else
        rhs[row] += line::gamma(core, l.s, k, l.ks, l.n);
    }
    row += rows;
  }
  return rhs;
}

}  // namespace

int coreDetSign(const CoreGroup& g, const System& sys, const Eigen::VectorXd& q) {
  Rows rows;
  evalRows(g, viewOf(g.core, q, nullptr, 0), q, rows);
  const double det = rows.J.determinant();
  const double scale = rows.J.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return 0;
  (void)sys;
  return det > 0 ? 1 : -1;
}

bool solveCore(const CoreGroup& g, const System& sys, const Eigen::VectorXd& prev, double h,
               Eigen::VectorXd& q, Eigen::VectorXd& dq, Eigen::VectorXd& ddq) {
  const int c = 3 * g.core;
  const double L = sys.size;
  // Predictor from the previous pose and rates (still in dq, ddq: not yet overwritten).
  Eigen::Vector3d x = prev.segment<3>(c) + h * dq.segment<3>(c) + (0.5 * h * h) * ddq.segment<3>(c);
  Rows rows;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu;
  bool converged = false, polished = false;
  double prevStep = INFINITY;
  for (int it = 0; it < 12; ++it) {
    q.segment<3>(c) = x;
    const BodyView core = viewOf(g.core, q, nullptr, 0);
    evalRows(g, core, q, rows);
    const double res = rows.phi.cwiseAbs().maxCoeff();
    const double tol = 1e-13 * std::max({L, std::abs(x[0]), std::abs(x[1])});
    if (!std::isfinite(res)) return false;
    if (res <= tol && (polished || res <= 0.05 * tol)) {
      converged = true;
      break;
    }
    if (res <= tol) polished = true;
    lu.compute(rows.J);
    const Eigen::Vector3d delta = lu.solve(rows.phi);
    const double step = std::max(delta.head<2>().cwiseAbs().maxCoeff(), std::abs(delta[2]) * L);
    // Far from the prediction, or not contracting: leave it to the general solve.
    if (!std::isfinite(step) || (it == 0 && step > 0.1 * L) || step > 0.5 * prevStep) return false;
    prevStep = step;
    x -= delta;
  }
  if (!converged) return false;
  q.segment<3>(c) = x;
  // The drawn branch: det J keeps its sign until a singular position.
  const BodyView core = viewOf(g.core, q, nullptr, 0);
  evalRows(g, core, q, rows);
  const double det = rows.J.determinant();
  const double scale = rows.J.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale) || (det > 0 ? 1 : -1) != g.detSign)
    return false;
  lu.compute(rows.J);
  const Eigen::Vector3d v = lu.solve(knownTerms(g, core, q, dq, nullptr));
  dq.segment<3>(c) = v;
  const BodyView coreV = viewOf(g.core, q, &dq, 0);
  ddq.segment<3>(c) = lu.solve(knownTerms(g, coreV, q, ddq, &dq));

  // The blocks: angle, rate and acceleration of their slot body; pin point on the core.
  for (const CoreLink& l : g.links) {
    if (l.block < 0) continue;
    const BodyView k = viewOf(l.known, q, &dq, 0);
    const double th = k.theta, w = k.w, al = l.known >= 0 ? ddq[3 * l.known + 2] : 0.0;
    const Vec2 g0 = coreV.R * l.s;
    const Vec2 P = coreV.r + g0;
    const Vec2 vP = coreV.v + coreV.w * perp(g0);
    const Vec2 aP = Vec2(ddq[c], ddq[c + 1]) + ddq[c + 2] * perp(g0) - coreV.w * coreV.w * g0;
    placeBody(l.block, th, w, al, l.blockPin, P, vP, aP, q, dq, ddq);
  }
  return true;
}

}  // namespace linkage
