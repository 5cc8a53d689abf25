// A joint's reaction differentiated with respect to the dimensions: see
// linkage/force_sensitivity.h.
#include "linkage/force_sensitivity.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "analysis/bearing_change.h"
#include "analysis/forces_jacobian.h"
#include "kinematics/kinematics_state.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage {

namespace {

// dQ/dp (linkage/dynamics.h generalizedForcesChange): a load's arm from its body's frame origin
// moves as its point less the origin.
Eigen::VectorXd forcesChangeOf(const Kinematics& k, const Sensitivity& s, int dim) {
  const System& sys = internal::state(k).sys;
  const Mechanism& m = k.mechanism();
  // A point's own move in its body (turned into the frame's axes): its move less the body's.
  auto own = [&](PointId p) {
    const PointLocation* at = sys.point(p);
    const Vec2 arm = Rot::of(k.q()[3 * at->body + 2]) * at->s;
    return Vec2(s.point(k, p, dim) - Vec2(s.dq().block<2, 1>(3 * at->body, dim)) -
                s.dq()(3 * at->body + 2, dim) * perp(arm));
  };
  std::function<Vec2(int)> comMove;
  if (s.dims()[dim].carriesMasses)  // every point of a body in the plane moves alike
    comMove = [&](int body) {
      for (const Point& p : m.points)
        if (sys.bodyIndex(p.body) == body) return own(p.id);
      return Vec2(Vec2::Zero());
    };
  return generalizedForcesChange(
      k, s.dq().col(dim), s.dqd().col(dim), s.dqdd().col(dim),
      [&](PointId p) {
        const PointLocation* at = sys.point(p);
        return Vec2(s.point(k, p, dim) - Vec2(s.dq().block<2, 1>(3 * at->body, dim)));
      },
      comMove);
}

// A joint's reaction as its rows make it: the generalized force -sum lambda_r J_r on one body
// (its force and its moment about that body's frame origin), read about the joint's point a; the
// rows are the kinematics' (independent) ones.
struct RowsReaction {
  int joint = -1;
  std::vector<int> rows, cams, rods;  // J's rows; of them, a cam's contact, a ball rod's
  int body = -1;                      // the moving body it is read on
  double flip = 1;                    // -1: that body is the other side (a is on the ground)
  PointId a;
  // On a machine in space, a on the ground (not a ball rod's end): the class frame the rows hold
  // it in (the body's) and its place there (as linkage/dynamics.h reads it), else -1.
  int groundClass = -1;
  Vec2 groundAt = Vec2::Zero();
  Vec2 place(const Kinematics& k) const { return groundClass >= 0 ? groundAt : k.position(a); }
  // Its move along dim: a ground point's world move seen in that frame.
  Vec2 move(const Kinematics& k, const Sensitivity& s, int dim) const {
    if (groundClass < 0) return s.point(k, a, dim);
    const Plane& f = internal::state(k).sys.frames[groundClass];
    const Vec3 w = s.point3(k, a, dim);
    return Vec2(w.dot(f.xAxis), w.dot(f.yAxis));
  }
};

std::string rowsOf(const KinematicsState& st, int ji, RowsReaction& out) {
  const System& sys = st.sys;
  const std::vector<int>& map = st.newton.rowMap();
  out = {};
  out.joint = ji;
  out.a = st.mech.joints[ji].a;
  out.body = sys.point(out.a)->body;
  for (const Row& r : sys.cons) {
    if (r.joint != ji || r.isDriver() || r.kind == Primitive::Hold) continue;
    for (int e = 0; e < r.rows(); ++e) {
      if (map[r.row + e] < 0) return "its rows are not independent";
      out.rows.push_back(map[r.row + e]);
      if (r.kind == Primitive::Cam) out.cams.push_back(map[r.row + e]);
      if (r.kind == Primitive::Distance3) out.rods.push_back(map[r.row + e]);
    }
    if (out.body >= 0 && out.flip > 0) continue;
    // a on the ground: the reaction is what the other side bears, turned round.
    if (r.bodies() > 2) return "a on the ground with rows on three bodies";
    out.flip = -1;
    out.body = r.body[0] >= 0 ? r.body[0] : r.body[1];
  }
  const Point* a = st.mech.point(out.a);
  if (isSpatial(st.mech) && out.body >= 0 && out.rods.empty() && sys.point(out.a)->body < 0) {
    out.groundClass = sys.classOf[out.body];
    out.groundAt = inClassFrame(st.mech, planeClasses(st.mech), *a, out.groundClass);
  }
  return "";
}

// The derivatives' common parts at one pose.
struct Context {
  const Kinematics& k;
  const Sensitivity& s;
  Eigen::MatrixXd J;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd lambda, Q;
  internal::Balance balance() const { return {J, lu, lambda, Q}; }
};

Eigen::Vector3d generalized(const Eigen::MatrixXd& J, const RowsReaction& r,
                            const Eigen::VectorXd& lambda) {
  Eigen::Vector3d G = Eigen::Vector3d::Zero();
  if (r.body < 0) return G;
  for (int row : r.rows) G -= lambda[row] * J.block<1, 3>(row, 3 * r.body).transpose();
  return G;
}

JointReaction value(const Context& c, const RowsReaction& r) {
  JointReaction out;
  const Eigen::Vector3d G = generalized(c.J, r, c.lambda);
  out.at = r.place(c.k);
  if (r.body >= 0) {
    const Vec2 origin = c.k.q().segment<2>(3 * r.body), F = G.head<2>();
    out.force = r.flip * F;
    out.coupleNm = r.flip * (G[2] - cross(out.at - origin, F)) / 1000;
  }
  for (int row : r.cams) out.contactN = -c.lambda[row];
  for (int row : r.rods) out.axialN = c.lambda[row];  // the tension (analysis/space_forces.h)
  return out;
}

// Its derivative along dimension dim, dQ the generalized forces' (forcesChange): each row's
// multiplier's (header) and the rows' own turn, dG = -sum (dlambda_r J_r + lambda_r dJ_r).
JointReaction change(const Context& c, const RowsReaction& r, int dim, const Eigen::VectorXd& dQ) {
  const int n = static_cast<int>(c.lambda.size());
  std::vector<double> dl;
  for (int row : r.rows) {
    const Eigen::VectorXd w = c.lu.solve(Eigen::VectorXd::Unit(n, row));
    dl.push_back(w.dot(dQ) - c.lambda.dot(forcesJacobianChange(c.k, c.s, w, dim)));
  }
  JointReaction out;
  out.at = r.move(c.k, c.s, dim);
  for (size_t e = 0; e < r.rows.size(); ++e) {
    for (int row : r.cams)
      if (r.rows[e] == row) out.contactN = -dl[e];
    for (int row : r.rods)
      if (r.rows[e] == row) out.axialN = dl[e];
  }
  if (r.body < 0) return out;
  Eigen::Vector3d dG = Eigen::Vector3d::Zero();
  for (int col = 0; col < 3; ++col) {
    const Eigen::VectorXd dJ =
        forcesJacobianChange(c.k, c.s, Eigen::VectorXd::Unit(n, 3 * r.body + col), dim);
    for (int row : r.rows) dG[col] -= c.lambda[row] * dJ[row];
  }
  for (size_t e = 0; e < r.rows.size(); ++e)
    dG -= dl[e] * c.J.block<1, 3>(r.rows[e], 3 * r.body).transpose();
  const Eigen::Vector3d G = generalized(c.J, r, c.lambda);
  const Vec2 at = r.place(c.k), origin = c.k.q().segment<2>(3 * r.body), F = G.head<2>();
  const Vec2 dOrigin = c.s.dq().block<2, 1>(3 * r.body, dim), dF = dG.head<2>();
  out.force = r.flip * dF;
  out.coupleNm = r.flip * (dG[2] - cross(out.at - dOrigin, F) - cross(at - origin, dF)) / 1000;
  return out;
}

// Positions at k's pose and their moves along one dimension, for the kinds' reactChange().
struct SensitivityPose : Pose {
  const Kinematics& k;
  const Sensitivity& s;
  int dim = 0;
  SensitivityPose(const Kinematics& kin, const Sensitivity& sens) : k(kin), s(sens) {}
  Vec2 point(PointId p) const override { return k.position(p); }
  Transform body(BodyId b) const override { return k.bodyTransform(b); }
  Vec2 drawnMove(PointId p) const {
    for (const auto& [id, move] : s.dims()[dim].points)
      if (id == p) return move;
    return Vec2::Zero();
  }
};

struct PointChange : PoseChange {
  const SensitivityPose& pose;
  explicit PointChange(const SensitivityPose& p) : pose(p) {}
  Vec2 point(PointId p) const override { return pose.s.point(pose.k, p, pose.dim); }
  Vec2 drawn(PointId p) const override { return pose.drawnMove(p); }
  double ratio(JointId j) const override { return pose.s.dims()[pose.dim].ratioOf == j ? 1 : 0; }
};

// What cannot be differentiated here, named; "" when the joint's reaction can be.
std::string refused(const Kinematics& k, const Forces& f) {
  const Mechanism& m = k.mechanism();
  if (!f.undetermined.empty())
    return "redundant joints: their reactions' shares are not determined, nor their derivatives";
  for (const Joint& j : m.joints)
    if (kindOf(j).react && !kindOf(j).reactChange)
      return jointLabel(m, j.id) + ": its restated reaction is not differentiated yet";
  return "";
}

// The reactions that make joint ji's: its own and the restated ones (a gear's moves its pivots').
std::vector<int> involved(const Mechanism& m, int ji) {
  std::vector<int> out{ji};
  for (size_t j = 0; j < m.joints.size(); ++j)
    if (kindOf(m.joints[j]).reactChange && static_cast<int>(j) != ji)
      out.push_back(static_cast<int>(j));
  return out;
}

// A counterweight's generalized forces on its body (system index i), N and N mm: columns of a
// mass, a static moment and the |s|^2 / m of its moment of inertia about the pivot, which act
// linearly (put's three numbers). On a machine in space in the body's class frame, as the
// solve holds it: its moment turned from its plane into that frame, gravity's part in it.
struct CounterweightForces {
  const Kinematics& k;
  const Counterweight& cw;
  int i;
  Eigen::MatrixXd& Q;
  Vec2 g = Vec2::Zero();  // m/s^2, in the class frame
  Rot toClass;            // the body's plane into its class frame
  CounterweightForces(const Kinematics& kin, const Counterweight& c, int index, Eigen::MatrixXd& q)
      : k(kin), cw(c), i(index), Q(q) {
    const Mechanism& m = k.mechanism();
    g = m.gravity.value_or(Vec2::Zero());
    if (!isSpatial(m)) return;
    const System& sys = internal::state(k).sys;
    const Plane& f = sys.frames[sys.classOf[i]];
    g = Vec2(m.gravityWorld().dot(f.xAxis), m.gravityWorld().dot(f.yAxis));
    toClass = planeClasses(m).of(m.body(cw.body)->plane).rot;
  }
  void put(int col, double kg, const Vec2& moment, double spin) const {
    const Rot R = Rot::of(k.bodyAngle(cw.body));
    const double w = k.bodyOmega(cw.body), alpha = k.bodyAlpha(cw.body);
    const Vec2 Rs = R * (toClass * moment);
    const Vec2 arm = k.position(cw.pivot) - Vec2(k.q().segment<2>(3 * i));
    const Vec2 F = kg * g + 1e-3 * (w * w * Rs - alpha * perp(Rs));  // its weight and inertia
    Q.block<2, 1>(3 * i, col) = F;
    Q(3 * i + 2, col) = cross(arm, F) + cross(Rs, g) - 1e-3 * alpha * spin;
  }
  // Its weight as a bearing's load out of the plane reads it (analysis/bearing_change.h): its
  // mass and first moment about the body's frame origin, kg (pivot - r) + R s; the moment's
  // change with the body turned by dTheta and the pivot moved along dim.
  internal::BodyWeight weight(double kg, const Vec2& moment) const {
    const Vec2 Rs = Rot::of(k.bodyAngle(cw.body)) * (toClass * moment);
    return {kg, kg * (k.position(cw.pivot) - Vec2(k.q().segment<2>(3 * i))) + Rs, Vec2::Zero()};
  }
  internal::BodyWeight weightChange(const Sensitivity& s, int dim, double dTheta, double kg,
                                    const Vec2& moment) const {
    internal::BodyWeight w = weight(kg, moment);
    const Vec2 Rs = w.moment - kg * (k.position(cw.pivot) - Vec2(k.q().segment<2>(3 * i)));
    w.dMoment =
        kg * (s.point(k, cw.pivot, dim) - Vec2(s.dq().block<2, 1>(3 * i, dim))) + dTheta * perp(Rs);
    return w;
  }
  // The same forces' change along dimension dim (its mass, moment and spin held): the body
  // turned by dTheta, its spin and spin's rate changed, the pivot's arm from the body's frame
  // origin moved.
  //   dF = 1e-3 (2 w dw Rs + w^2 dRs - dalpha perp(Rs) - alpha perp(dRs)), dRs = dTheta perp(Rs)
  //   dM = darm x F + arm x dF + dRs x g - 1e-3 dalpha spin
  Eigen::VectorXd change(const Sensitivity& s, int dim, double dTheta, double kg,
                         const Vec2& moment, double spin) const {
    const Rot R = Rot::of(k.bodyAngle(cw.body));
    const double w = k.bodyOmega(cw.body), alpha = k.bodyAlpha(cw.body);
    const double dw = s.angularVelocity(k, cw.body, dim),
                 da = s.angularAcceleration(k, cw.body, dim);
    const Vec2 Rs = R * (toClass * moment), dRs = dTheta * perp(Rs);
    const Vec2 arm = k.position(cw.pivot) - Vec2(k.q().segment<2>(3 * i));
    const Vec2 dArm = s.point(k, cw.pivot, dim) - Vec2(s.dq().block<2, 1>(3 * i, dim));
    const Vec2 F = kg * g + 1e-3 * (w * w * Rs - alpha * perp(Rs));
    const Vec2 dF = 1e-3 * (2 * w * dw * Rs + w * w * dRs - da * perp(Rs) - alpha * perp(dRs));
    Eigen::VectorXd dQ = Eigen::VectorXd::Zero(Q.rows());
    dQ.segment<2>(3 * i) = dF;
    dQ[3 * i + 2] = cross(dArm, F) + cross(arm, dF) + cross(dRs, g) - 1e-3 * da * spin;
    return dQ;
  }
};

// Positions at k's pose, and no move: a share of the forces at a held pose, for reactChange().
struct HeldPose : Pose, PoseChange {
  const Kinematics& k;
  explicit HeldPose(const Kinematics& kin) : k(kin) {}
  Vec2 point(PointId p) const override { return k.position(p); }
  Transform body(BodyId b) const override { return k.bodyTransform(b); }
  Vec2 drawn(PointId) const override { return Vec2::Zero(); }
  double ratio(JointId) const override { return 0; }
};

// What both derivatives start from: k with its accelerations, the joint's place, its reaction,
// and the rows of the reactions that make it (involved()).
struct Setup {
  Kinematics k;
  int ji = -1;
  JointReaction reaction;
  std::vector<int> joints;
  std::vector<RowsReaction> rows;

