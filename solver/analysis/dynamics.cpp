// Forces at the driver's constant speed: see linkage/dynamics.h.
#include "linkage/dynamics.h"
#include "linkage/space.h"

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <charconv>
#include <cmath>

#include "analysis/group_forces.h"
#include "analysis/space_forces.h"
#include "kinematics/kinematics_state.h"

namespace linkage {

namespace {

constexpr double kNaN = NAN;

// A reaction that is not known: every part NaN but where it acts.
void unknown(JointReaction& r) {
  const Vec2 at = r.at;
  r = {Vec2::Constant(kNaN), at, kNaN, kNaN, Vec2::Constant(kNaN), kNaN, kNaN, kNaN};
}

// Positions at k's pose, for the kinds' react().
struct KinematicsPose : Pose {
  const Kinematics& k;
  explicit KinematicsPose(const Kinematics& kin) : k(kin) {}
  Vec2 point(PointId p) const override { return k.position(p); }
  Transform body(BodyId b) const override { return k.bodyTransform(b); }
};

}  // namespace

struct ForceSolver::Impl {
  using BodyMass = SpaceForces::BodyMass;
  struct LoadAt {
    Load load;  // a copy: the solver may outlive the kinematics it was prepared on (a copy of
                // them of the same revision is computed with)
    int body = -1;
    Vec2 s = Vec2::Zero();      // the point in the body's frame (a force)
    Vec2 force = Vec2::Zero();  // in the body's class frame (in space; else the load's)
  };
  std::uint64_t revision = 0;
  std::vector<std::optional<BodyMass>> mass;  // by system body index
  std::vector<LoadAt> loads;                  // on moving bodies
  std::vector<PointLocation> jointA;          // by joint: where its point a is
  struct Reacting {
    int row;      // in System::cons
    double sign;  // +1 where the joint's point a is on body[0], -1 where on body[1]
  };
  std::vector<Reacting> reacting;  // the joints' rows that are forces at a point
  struct Coupling {
    int row, joint;
    double perUnit;  // the couple on the body of the joint's point a per unit multiplier, N mm
  };
  std::vector<Coupling> coupling;  // the joints' Angles rows on the body of their point a
  std::vector<int> restated;       // the joints whose kinds restate their reactions
  Vec2 gravity = Vec2::Zero();     // m/s^2, in the plane (a planar machine)
  double gravityZ = 0;             // m/s^2, along the drawing's normal (a planar machine)
  bool grouped = false;
  std::vector<char> rowDetermined;  // by scalar row
  std::vector<BodyView> views;
  GroupForces groups;  // on the closed-form path
  SpaceForces space;   // a machine in space's planes, bearings and rods
  Eigen::VectorXd Q, lambda, x;

