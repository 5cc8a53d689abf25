#include "solve/core_group.h"

#include <Eigen/LU>
#include <cmath>

#include "joints/pin.h"
#include "joints/pin_in_slot.h"

namespace linkage {

namespace {

// A body as the joint functions see it; col -1 leaves its columns out of a Jacobian.
BodyView viewOf(const BodyState& m, int col, bool withRates) {
  BodyView b;
  b.col = col;
  b.r = m.r;
  b.R = m.R;
  if (withRates) {
    b.v = m.v;
    b.w = m.w;
  }
  return b;
}

// The three rows: residual, the core's 3 x 3 Jacobian (theta column as is), and optionally the
// known bodies' contributions J_K x_K for a given x (velocities or accelerations).
struct Rows {
  Eigen::Vector3d phi;
  Eigen::Matrix3d J;
};

void evalRows(const CoreGroup& g, const BodyView& core, const Motion& m, Rows& out) {
  out.J.setZero();
  int row = 0;
  for (const CoreLink& l : g.links) {
    const BodyView k = viewOf(m.of(l.known), -1, false);  // only the core's columns
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
Eigen::Vector3d knownTerms(const CoreGroup& g, const BodyView& core, const Motion& m,
                           bool accelerations) {
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  BodyView noCore = core;
  noCore.col = -1;
  int row = 0;
  for (const CoreLink& l : g.links) {
    const int rows = l.pin ? 2 : 1;
    const BodyState& km = m.of(l.known);
    const BodyView k = viewOf(km, 0, accelerations);
    if (l.known >= 0) {
      Eigen::Matrix3d Jk = Eigen::Matrix3d::Zero();
      if (l.pin)
        pin::jacobian(Jk, row, noCore, l.s, k, l.ks);
      else
        line::jacobian(Jk, row, noCore, l.s, k, l.n);
      const Eigen::Vector3d x = accelerations ? Eigen::Vector3d(km.a.x(), km.a.y(), km.al)
                                              : Eigen::Vector3d(km.v.x(), km.v.y(), km.w);
      rhs.segment(row, rows) -= Jk.middleRows(row, rows) * x;
    }
    if (accelerations) {
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

int coreDetSign(const CoreGroup& g, const Eigen::VectorXd& q) {
  Motion m;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q.size());
  m.fromCoordinates(0, q, zero, zero);
  Rows rows;
  evalRows(g, viewOf(m.body[g.core], 0, false), m, rows);
  const double det = rows.J.determinant();
  const double scale = rows.J.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return 0;
  return det > 0 ? 1 : -1;
}

bool solveCore(const CoreGroup& g, const System& sys, const Motion& prev, Motion& next) {
  const double L = sys.size;
  const double h = next.phi - prev.phi;
  const BodyState& before = prev.body[g.core];
  BodyState& core = next.body[g.core];
  // Unknowns: the frame origin and the turn d relative to the previous rotation, from the
  // predictor along the previous rates.
  Eigen::Vector3d x;
  const double h2 = prev.accelerations ? 0.5 * h * h : 0.0;  // second order where known
  x << before.r + h * before.v + h2 * (prev.accelerations ? before.a : Vec2::Zero()),
      h * before.w + h2 * (prev.accelerations ? before.al : 0.0);
  auto pose = [&](const Eigen::Vector3d& at) {
    core.r = at.head<2>();
    const Rot d{std::cos(at[2]), std::sin(at[2])};
    core.R = Rot{before.R.c * d.c - before.R.s * d.s, before.R.s * d.c + before.R.c * d.s};
    return viewOf(core, 0, false);
  };
  Rows rows;
  Eigen::PartialPivLU<Eigen::Matrix3d> lu;
  bool converged = false, polished = false;
  double prevStep = INFINITY;
  for (int it = 0; it < 12; ++it) {
    evalRows(g, pose(x), next, rows);
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
  // The drawn branch: det J keeps its sign until a singular position.
  const BodyView at = pose(x);
  core.turns = turnsAfter(before.R, before.turns, core.R);
  evalRows(g, at, next, rows);
  const double det = rows.J.determinant();
  const double scale = rows.J.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale) || (det > 0 ? 1 : -1) != g.detSign)
    return false;
  lu.compute(rows.J);
  const Eigen::Vector3d v = lu.solve(knownTerms(g, at, next, false));
  core.v = v.head<2>();
  core.w = v[2];
  const Eigen::Vector3d a =
      next.accelerations
          ? Eigen::Vector3d(lu.solve(knownTerms(g, viewOf(core, 0, true), next, true)))
          : Eigen::Vector3d::Constant(NAN);
  core.a = a.head<2>();
  core.al = a[2];

  // The blocks: rotation, rate and acceleration of their slot body; pin point on the core.
  for (const CoreLink& l : g.links) {
    if (l.block < 0) continue;
    const BodyState& k = next.of(l.known);
    place(next.body[l.block], k.R, k.turns, k.w, k.al, l.blockPin, core.pos(l.s), core.vel(l.s),
          core.acc(l.s));
  }
  return true;
}

}  // namespace linkage
