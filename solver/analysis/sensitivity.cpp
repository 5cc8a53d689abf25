// dq/dp = -J_q^-1 J_p at a pose (linkage/sensitivity.h). J_p, row by row: a row's residual
// depends on a dimension only through its constants (the local vectors s of its points, a slot's
// point u and normal n, a gear's coefficients), whose derivatives come from how the element kind
// compiled them (elements/*.cpp) and the dimension's move of the drawing; with the frames held a
// sketch move is the same move of the local vector (frames are at angle 0 as drawn).
//
//   Coincident  Phi = r_i + R_i s_i - r_j - R_j s_j     dPhi = R_i ds_i - R_j ds_j
//   OnLine      Phi = (R_j n) . (p - q)                 dPhi = (R_j dn) . (p - q)
//                                                             + (R_j n) . (R_i ds_i - R_j du)
//   OnCircle    Phi = (d . d - rho^2) / (2 rho)         dPhi = d . (R_i ds_i) / rho  (centre and
//                                                             radius: arc slots have no dimension)
//   Angles      Phi = L (sum c_k theta_k - ...)         dPhi = L sum dc_k theta_k (a gear's ratio)
#include <Eigen/LU>
#include <cmath>

#include "kinematics/kinematics_state.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/sensitivity.h"
#include "system/system.h"