  // The joint's reaction's change: each involved reaction as its rows make it (at c) and its
  // change (rowChange of its rows), both restated as the kinds restate them (reactChange).
  template <class RowChange>
  JointReaction restated(const Context& c, const Pose& pose, const PoseChange& dpose,
                         RowChange rowChange) const {
    const Mechanism& m = k.mechanism();
    std::vector<JointReaction> all(m.joints.size()), changes(m.joints.size());
    for (size_t i = 0; i < joints.size(); ++i) {
      all[joints[i]] = value(c, rows[i]);
      changes[joints[i]] = rowChange(rows[i]);
    }
    for (int j : joints)
      if (kindOf(m.joints[j]).reactChange)
        kindOf(m.joints[j]).reactChange(m, j, pose, dpose, all, changes);
    return changes[ji];
  }
};

Status setUp(const Kinematics& k0, JointId joint, Setup& s) {
  s.k = k0;
  s.k.setAccelerations(true);
  const Mechanism& m = s.k.mechanism();
  s.ji = m.jointIndex(joint);
  if (s.ji < 0) return Status::badModel("no such joint");
  const Forces f = computeForces(s.k);
  if (!f.status.ok()) return f.status;
  if (std::string why = refused(s.k, f); !why.empty())
    return Status::badModel(jointLabel(m, joint) + ": " + why);
  s.reaction = f.joints[s.ji];
  s.joints = involved(m, s.ji);
  s.rows.resize(s.joints.size());
  for (size_t i = 0; i < s.joints.size(); ++i)
    if (std::string why = rowsOf(internal::state(s.k), s.joints[i], s.rows[i]); !why.empty())
      return Status::badModel(jointLabel(m, m.joints[s.joints[i]].id) + ": " + why);
  return Status::success();
}

// setUp, and the counterweight's body's index in the system.
Status shareSetUp(const Kinematics& k0, JointId joint, const Counterweight& cw, Setup& su, int& i) {
  if (Status s = setUp(k0, joint, su); !s.ok()) return s;
  i = internal::state(su.k).sys.bodyIndex(cw.body);
  return i < 0 ? Status::badModel("a counterweight on no moving body") : Status::success();
}

// The forces' Jacobian at k's pose, factored, and the multipliers.
Context factored(const Kinematics& k, const Sensitivity& s) {
  Context c{k, s, forcesJacobian(k), {}, {}, generalizedForces(k)};
  c.lu.compute(c.J);
  c.lambda = c.lu.transpose().solve(c.Q);
  return c;
}

}  // namespace