  void bodies(const KinematicsState& s);
  void joints(const KinematicsState& s);
  void undetermined(const KinematicsState& s, Forces& out);
  void appliedAndInertia(const KinematicsState& s, double omega, double crankDeg);
  bool solveWithKinematics(const KinematicsState& s);
  bool solveWhole(const KinematicsState& s);
  void reactions(const KinematicsState& s, const Kinematics& k, Forces& out);
  void shakingOf(const System& sys, Forces& out) const;
};

void ForceSolver::ImplDeleter::operator()(Impl* p) const {
  delete p;
}

void ForceSolver::Impl::bodies(const KinematicsState& s) {
  const System& sys = s.sys;
  // In space a body's loads are in its plane: into its class's frame.
  const bool spatial = isSpatial(s.mech);
  const PlaneClasses pc = spatial ? planeClasses(s.mech) : PlaneClasses{};
  auto placing = [&](BodyId b) { return pc.of(s.mech.body(b)->plane); };
  mass = SpaceForces::masses(s.mech, sys);
  loads.clear();
  for (const Load& l : s.mech.loads) {
    if (l.point) {
      const PointLocation* p = sys.point(l.point);
      if (!p || p->body < 0) continue;
      const PlaneInClass in = spatial ? placing(s.mech.point(l.point)->body) : PlaneInClass{};
      loads.push_back({l, p->body, p->s, in.identity ? l.forceN : Vec2(in.rot * l.forceN)});
    } else if (const int k = sys.bodyIndex(l.body); k >= 0) {
      loads.push_back({l, k, Vec2::Zero(), Vec2::Zero()});
    }
  }
  gravity = s.mech.gravity.value_or(Vec2::Zero());
  gravityZ = s.mech.gravityZ.value_or(0);
  space.prepare(s.mech, sys, mass, s.mech.gravityWorld());
}

// What the reactions read, listed once (shaking() needs none of it).
void ForceSolver::Impl::joints(const KinematicsState& s) {
  const System& sys = s.sys;
  jointA.clear();
  restated.clear();
  for (const Joint& j : s.mech.joints) {
    jointA.push_back(*sys.point(j.a));
    if (kindOf(j).react) restated.push_back(static_cast<int>(jointA.size()) - 1);
  }
  // On a machine in space a ground point a is read where the joint's rows hold it: in the class
  // frame of the body it holds, not at its drawing's x, y (a pin's couple about it is then 0).
  // A ball rod's ground end is in no plane: its drawing's x, y.
  if (isSpatial(s.mech)) {
    const PlaneClasses pc = planeClasses(s.mech);
    std::vector<char> placed(jointA.size(), 0);
    for (const Row& row : sys.cons) {
      if (row.joint < 0 || placed[row.joint] || jointA[row.joint].body >= 0 ||
          row.kind == Primitive::Distance3)
        continue;
      const int other = row.body[0] >= 0 ? row.body[0] : row.body[1];
      if (other < 0) continue;
      placed[row.joint] = 1;
      jointA[row.joint].s =
          inClassFrame(s.mech, pc, *s.mech.point(s.mech.joints[row.joint].a), sys.classOf[other]);
    }
  }
  reacting.clear();
  coupling.clear();
  for (size_t i = 0; i < sys.cons.size(); ++i) {
    const Row& row = sys.cons[i];
    if (row.joint < 0 || row.isDriver() || row.kind == Primitive::Hold) continue;
    const int a = jointA[row.joint].body;
    if (row.kind != Primitive::Angles) {
      reacting.push_back({static_cast<int>(i), row.body[0] == a ? 1.0 : -1.0});
      continue;
    }
    for (int c = 0; c < 3; ++c)
      if (row.body[c] == a && row.c[c] != 0)
        coupling.push_back({row.row, row.joint, -row.c[c] * sys.size});
  }
}

// Q: per body, at its frame origin, the force (N) and the moment (N mm) of its weight, its
// inertia (-m a_com, -J alpha) and its loads. Lengths in mm, accelerations per second squared.
void ForceSolver::Impl::appliedAndInertia(const KinematicsState& s, double omega, double crankDeg) {
  const Motion& m = s.cur();
  const int n = s.sys.nBodies;
  Q.setZero(3 * n);
  const double w2 = omega * omega;
  for (int k = 0; k < n; ++k) {
    if (!mass[k]) continue;
    const BodyMass& bm = *mass[k];
    const BodyState& b = m.body[k];
    const Vec2 g = b.R * bm.c;
    const Vec2 acc = w2 * (b.a + b.al * perp(g) - b.w * b.w * g);                       // mm/s^2
    const Vec2 F = bm.kg * ((space.on() ? space.gravityIn(k) : gravity) - acc / 1000);  // N
    Q.segment<2>(3 * k) += F;
    Q[3 * k + 2] += cross(g, F) - bm.j * w2 * b.al / 1000;  // N mm (kg mm^2/s^2 = 1e-3 N mm)
  }
  for (const LoadAt& l : loads) {
    if (!l.load.activeAt(crankDeg)) continue;
    if (l.load.point) {
      const Vec2 g = m.body[l.body].R * l.s;
      Q.segment<2>(3 * l.body) += l.force;
      Q[3 * l.body + 2] += cross(g, l.force);
    } else {
      Q[3 * l.body + 2] += 1000 * l.load.torqueNm;
    }
  }
}

void ForceSolver::Impl::shakingOf(const System& sys, Forces& out) const {
  if (space.on()) {
    space.shaking(sys, views, Q, mass, out.shakingForce3N, out.shakingMoment3Nm);
    out.shakingForceN = out.shakingForce3N.head<2>();
    out.shakingMomentNm = out.shakingMoment3Nm.z();
    return;
  }
  Vec2 force = Vec2::Zero();
  double moment = 0;
  for (int k = 0; k < sys.nBodies; ++k) {
    const Vec2 F = Q.segment<2>(3 * k);
    force += F;
    moment += Q[3 * k + 2] + cross(views[k + 1].r, F);  // about the sketch origin, N mm
  }
  out.shakingForceN = force;
  out.shakingMomentNm = moment / 1000;
  // Gravity's z is along the drawing's normal: the weights along it change no force in the
  // plane, and the frame bears them (at the centres of mass, z 0) out of it.
  Vec3 tilt = Vec3::Zero();
  double fz = 0;
  for (int k = 0; k < sys.nBodies && gravityZ != 0; ++k) {
    if (!mass[k]) continue;
    const Vec2 c = views[k + 1].r + views[k + 1].R * mass[k]->c;
    const double w = mass[k]->kg * gravityZ;
    fz += w;
    tilt += Vec3(c.x(), c.y(), 0).cross(Vec3(0, 0, w));
  }
  out.shakingForce3N = Vec3(force.x(), force.y(), fz);
  out.shakingMoment3Nm = tilt / 1000 + Vec3(0, 0, out.shakingMomentNm);
}

// On the general path the kinematics factored J at this very pose for its velocities: J^T lambda
// = Q is then two triangular solves with the same factors.
bool ForceSolver::Impl::solveWithKinematics(const KinematicsState& s) {
  const Eigen::VectorXd& q = s.coordinates(s.cur()).q;
  if (!s.newton.factoredAt(q)) return false;
  x = Q;
  s.newton.solveTransposedInPlace(s.sys, x);
  if (!x.allFinite()) return false;
  const std::vector<int>& map = s.newton.rowMap();
  lambda.resize(s.sys.nRows);
  for (int r = 0; r < s.sys.nRows; ++r) lambda[r] = map[r] >= 0 ? x[map[r]] : kNaN;
  return true;
}

// J^T lambda = Q with the independent rows, factored here (the kinematics' factors are of
// another pose); a sparse LU from the sizes the Newton goes sparse.
bool ForceSolver::Impl::solveWhole(const KinematicsState& s) {
  const System& sys = s.sys;
  const std::vector<int>& active = s.structure.activeRows;
  const int n = sys.nCoords();
  std::vector<int> index(sys.nRows, -1);
  for (size_t i = 0; i < active.size(); ++i) index[active[i]] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double>> entries;
  for (const Row& row : sys.cons) {
    if (row.kind == Primitive::Hold) continue;
    const Eigen::Matrix<double, 2, 9> B = rowJacobian(sys, views, row);
    for (int i = 0; i < row.rows(); ++i) {
      const int r = index[row.row + i];
      if (r < 0) continue;
      for (int k = 0; k < 3; ++k)
        if (row.body[k] >= 0)
          for (int c = 0; c < 3; ++c)
            if (B(i, 3 * k + c) != 0) entries.emplace_back(3 * row.body[k] + c, r, B(i, 3 * k + c));
    }
  }
  Eigen::SparseMatrix<double> JT(n, static_cast<int>(active.size()));
  JT.setFromTriplets(entries.begin(), entries.end());
  if (n < s.opt.sparseFrom) {
    x = Eigen::MatrixXd(JT).partialPivLu().solve(Q);
  } else {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(JT);
    if (lu.info() != Eigen::Success) return false;
    x = lu.solve(Q);
  }
  if (!x.allFinite()) return false;
  lambda.setConstant(sys.nRows, kNaN);
  for (size_t i = 0; i < active.size(); ++i) lambda[active[i]] = x[i];
  return true;
}

namespace {

void viewsOf(const KinematicsState& s, std::vector<BodyView>& views) {
  const Motion& m = s.cur();
  views.resize(s.sys.nBodies + 1);
  views[0] = BodyView{};
  for (int k = 0; k < s.sys.nBodies; ++k) {
    const BodyState& b = m.body[k];
    BodyView& v = views[k + 1];
    v.col = 3 * k;
    v.r = b.r;
    v.R = b.R;  // (theta is for residuals: not needed here)
  }
}

}  // namespace

// With redundant joints J^T lambda = Q has more unknowns than equations: the rows whose
// multiplier varies along the null space of J^T (all rows, the driver's included) are those whose
// share is not fixed. Their joints are named; the others' reactions are determined.
void ForceSolver::Impl::undetermined(const KinematicsState& s, Forces& out) {
  const System& sys = s.sys;
  rowDetermined.assign(sys.nRows, 1);
  if (s.structure.dependentRows.empty()) return;
  viewsOf(s, views);
  const int m = sys.nJointRows + (sys.driverRow >= 0 ? 1 : 0);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, sys.nCoords());
  for (const Row& row : sys.cons) {
    if (row.kind == Primitive::Hold) continue;
    const Eigen::Matrix<double, 2, 9> B = rowJacobian(sys, views, row);
    for (int k = 0; k < 3; ++k)
      if (row.body[k] >= 0)
        J.block(row.row, 3 * row.body[k], row.rows(), 3) = B.block(0, 3 * k, row.rows(), 3);
  }
  for (int k = 0; k < sys.nBodies; ++k) J.col(3 * k + 2) /= sys.size;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(J.transpose());
  lu.setThreshold(1e-9);
  const Eigen::MatrixXd N = lu.kernel();
  if (N.cols() == 0 || (N.cols() == 1 && N.isZero())) return;
  for (int r = 0; r < m; ++r)
    if (N.row(r).cwiseAbs().maxCoeff() > 1e-9 * N.cwiseAbs().maxCoeff()) rowDetermined[r] = 0;
  for (const Row& row : sys.cons) {
    if (row.joint < 0 || row.isDriver() || row.kind == Primitive::Hold) continue;
    bool known = true;
    for (int i = 0; i < row.rows(); ++i) known = known && rowDetermined[row.row + i];
    const JointId id = s.mech.joints[row.joint].id;
    if (!known && (out.undetermined.empty() || out.undetermined.back() != id))
      out.undetermined.push_back(id);
  }
}

