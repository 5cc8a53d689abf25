// A pin's reaction differentiated with respect to the dimensions: see
// linkage/force_sensitivity.h.
#include "linkage/force_sensitivity.h"

#include <Eigen/LU>
#include <algorithm>

#include "kinematics/kinematics_state.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage {

namespace {

// dQ/dp: each body's applied and inertia force m (g - a) / 1000 and its moment about the frame
// origin, cross(R c, F) - j omega^2 alpha / 1000, with the loads' moments; a dimension moves no
// mass (its centre stays in its body) and no load's force.
Eigen::VectorXd forcesChange(const Kinematics& k, const Sensitivity& s, int dim) {
  const KinematicsState& st = internal::state(k);
  const System& sys = st.sys;
  Eigen::VectorXd dQ = Eigen::VectorXd::Zero(sys.nCoords());
  const double w2 = k.omega() * k.omega();
  const Vec2 gravity = st.mech.gravity.value_or(Vec2::Zero());
  for (const Body& b : st.mech.bodies) {
    const int i = sys.bodyIndex(b.id);
    if (i < 0 || !b.mass || b.mass->kg == 0) continue;
    const double w = k.dq()[3 * i + 2], alpha = k.ddq()[3 * i + 2];
    const Vec2 g = Rot::of(k.q()[3 * i + 2]) * Vec2(b.mass->com - sys.frameOrigin[i]);
    const Vec2 acc = w2 * (Vec2(k.ddq().segment<2>(3 * i)) + alpha * perp(g) - w * w * g);
    const Vec2 F = b.mass->kg * (gravity - acc / 1000);
    const Vec2 dF = -b.mass->kg * s.acceleration(k, b.id, b.mass->com, dim) / 1000;
    const Vec2 dg = s.dq()(3 * i + 2, dim) * perp(g);
    dQ.segment<2>(3 * i) += dF;
    dQ[3 * i + 2] +=
        cross(dg, F) + cross(g, dF) - b.mass->jKgMm2 * w2 * s.dqdd()(3 * i + 2, dim) / 1000;
  }
  for (const Load& l : st.mech.loads) {
    if (!l.point || !l.activeAt(k.crankDeg())) continue;
    const PointLocation* p = sys.point(l.point);
    if (!p || p->body < 0) continue;
    // The arm from the frame origin: the point's move less the origin's.
    const Vec2 dat = s.point(k, l.point, dim) - Vec2(s.dq().block<2, 1>(3 * p->body, dim));
    dQ[3 * p->body + 2] += cross(dat, l.forceN);
  }
  return dQ;
}

}  // namespace

JointForceSensitivity jointForceSensitivity(const Kinematics& k0, JointId joint,
                                            std::vector<Dimension> dims) {
  JointForceSensitivity out;
  Kinematics k = k0;
  k.setAccelerations(true);
  const Mechanism& m = k.mechanism();
  const int ji = m.jointIndex(joint);
  if (ji < 0) return out.status = Status::badModel("no such joint"), out;
  const std::string name = jointLabel(m, joint);
  if (kindOf(m.joints[ji]).role != Role::Revolute)
    return out.status = Status::badModel(name + ": only a pin's reaction is differentiated yet"),
           out;
  if (isSpatial(m))
    return out.status = Status::badModel(
               "a machine in space's reactions are not "
               "differentiated yet"),
           out;
  const KinematicsState& st = internal::state(k);
  if (st.sys.contactRows)
    return out.status = Status::badModel("reactions through a cam are not differentiated yet"), out;
  const Forces f = computeForces(k);
  if (!f.status.ok()) return out.status = f.status, out;
  if (!f.undetermined.empty())
    return out.status = Status::badModel(
               "redundant joints: their reactions' shares are not "
               "determined, nor their derivatives"),
           out;
  out.force = f.joints[ji].force;
  Sensitivity s;
  if (out.status = s.prepare(k, std::move(dims)); !out.status.ok()) return out;
  if (out.status = s.at(k); !out.status.ok()) return out;
  out.dims = s.dims();
  const System& sys = st.sys;
  const std::vector<int>& map = st.newton.rowMap();
  std::vector<BodyView> views;
  makeViews(sys, k.q(), &k.dq(), views);
  Eigen::MatrixXd J(sys.nCoords(), sys.nCoords());
  evalJacobian(sys, views, map, J);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
  const Eigen::VectorXd lambda = lu.transpose().solve(generalizedForces(k));
  // The pin's rows, and on which side its point a is (the reaction is on a's body).
  const Row* row = nullptr;
  for (const Row& r : sys.cons)
    if (r.joint == ji && r.kind == Primitive::Coincident) row = &r;
  if (!row || map[row->row] < 0 || map[row->row + 1] < 0)
    return out.status = Status::badModel(name + ": its rows are not independent"), out;
  const PointLocation* a = sys.point(m.joints[ji].a);
  const double sign = a && row->body[0] == a->body ? 1 : -1;
  Eigen::VectorXd w[2];
  for (int e = 0; e < 2; ++e)
    w[e] = lu.solve(Eigen::VectorXd::Unit(sys.nCoords(), map[row->row + e]));
  for (size_t d = 0; d < out.dims.size(); ++d) {
    const int dim = static_cast<int>(d);
    const Eigen::VectorXd dQ = forcesChange(k, s, dim);
    Vec2 dl;
    for (int e = 0; e < 2; ++e) dl[e] = w[e].dot(dQ) - lambda.dot(s.jacobianChange(k, w[e], dim));
    out.derivative.push_back(-sign * dl);
  }
  if (!std::all_of(out.derivative.begin(), out.derivative.end(),
                   [](const Vec2& v) { return v.allFinite(); }))
    out.status = Status::failure(StatusCode::Singular, "the reaction's derivatives are unbounded");
  return out;
}

}  // namespace linkage