bool bearsOutOfPlane(const Kinematics& k, JointId joint) {
  const int ji = k.valid() ? k.mechanism().jointIndex(joint) : -1;
  return ji >= 0 && internal::BearingChange(k, ji).bears();
}

JointForceSensitivity jointForceSensitivity(const Kinematics& k0, JointId joint,
                                            std::vector<Dimension> dims) {
  JointForceSensitivity out;
  Setup su;
  if (out.status = setUp(k0, joint, su); !out.status.ok()) return out;
  const Kinematics& k = su.k;
  const Mechanism& m = k.mechanism();
  out.reaction = su.reaction;
  out.force = out.reaction.force;
  Sensitivity s;
  const Sensitivity::Space world =
      isSpatial(m) ? Sensitivity::Space::World : Sensitivity::Space::Refuse;
  if (out.status = s.prepare(k, std::move(dims), world); !out.status.ok()) return out;
  if (out.status = s.at(k); !out.status.ok()) return out;
  out.dims = s.dims();
  const Context c = factored(k, s);
  SensitivityPose pose(k, s);
  const PointChange dpose(pose);
  // On a machine in space a body's bearing takes its load out of the plane as well.
  const internal::BearingChange bearing(k, su.ji);
  for (size_t d = 0; d < out.dims.size(); ++d) {
    pose.dim = static_cast<int>(d);
    const Eigen::VectorXd dQ = forcesChangeOf(k, s, pose.dim);
    out.change.push_back(su.restated(
        c, pose, dpose, [&](const RowsReaction& r) { return change(c, r, pose.dim, dQ); }));
    if (bearing.bears())
      bearing.change(k, s, c.balance(), internal::balanceChange(k, s, c.balance(), pose.dim, dQ),
                     out.change.back());
    out.derivative.push_back(out.change.back().force);
  }
  if (!std::all_of(out.change.begin(), out.change.end(), [](const JointReaction& r) {
        return r.force.allFinite() && std::isfinite(r.coupleNm) && std::isfinite(r.contactN) &&
               std::isfinite(r.normalN) && r.tiltNm.allFinite();
      }))
    out.status = Status::failure(StatusCode::Singular, "the reaction's derivatives are unbounded");
  return out;
}

