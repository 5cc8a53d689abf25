#include "kinematics/core_group.h"

#include <Eigen/LU>
#include <cmath>

#include "elements/coincident.h"
#include "elements/on_line.h"

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
      out.phi.segment<2>(row) = coincident::residual(core, l.s, k, l.ks);
      coincident::jacobian(out.J, row, core, l.s, k, l.ks);
      row += 2;
    } else {
      out.phi[row] = on_line::residual(core, l.s, k, l.ks, l.n);
      on_line::jacobian(out.J, row, core, l.s, k, l.n);
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
        coincident::jacobian(Jk, row, noCore, l.s, k, l.ks);
      else
        on_line::jacobian(Jk, row, noCore, l.s, k, l.n);
      const Eigen::Vector3d x = accelerations ? Eigen::Vector3d(km.a.x(), km.a.y(), km.al)
                                              : Eigen::Vector3d(km.v.x(), km.v.y(), km.w);
      rhs.segment(row, rows) -= Jk.middleRows(row, rows) * x;
    }
    if (accelerations) {
      if (l.pin)
        rhs.segment<2>(row) += coincident::gamma(core, l.s, k, l.ks);
      else
        rhs[row] += on_line::gamma(core, l.s, k, l.ks, l.n);
    }
    row += rows;
  }
  return rhs;
}

// Sign of det J, 0 where J is (near) singular.
int detSign(const Eigen::Matrix3d& J) {
  const double det = J.determinant();
  const double scale = J.cwiseAbs().maxCoeff();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return 0;
  return det > 0 ? 1 : -1;
}

// The same of the core's 3 x 3 Jacobian with the core at `core`.
int detSignAt(const CoreGroup& g, const BodyState& core, const Motion& m) {
  Rows rows;
  evalRows(g, viewOf(core, 0, false), m, rows);
  return detSign(rows.J);
}

}  // namespace

int coreDetSign(const CoreGroup& g, const Motion& m) {
  return detSignAt(g, m.body[g.core], m);
}

bool corePose(const CoreGroup& g, const Motion& m, BodyState& pose) {
  // Rows M (x, y, c, s) = b: a pin r + R s = K gives two, a line n . (r + R s - U) = 0 one, with
  // R s = (c s_x - s s_y, s s_x + c s_y).
  Eigen::Matrix<double, 3, 4> M;
  Eigen::Vector3d b;
  int row = 0;
  for (const CoreLink& l : g.links) {
    const BodyState& k = m.of(l.known);
    const Vec2& s = l.s;
    if (l.pin) {
      const Vec2 K = k.pos(l.ks);
      M.row(row) << 1, 0, s.x(), -s.y();
      M.row(row + 1) << 0, 1, s.y(), s.x();
      b.segment<2>(row) = K;
      row += 2;
    } else {
      const Vec2 n = k.R * l.n;
      M.row(row) << n.x(), n.y(), n.dot(s), cross(s, n);
      b[row] = n.dot(k.pos(l.ks));
      row += 1;
    }
  }
  Eigen::FullPivLU<Eigen::Matrix<double, 3, 4>> lu(M);
  if (lu.rank() < 3) return false;
  const Eigen::Vector4d x0 = lu.solve(b);
  const Eigen::Vector4d k = lu.kernel().col(0);
  // |x0.cs + t k.cs|^2 = 1: a t^2 + 2 bh t + c = 0.
  const Vec2 p = x0.tail<2>(), q = k.tail<2>();
  const double a = q.squaredNorm(), bh = p.dot(q), c = p.squaredNorm() - 1;
  const double disc = bh * bh - a * c;
  if (!(a > 0) || !(disc >= 0)) return false;
  const double root = std::sqrt(disc);
  // The two roots without cancellation: t1 t2 = c / a.
  const double t1 = (-bh - std::copysign(root, bh)) / a;
  const double t2 = t1 != 0 ? c / (a * t1) : (-bh + root) / a;
  for (double t : {t1, t2}) {
    const Eigen::Vector4d x = x0 + t * k;
    const double n = x.tail<2>().norm();
    pose.r = x.head<2>();
    pose.R = Rot{x[2] / n, x[3] / n};
    if (detSignAt(g, pose, m) == g.detSign) return true;
  }
  return false;
}

bool solveCore(const CoreGroup& g, const System& sys, const Motion& prev, Motion& next,
               const BodyState* start) {
  const double L = sys.size;
  const double h = next.phi - prev.phi;
  const BodyState& before = prev.body[g.core];
  BodyState& core = next.body[g.core];
  // Unknowns: the frame origin and the turn d relative to a base rotation: the previous one,
  // with the predictor along the previous rates, or the start's.
  Eigen::Vector3d x;
  const Rot base = start ? start->R : before.R;
  if (start) {
    x << start->r, 0.0;
  } else {
    const double h2 = prev.accelerations ? 0.5 * h * h : 0.0;  // second order where known
    x << before.r + h * before.v + h2 * (prev.accelerations ? before.a : Vec2::Zero()),
        h * before.w + h2 * (prev.accelerations ? before.al : 0.0);
  }
  auto pose = [&](const Eigen::Vector3d& at) {
    core.r = at.head<2>();
    const Rot d{std::cos(at[2]), std::sin(at[2])};
    core.R = Rot{base.c * d.c - base.s * d.s, base.s * d.c + base.c * d.s};
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
  core.turns =
      start ? nearestTurns(before.angle(), core.R) : turnsAfter(before.R, before.turns, core.R);
  evalRows(g, at, next, rows);
  if (detSign(rows.J) != g.detSign) return false;
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
