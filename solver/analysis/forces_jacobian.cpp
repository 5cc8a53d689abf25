// The forces' Jacobian and its change: see analysis/forces_jacobian.h.
#include "analysis/forces_jacobian.h"

#include "elements/cam_row.h"
#include "kinematics/kinematics_state.h"
#include "linkage/cam_joint.h"
#include "system/system.h"

namespace linkage {

namespace {

Vec2 perp2(const Vec2& v) {
  return perp(v);
}

// A body's frame origin's move and turn along dim (none for the ground).
struct BodyMove {
  Vec2 dr = Vec2::Zero();
  double dtheta = 0;
};

BodyMove bodyMove(const Sensitivity& s, int body, int dim) {
  if (body < 0) return {};
  return {Vec2(s.dq().block<2, 1>(3 * body, dim)), s.dq()(3 * body + 2, dim)};
}

// The point on the guide the oscillating follower of cam c turns about.
PointId pivotOnGuide(const Mechanism& m, const CamJoint& c) {
  const Joint& f = *m.joint(c.followerJoint);
  return m.point(f.a)->body == c.guide ? f.a : f.b;
}

// The contact's Place at the pose and its move along dim (each member's derivative).
void places(const Kinematics& k, const Sensitivity& s, const Row& r, const BodyView v[3], int dim,
            cam::Place& at, cam::Place& move) {
  const Mechanism& m = k.mechanism();
  const Joint& j = m.joints[r.joint];
  const CamRow& row = *r.cam;
  const BodyView &f = v[0], &c = v[1], &g = v[2];
  at.centre = c.r + c.R * row.centre;
  at.b = f.r + f.R * r.s[0];
  at.along = g.R * row.along;
  at.pivot = g.r + g.R * row.pivot;
  at.face = f.R * row.face;
  const BodyMove gm = bodyMove(s, r.body[2], dim), fm = bodyMove(s, r.body[0], dim);
  move.centre = s.point(k, j.a, dim);
  move.b = s.point(k, j.b, dim);
  move.along = gm.dtheta * perp2(at.along) + g.R * s.camRowMove(dim, r.joint).along;
  move.face = (fm.dtheta + s.camRowMove(dim, r.joint).faceTurn) * perp2(at.face);
  move.pivot = Vec2::Zero();
  if (row.kind.oscillating)
    if (const std::optional<CamJoint> cj = camJoint(m, j))
      move.pivot = s.point(k, pivotOnGuide(m, *cj), dim);
}

double contactRowChange(const Kinematics& k, const Sensitivity& s, const Row& r,
                        const std::vector<BodyView>& views, const Eigen::VectorXd& w, int dim) {
  BodyView v[3];
  for (int b = 0; b < 3; ++b) v[b] = views[r.body[b] + 1];
  cam::Place at, move;
  places(k, s, r, v, dim, at, move);
  const CamRow& row = *r.cam;
  const double theta = cam_row::theta(v[1], v[2]);
  const cam::Displacement law = row.program.at(theta);
  const Dimension& d = s.dims()[dim];
  const double perRise =
      d.camOf == k.mechanism().joints[r.joint].id ? row.program.perRise(theta, d.camRises).v : 0;
  const double dtheta = bodyMove(s, r.body[1], dim).dtheta - bodyMove(s, r.body[2], dim).dtheta;
  const cam::Contact ct = cam::contact(row.kind, at, law.v);
  const cam::Contact dct = cam::contactChange(row.kind, at, move, law.v, perRise + law.a * dtheta);
  // The follower's (f) and the cam's (c) velocity at the contact under w, and their change.
  Vec2 rel = Vec2::Zero(), drel = Vec2::Zero();
  for (int b = 0; b < 2; ++b) {
    const int body = r.body[b];
    if (body < 0) continue;
    const double sign = b == 0 ? 1 : -1, wt = w[3 * body + 2];
    const BodyMove bm = bodyMove(s, body, dim);
    rel += sign * (Vec2(w.segment<2>(3 * body)) + wt * perp2(ct.point - v[b].r));
    drel += sign * wt * perp2(dct.point - bm.dr);
  }
  return dct.normal.dot(rel) + ct.normal.dot(drel);
}

}  // namespace

Eigen::MatrixXd forcesJacobian(const Kinematics& k) {
  const KinematicsState& st = internal::state(k);
  const System& sys = st.sys;
  const std::vector<int>& map = st.newton.rowMap();
  std::vector<BodyView> views;
  makeViews(sys, k.q(), &k.dq(), views);
  Eigen::MatrixXd J(sys.nCoords(), sys.nCoords());
  evalJacobian(sys, views, map, J);
  for (const Row& r : sys.cons) {
    if (r.kind != Primitive::Cam || map[r.row] < 0) continue;
    const Eigen::Matrix<double, 2, 9> B = rowJacobian(sys, views, r);
    J.row(map[r.row]).setZero();
    for (int b = 0; b < 3; ++b)
      if (r.body[b] >= 0) J.block<1, 3>(map[r.row], 3 * r.body[b]) = B.block<1, 3>(0, 3 * b);
  }
  return J;
}

Eigen::VectorXd forcesJacobianChange(const Kinematics& k, const Sensitivity& s,
                                     const Eigen::VectorXd& w, int dim) {
  Eigen::VectorXd out = s.jacobianChange(k, w, dim);
  const KinematicsState& st = internal::state(k);
  if (!st.sys.contactRows) return out;
  const std::vector<int>& map = st.newton.rowMap();
  std::vector<BodyView> views;
  makeViews(st.sys, k.q(), nullptr, views);
  for (const Row& r : st.sys.cons)
    if (r.kind == Primitive::Cam && map[r.row] >= 0)
      out[map[r.row]] = contactRowChange(k, s, r, views, w, dim);
  return out;
}

}  // namespace linkage