struct CounterweightShares::Impl {
  std::uint64_t revision = 0;  // of the design prepared for
  Setup su;
  std::optional<internal::BearingChange> bearing;  // its load out of the plane, in space
  // The forces' Jacobian, its factors and the design's multipliers at the last pose asked for
  // (a search asks for each counterweight and each of its variables at one pose).
  struct Factored {
    Eigen::VectorXd q;
    double omega = NAN;
    Eigen::MatrixXd J;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    Eigen::VectorXd lambda, Q;
  };
  mutable Factored last;
  Context factoredAt(const Kinematics& k, const Sensitivity& none) const {
    if (last.omega != k.omega() || last.q.size() != k.q().size() || last.q != k.q()) {
      const Context c = factored(k, none);
      last = {k.q(), k.omega(), c.J, c.lu, c.lambda, c.Q};
    }
    return Context{k, none, last.J, last.lu, last.lambda, last.Q};
  }
};

CounterweightShares::CounterweightShares() = default;
CounterweightShares::~CounterweightShares() = default;

Status CounterweightShares::prepare(const Kinematics& k, JointId joint) {
  d_ = std::make_unique<Impl>();
  if (Status s = setUp(k, joint, d_->su); !s.ok()) {
    d_.reset();
    return s;
  }
  d_->bearing.emplace(d_->su.k, d_->su.ji);
  d_->revision = k.revision();
  return Status::success();
}