Status ForceSolver::prepare(const Kinematics& k) {
  out_ = Forces{};
  d_.reset();
  if (!k.valid()) return out_.status = Status::badModel("no mechanism is loaded");
  const KinematicsState& s = internal::state(k);
  if (!s.sys.hasDriver)
    return out_.status = Status::badModel(
               "the mechanism has no driver: forces are those at the driver's constant speed");
  if (s.structure.freeAfterDriver > 0)
    return out_.status = Status::failure(
               StatusCode::Underconstrained,
               "the motion is not determined (" + std::to_string(s.structure.freeAfterDriver) +
                   " freedom(s) the driver leaves), so neither are its forces");
  d_.reset(new Impl);
  d_->revision = k.revision();
  d_->bodies(s);
  d_->joints(s);
  d_->grouped = s.plan.has_value() && s.decomposition.closedForm();
  if (d_->grouped) d_->groups.prepare(s.sys, s.decomposition);
  out_.outOfPlaneUnsupported = d_->space.unsupported();
  d_->undetermined(s, out_);
  return out_.status;
}

// Each joint's reaction on the body of its point a, from its rows' multipliers: a force at each
// row's point (Coincident, OnLine, OnCircle: on body[0], its opposite on body[1]) and couples
// (Angles: -c_k L lambda on body k); then as its kind states it.
void ForceSolver::Impl::reactions(const KinematicsState& s, const Kinematics& k, Forces& out) {
  const Mechanism& m = s.mech;
  const size_t n = m.joints.size();
  if (out.joints.size() != n) out.joints.resize(n);
  JointReaction* joints = out.joints.data();
  for (size_t j = 0; j < n; ++j) {  // the couples in N mm until the end
    const BodyView& v = views[jointA[j].body + 1];
    joints[j] = {Vec2::Zero(), v.r + v.R * jointA[j].s, 0};
  }
  RowForce here;
  for (const Reacting& x : reacting) {
    const Row& row = s.sys.cons[x.row];
    JointReaction& r = joints[row.joint];
    const double* lam = lambda.data() + row.row;
    const RowForce* f = grouped ? groups.force(x.row) : nullptr;
    if (!f) {
      rowForce(s.sys, views, row, here);
      f = &here;
    }
    Vec2 F = lam[0] * f->u[0];
    if (row.rows() == 2) F += lam[1] * f->u[1];
    F *= -x.sign;  // the row's force is +u on body[0]; the joint's is on the body of a
    // A cam's row is its contact's, u[0] the normal from the cam to the follower: the force on
    // the follower is -lambda u[0], so the compression is -lambda.
    if (row.kind == Primitive::Cam) r.contactN = -lam[0];
    r.force += F;
    r.coupleNm += cross(f->P - r.at, F);
  }
  for (const Coupling& c : coupling) joints[c.joint].coupleNm += c.perUnit * lambda[c.row];
  for (size_t j = 0; j < n; ++j) joints[j].coupleNm /= 1000;
  for (size_t j = 0; j < n; ++j) joints[j].transmittedNm = joints[j].coupleNm;
  if (space.on()) space.reactions(m, s.sys, views, lambda, Q, mass, out);
  if (!restated.empty()) {
    const KinematicsPose pose(k);
    for (int j : restated) kindOf(m.joints[j]).react(m, j, pose, out.joints);
  }
  for (JointId id : out.undetermined) {
    unknown(out.joints[m.jointIndex(id)]);
  }
}