namespace linkage {

namespace {

struct Moves {  // one dimension's move of the drawing, by id value
  const std::vector<Vec2>& point;
  const Dimension& dim;
  Vec2 at(PointId p) const { return p.value < point.size() ? point[p.value] : Vec2::Zero(); }
};

// The block's point of a slider in an arc slot is compiled as the point at the arc's centre,
// p - radius (p - c) / |p - c|: its move for a move dp of p (the arc held).
Vec2 arcBlockMove(const Mechanism& m, const Joint& j, const Vec2& dp) {
  const std::optional<Guide> g = guideOf(*m.slot(j.slot));
  const Vec2 d = m.point(j.a)->pos - g->centre;
  const Vec2 u = d.normalized();
  return dp - g->radius / d.norm() * (dp - u * u.dot(dp));
}

// A straight slot's point u (its first end) and unit normal n as they move.
void slotMove(const Mechanism& m, const Joint& j, const Dimension& dim, Vec2& du, Vec2& dn) {
  du = dn = Vec2::Zero();
  for (const Dimension::SlotMove& s : dim.slots) {
    if (s.slot != j.slot) continue;
    const Slot& slot = *m.slot(j.slot);
    const Vec2 t = slot.p1 - slot.p0;
    const double len = t.norm();
    const Vec2 e = t / len, dt = s.p1 - s.p0;
    du = s.p0;
    dn = perp((dt - e * e.dot(dt)) / len);
  }
}

Vec2 coincident(const Mechanism& m, const Joint& j, const BodyView& bi, const BodyView& bj,
                const Moves& mv) {
  if (kindOf(j).role == Role::Prismatic) return bi.R * arcBlockMove(m, j, mv.at(j.a));
  return bi.R * mv.at(j.a) - bj.R * mv.at(j.b);
}

double onLine(const Mechanism& m, const Joint& j, const Row& r, const BodyView& bi,
              const BodyView& bj, const Moves& mv) {
  Vec2 du, dn;
  slotMove(m, j, mv.dim, du, dn);
  const Vec2 d = bi.r + bi.R * r.s[0] - bj.r - bj.R * r.s[1];
  return (bj.R * dn).dot(d) + (bj.R * r.n).dot(bi.R * mv.at(j.a) - bj.R * du);
}

double onCircle(const Joint& j, const Row& r, const BodyView& bi, const BodyView& bj,
                const Moves& mv) {
  const Vec2 d = bi.r + bi.R * r.s[0] - bj.r - bj.R * r.s[1];
  return d.dot(bi.R * mv.at(j.a)) / r.c[0];
}

double angles(const System& sys, const Joint& j, const Row& r, const std::vector<BodyView>& views,
              const Moves& mv) {
  if (r.isDriver() || kindOf(j).role != Role::Coupling || mv.dim.ratioOf != j.id) return 0;
  // theta_b - ratio theta_a + (ratio - 1) theta_c: dc = (0, -1, 1) per unit ratio.
  return sys.size * (-views[r.body[1] + 1].theta + views[r.body[2] + 1].theta);
}

// The derivative of every row's residual (at the views) with respect to one dimension.
void rowDerivatives(const Mechanism& m, const System& sys, const std::vector<BodyView>& views,
                    const Moves& mv, Eigen::VectorXd& out) {
  out.setZero(sys.nRows);
  for (const Row& r : sys.cons) {
    if (r.kind == Primitive::Hold) continue;
    const Joint& j = m.joints[r.joint];
    const BodyView &bi = views[r.body[0] + 1], &bj = views[r.body[1] + 1];
    switch (r.kind) {
      case Primitive::Coincident:
        out.segment<2>(r.row) = coincident(m, j, bi, bj, mv);
        break;
      case Primitive::OnLine:
        out[r.row] = onLine(m, j, r, bi, bj, mv);
        break;
      case Primitive::OnCircle:
        out[r.row] = onCircle(j, r, bi, bj, mv);
        break;
      case Primitive::Angles:
        out[r.row] = angles(sys, j, r, views, mv);
        break;
      default:
        break;
    }
  }
}

// What prepare() cannot differentiate, named; "" when it can.
std::string unsupported(const Mechanism& m, const System& sys) {
  if (sys.frames.size() > 1)
    return "sensitivities of a spatial model (planes) are not computed yet";
  for (const Row& r : sys.cons)
    if (r.kind == Primitive::Distance3)
      return "sensitivities through a ball rod (" + jointLabel(m, m.joints[r.joint].id) +
             ") are not computed yet";
  for (const Joint& j : m.joints) {
    const Role role = kindOf(j).role;
    if (role != Role::Revolute && role != Role::Prismatic && role != Role::PointOnCurve &&
        role != Role::Coupling)
      return std::string("sensitivities through a ") + kindOf(j).name + " (" + jointLabel(m, j.id) +
             ") are not computed yet";
  }
  return "";
}

}  // namespace

Status Sensitivity::prepare(const Kinematics& k, std::vector<Dimension> dims) {
  dims_ = std::move(dims);
  pointMove_.clear();
  dq_.resize(0, 0);
  if (!k.valid()) return Status::badModel("no mechanism is loaded");
  const KinematicsState& s = internal::state(k);
  if (std::string why = unsupported(s.mech, s.sys); !why.empty()) return Status::badModel(why);
  size_t ids = 0;
  for (const Point& p : s.mech.points) ids = std::max<size_t>(ids, p.id.value + 1);
  pointMove_.assign(dims_.size(), std::vector<Vec2>(ids, Vec2::Zero()));
  for (size_t d = 0; d < dims_.size(); ++d)
    for (const auto& [p, move] : dims_[d].points)
      if (p.value < ids) pointMove_[d][p.value] += move;
  return Status::success();
}

Status Sensitivity::at(const Kinematics& k) {
  const KinematicsState& s = internal::state(k);
  if (!k.valid() || !k.derivativesValid() || pointMove_.size() != dims_.size())
    return Status::failure(StatusCode::Singular,
                           "at a singular position the motion's derivatives are unbounded");
  const System& sys = s.sys;
  const Eigen::VectorXd& q = k.q();
  std::vector<BodyView> views;
  makeViews(sys, q, nullptr, views);
  const std::vector<int>& map = s.newton.rowMap();
  const int n = sys.nCoords();
  Eigen::MatrixXd J(n, n), Jp(n, static_cast<int>(dims_.size()));
  evalJacobian(sys, views, map, J);
  Eigen::VectorXd rows;
  for (size_t d = 0; d < dims_.size(); ++d) {
    rowDerivatives(s.mech, sys, views, Moves{pointMove_[d], dims_[d]}, rows);
    Jp.col(static_cast<int>(d)).setZero();
    for (int r = 0; r < sys.nRows; ++r)
      if (map[r] >= 0) Jp(map[r], static_cast<int>(d)) = rows[r];
  }
  dq_ = -Eigen::PartialPivLU<Eigen::MatrixXd>(J).solve(Jp);
  if (!dq_.allFinite())
    return Status::failure(StatusCode::Singular,
                           "at a singular position the motion's derivatives are unbounded");
  return Status::success();
}

Vec2 Sensitivity::point(const Kinematics& k, PointId p, int dim) const {
  const System& sys = internal::system(k);
  const PointLocation* loc = sys.point(p);
  const Vec2 own = p.value < pointMove_[dim].size() ? pointMove_[dim][p.value] : Vec2::Zero();
  if (!loc || loc->body < 0) return own;
  const int c = 3 * loc->body;
  const Rot R = Rot::of(k.q()[c + 2]);
  const Vec2 a = R * loc->s;
  return Vec2(dq_(c, dim), dq_(c + 1, dim)) + dq_(c + 2, dim) * perp(a) + R * own;
}

}  // namespace linkage