CounterweightShare CounterweightShares::at(const Kinematics& k0, const Counterweight& cw) const {
  CounterweightShare out;
  if (!d_) return out.status = Status::badModel("the shares are not prepared"), out;
  if (k0.revision() != d_->revision)
    return out.status = Status::badModel("the shares were prepared for another design"), out;
  std::optional<Kinematics> copy;  // the inertia forces need the accelerations
  if (!k0.accelerations()) copy.emplace(k0).setAccelerations(true);
  const Kinematics& k = copy ? *copy : k0;
  const KinematicsState& st = internal::state(k);
  const int i = st.sys.bodyIndex(cw.body);
  if (i < 0) return out.status = Status::badModel("a counterweight on no moving body"), out;
  Eigen::MatrixXd dQ = Eigen::MatrixXd::Zero(st.sys.nCoords(), 3);
  const CounterweightForces put(k, cw, i, dQ);
  const Vec2 s = cw.staticMoment;
  const double norm = s.norm(), R = cw.maxRadiusMm;
  // Each column's mass and static moment: the counterweight's, then per kg mm of s's x and y.
  double kg[3] = {cw.kg, 0, 0};
  Vec2 moment[3] = {s, Vec2::UnitX(), Vec2::UnitY()};
  put.put(0, cw.kg, s, cw.kg > 0 ? s.squaredNorm() / cw.kg : 0.0);
  for (int e = 0; e < 2; ++e) {  // the mass |s| / R, so the spin |s| R
    kg[1 + e] = norm > 0 ? s[e] / (norm * R) : 0.0;
    put.put(1 + e, kg[1 + e], moment[1 + e], norm > 0 ? R * s[e] / norm : 0.0);
  }
  const Sensitivity none;
  const Context c = d_->factoredAt(k, none);
  const Eigen::MatrixXd dl = c.lu.transpose().solve(dQ);
  if (!dl.allFinite())
    return out.status = Status::failure(StatusCode::Singular,
                                        "a singular position: the shares are unbounded"),
           out;
  const HeldPose pose(k);
  JointReaction* parts[3] = {&out.share, &out.perX, &out.perY};
  for (int col = 0; col < 3; ++col) {
    Context share{k, none, c.J, {}, dl.col(col), dQ.col(col)};
    *parts[col] = d_->su.restated(c, pose, pose, [&](const RowsReaction& r) {
      JointReaction v = value(share, r);
      v.at = Vec2::Zero();  // a share at a held pose: no point moves
      return v;
    });
    d_->bearing->share(k, share.balance(), i, put.weight(kg[col], moment[col]), *parts[col]);
  }
  return out;
}