const Forces& ForceSolver::compute(const Kinematics& k) {
  if (!d_) return out_;
  Forces& out = out_;
  out.status = Status::success();
  if (!k.valid() || k.revision() != d_->revision) {
    out.status = Status::badModel(
        "the kinematics hold another mechanism (or another revision of it) than the one "
        "prepared: call prepare() again");
    return out;
  }
  const KinematicsState& s = internal::state(k);
  out.crankDeg = k.crankDeg();
  if (!k.derivativesValid() || !s.cur().accelerations) {
    out.status = Status::failure(StatusCode::Singular,
                                 "no accelerations at this pose (a singular position, or not "
                                 "computed): no forces");
    out.driverTorqueNm = kNaN;
    out.shakingForceN = Vec2::Constant(kNaN);
    out.shakingMomentNm = kNaN;
    out.shakingForce3N = out.shakingMoment3Nm = Vec3::Constant(kNaN);
    for (JointReaction& r : out.joints) unknown(r), r.at = Vec2::Constant(kNaN);
    return out;
  }
  viewsOf(s, d_->views);
  d_->appliedAndInertia(s, k.omega(), out.crankDeg);
  // Forces past double's range (a speed of 1e200 rpm, loads of 1e308 N) are no figures: said so,
  // not taken for a singular position, and never written as inf or NaN.
  if (!d_->Q.allFinite()) return overflowed(out);
  d_->shakingOf(s.sys, out);
  auto solve = [&] {
    return d_->grouped ? d_->groups.solve(s.sys, d_->views, d_->Q, d_->lambda) || d_->solveWhole(s)
                       : (!s.sys.contactRows && d_->solveWithKinematics(s)) || d_->solveWhole(s);
  };
  if (!solve()) {
    // The multipliers are linear in Q: where Q scaled down solves, the solve overflowed (a load
    // of 1e308 N), the pose is no singular one.
    if (const double most = d_->Q.cwiseAbs().maxCoeff(); most > 1) {
      d_->Q /= most;
      if (solve()) return overflowed(out);
    }
    out.status = Status::failure(StatusCode::Singular,
                                 "the constraint forces cannot be solved at "
                                 "this pose (a singular position)");
    return out;
  }
  // The driver's couple on the body of its b point: -c L lambda, c = 1 there.
  out.driverTorqueNm = -s.sys.size * d_->lambda[s.sys.driverRow] / 1000;
  d_->reactions(s, k, out);
  if (!finiteForces(out)) return overflowed(out);
  return out;
}