CounterweightShare counterweightShare(const Kinematics& k, JointId joint, const Counterweight& cw) {
  CounterweightShares shares;
  if (Status s = shares.prepare(k, joint); !s.ok()) {
    CounterweightShare out;
    out.status = s;
    return out;
  }
  return shares.at(k, cw);
}

Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Sensitivity& s, int dim) {
  return forcesChangeOf(k, s, dim);
}

CounterweightShareChange counterweightShareChange(const Kinematics& k0, JointId joint,
                                                  const Counterweight& cw,
                                                  std::vector<Dimension> dims,
                                                  const std::vector<double>& turn0) {
  CounterweightShareChange out;
  Setup su;
  int i = -1;
  if (out.status = shareSetUp(k0, joint, cw, su, i); !out.status.ok()) return out;
  const Kinematics& k = su.k;
  const KinematicsState& st = internal::state(k);
  Sensitivity s;
  const Sensitivity::Space world =
      isSpatial(k.mechanism()) ? Sensitivity::Space::World : Sensitivity::Space::Refuse;
  if (out.status = s.prepare(k, std::move(dims), world); !out.status.ok()) return out;
  if (out.status = s.at(k); !out.status.ok()) return out;
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(st.sys.nCoords(), 1);
  const CounterweightForces put(k, cw, i, Q);
  const double spin = cw.kg > 0 ? cw.staticMoment.squaredNorm() / cw.kg : 0.0;
  put.put(0, cw.kg, cw.staticMoment, spin);
  // The share's multipliers in the Context's place of the design's: change() then gives the
  // share's change, its rows' turn and its forces' change together.
  Context c{k, s, forcesJacobian(k), {}, {}, Q.col(0)};
  c.lu.compute(c.J);
  c.lambda = c.lu.transpose().solve(Q.col(0));
  SensitivityPose pose(k, s);
  const PointChange dpose(pose);
  const internal::BearingChange bearing(k, su.ji);  // its load out of the plane, in space
  for (size_t d = 0; d < s.dims().size(); ++d) {
    pose.dim = static_cast<int>(d);
    const double dTheta = s.angle(k, cw.body, pose.dim) - (d < turn0.size() ? turn0[d] : 0.0);
    const Eigen::VectorXd dQ = put.change(s, pose.dim, dTheta, cw.kg, cw.staticMoment, spin);
    out.change.push_back(su.restated(
        c, pose, dpose, [&](const RowsReaction& r) { return change(c, r, pose.dim, dQ); }));
    if (bearing.bears())
      bearing.shareChange(
          k, s, c.balance(), internal::balanceChange(k, s, c.balance(), pose.dim, dQ), i,
          put.weightChange(s, pose.dim, dTheta, cw.kg, cw.staticMoment), out.change.back());
  }
  return out;
}

}  // namespace linkage