const Forces& ForceSolver::overflowed(Forces& out) {
  char deg[32];
  const auto end =
      std::to_chars(deg, deg + sizeof deg, out.crankDeg, std::chars_format::general, 6);
  out.status = Status::badModel(
      "the forces at crank angle " + std::string(deg, end.ptr) +
      " deg overflow (beyond 1e308 N or N m): a speed, a load or a mass too large to compute "
      "with");
  out.status.crankDeg = out.crankDeg;
  out.driverTorqueNm = kNaN;
  out.shakingForceN = Vec2::Constant(kNaN);
  out.shakingMomentNm = kNaN;
  out.shakingForce3N = out.shakingMoment3Nm = Vec3::Constant(kNaN);
  for (JointReaction& r : out.joints) unknown(r), r.at = Vec2::Constant(kNaN);
  return out;
}

bool finiteForces(const Forces& f) {
  // Each force with its magnitude: a force of (1e200, 1e200) N has none a double holds.
  auto finite = [](const Vec2& v) {
    return v.allFinite() && std::isfinite(std::hypot(v.x(), v.y()));
  };
  if (!std::isfinite(f.driverTorqueNm) || !finite(f.shakingForceN) ||
      !std::isfinite(f.shakingMomentNm))
    return false;
  for (const JointReaction& r : f.joints)
    if (!std::isnan(r.force.x()) && (!finite(r.force) || !std::isfinite(r.coupleNm))) return false;
  return true;
}

Forces computeForces(const Kinematics& k) {
  ForceSolver f;
  if (!f.prepare(k).ok()) return f.result();
  return f.compute(k);
}

void shaking(const Kinematics& k, Vec2& forceN, double& momentNm) {
  Vec3 force, moment;
  shaking(k, force, moment);
  forceN = force.head<2>();
  momentNm = moment.z();
}

void shaking(const Kinematics& k, Vec3& forceN, Vec3& momentNm) {
  forceN = momentNm = Vec3::Constant(kNaN);
  if (!k.valid() || !k.derivativesValid()) return;
  const KinematicsState& s = internal::state(k);
  ForceSolver::Impl d;
  d.bodies(s);
  viewsOf(s, d.views);
  d.appliedAndInertia(s, k.omega(), k.crankDeg());
  Forces out;
  d.shakingOf(s.sys, out);
  forceN = out.shakingForce3N;
  momentNm = out.shakingMoment3Nm;
}

Eigen::VectorXd generalizedForces(const Kinematics& k) {
  if (!k.valid() || !k.derivativesValid()) return Eigen::VectorXd();
  const KinematicsState& s = internal::state(k);
  ForceSolver::Impl d;
  d.bodies(s);
  viewsOf(s, d.views);
  d.appliedAndInertia(s, k.omega(), k.crankDeg());
  return d.Q;
}

Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Eigen::VectorXd& dq,
                                        const Eigen::VectorXd& dqd, const Eigen::VectorXd& dqdd,
                                        const std::function<Vec2(PointId)>& armMove,
                                        const std::function<Vec2(int)>& comMove) {
  if (!k.valid() || !k.derivativesValid()) return Eigen::VectorXd();
  const KinematicsState& s = internal::state(k);
  ForceSolver::Impl d;
  d.bodies(s);
  const double w2 = k.omega() * k.omega();
  Eigen::VectorXd dQ = Eigen::VectorXd::Zero(3 * s.sys.nBodies);
  for (int i = 0; i < s.sys.nBodies; ++i) {
    if (!d.mass[i]) continue;
    const ForceSolver::Impl::BodyMass& bm = *d.mass[i];
    // The centre's arm g = R c turns by dtheta; its acceleration w^2 (a + alpha perp(g) -
    // omega^2 g), per radian rates, changes with every term.
    const Vec2 g = Rot::of(k.q()[3 * i + 2]) * bm.c;
    const Vec2 dg = dq[3 * i + 2] * perp(g) + (comMove ? comMove(i) : Vec2::Zero());
    const double w = k.dq()[3 * i + 2], alpha = k.ddq()[3 * i + 2];
    const double dw = dqd[3 * i + 2], dalpha = dqdd[3 * i + 2];
    const Vec2 acc = w2 * (Vec2(k.ddq().segment<2>(3 * i)) + alpha * perp(g) - w * w * g);
    const Vec2 dacc = w2 * (Vec2(dqdd.segment<2>(3 * i)) + dalpha * perp(g) + alpha * perp(dg) -
                            2 * w * dw * g - w * w * dg);
    const Vec2 F = bm.kg * ((d.space.on() ? d.space.gravityIn(i) : d.gravity) - acc / 1000);
    const Vec2 dF = -bm.kg * dacc / 1000;
    dQ.segment<2>(3 * i) += dF;
    dQ[3 * i + 2] += cross(dg, F) + cross(g, dF) - bm.j * w2 * dalpha / 1000;
  }
  for (const ForceSolver::Impl::LoadAt& l : d.loads)
    if (l.load.point && l.load.activeAt(k.crankDeg()))
      dQ[3 * l.body + 2] += cross(armMove(l.load.point), l.force);
  return dQ;
}

}  // namespace linkage
