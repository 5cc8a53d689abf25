// A bearing's out-of-plane reaction and its derivative: see analysis/bearing_change.h.
#include "analysis/bearing_change.h"

#include "analysis/forces_jacobian.h"
#include "elements/distance3.h"
#include "kinematics/kinematics_state.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage::internal {

namespace {

// Joint j's point on body k, as SpaceForces::depthOn reads it (none: a null id); its point on
// the ground.
PointId pointOn(const Mechanism& m, const System& sys, const Joint& j, int k) {
  for (PointId p : {j.a, j.b})
    if (const Point* pt = p ? m.point(p) : nullptr; pt && sys.bodyIndex(pt->body) == k) return p;
  return PointId{};
}

PointId groundPoint(const Mechanism& m, const System& sys, const Joint& j) {
  for (PointId p : {j.a, j.b})
    if (const Point* pt = p ? m.point(p) : nullptr; pt && sys.bodyIndex(pt->body) < 0) return p;
  return PointId{};
}

Vec3 inFrame(const Plane& f, const Vec3& w) {
  return Vec3(w.dot(f.xAxis), w.dot(f.yAxis), w.dot(f.normal()));
}

Vec3 flat(const Vec2& v, double z = 0) {
  return Vec3(v.x(), v.y(), z);
}

}  // namespace

// The load W and its change dW (header).
struct BearingChange::Load {
  Vec3 W = Vec3::Zero(), dW = Vec3::Zero();
  void add(const Vec3& F, const Vec3& dF, const Vec3& rel, const Vec3& drel) {
    const Vec3 M = rel.cross(F), dM = drel.cross(F) + rel.cross(dF);
    W += Vec3(F.z(), M.x(), M.y());
    dW += Vec3(dF.z(), dM.x(), dM.y());
  }
  // A weight's part g along the normal, kg g, whose first moment about the bearing in the plane
  // is `arm` (kg mm; it acts at kg^-1 arm from there): rel x (0, 0, kg g) = g (arm_y, -arm_x).
  void addWeight(double kg, double g, const Vec2& arm, const Vec2& dArm) {
    W += Vec3(kg * g, g * arm.y(), -g * arm.x());
    dW += Vec3(0, g * dArm.y(), -g * dArm.x());
  }
};

// One dimension's moves, seen in the body's class frame (x, y, along the normal).
struct BearingChange::Moves {
  const Kinematics& k;
  const Sensitivity& s;
  int dim;
  Plane f;
  double plane = 0;         // the body's plane along the normal (a plane's origin moved)
  double depth = 0;         // the mean of its points' depths (where its mass and loads act)
  Vec2 com = Vec2::Zero();  // its centre of mass in it, turned into the frame's axes
  Vec3 point(PointId p) const { return inFrame(f, s.point3(k, p, dim)); }

  Moves(const Kinematics& kin, const Sensitivity& sens, int d, int body)
      : k(kin), s(sens), dim(d), f(state(kin).sys.frames[state(kin).sys.classOf[body]]) {
    const KinematicsState& st = state(k);
    int count = 0;
    for (const Point& p : st.mech.points)
      if (st.sys.bodyIndex(p.body) == body) {
        depth += point(p.id).z();
        if (count++ || !s.dims()[dim].carriesMasses) continue;
        // Every point of the body moves alike, along the normal and in the plane.
        plane = point(p.id).z();
        const Vec2 arm = Rot::of(k.q()[3 * body + 2]) * st.sys.point(p.id)->s;
        com = s.point(k, p.id, dim) - Vec2(s.dq().block<2, 1>(3 * body, dim)) -
              s.dq()(3 * body + 2, dim) * perp(arm);
      }
    if (count) depth /= count;
  }
};

BalanceChange balanceChange(const Kinematics& k, const Sensitivity& s, const Balance& b, int dim,
                            const Eigen::VectorXd& dQ) {
  const int n = static_cast<int>(b.lambda.size());
  BalanceChange c;
  c.dim = dim;
  c.dQ = dQ;
  c.dJ.resize(n, n);
  for (int col = 0; col < n; ++col)
    c.dJ.col(col) = forcesJacobianChange(k, s, Eigen::VectorXd::Unit(n, col), dim);
  c.dlambda = b.lu.transpose().solve(dQ - c.dJ.transpose() * b.lambda);
  return c;
}

BearingChange::BearingChange(const Kinematics& k, int ji) : joint_(ji) {
  const KinematicsState& st = state(k);
  if (!isSpatial(st.mech)) return;
  mass_ = SpaceForces::masses(st.mech, st.sys);
  space_.prepare(st.mech, st.sys, mass_, st.mech.gravityWorld());
  for (int i = 0; i < st.sys.nBodies; ++i)
    if (space_.bearing(i) == ji) body_ = i;
  if (body_ < 0) return;
  const Joint& j = st.mech.joints[ji];
  sign_ = st.sys.bodyIndex(st.mech.point(j.a)->body) == body_ ? -1.0 : 1.0;
}

void BearingChange::change(const Kinematics& k, const Sensitivity& s, const Balance& b,
                           const BalanceChange& c, JointReaction& out) const {
  if (!bears()) return;
  const Moves mv(k, s, c.dim, body_);
  // The body's mass, fixed in its frame (a plane's origin carrying it: mv.com).
  BodyWeight w;
  if (const std::optional<SpaceForces::BodyMass>& mass = mass_[body_]) {
    const Vec2 g = Rot::of(k.q()[3 * body_ + 2]) * mass->c;
    w = {mass->kg, mass->kg * g, mass->kg * (s.dq()(3 * body_ + 2, c.dim) * perp(g) + mv.com)};
  }
  Load load;
  this->load(k, b, &c, &mv, w, load);
  put(load.dW, out);
}

void BearingChange::share(const Kinematics& k, const Balance& b, int body, const BodyWeight& w,
                          JointReaction& out) const {
  if (!bears()) return;
  Load load;
  this->load(k, b, nullptr, nullptr, body == body_ ? w : BodyWeight{}, load);
  put(load.W, out);
}

void BearingChange::shareChange(const Kinematics& k, const Sensitivity& s, const Balance& b,
                                const BalanceChange& c, int body, const BodyWeight& w,
                                JointReaction& out) const {
  if (!bears()) return;
  const Moves mv(k, s, c.dim, body_);
  Load load;
  this->load(k, b, &c, &mv, body == body_ ? w : BodyWeight{}, load);
  put(load.dW, out);
}

void BearingChange::put(const Vec3& W, JointReaction& out) const {
  out.normalN = sign_ * W.x();
  out.tiltNm = sign_ * Vec2(W.y(), W.z()) / 1000;
}

// The body's own forces (Q at its depth, a weight's normal part: w, the body's or a share's),
// then the rows'.
void BearingChange::load(const Kinematics& k, const Balance& b, const BalanceChange* c,
                         const Moves* mv, const BodyWeight& w, Load& out) const {
  const KinematicsState& st = state(k);
  const Mechanism& m = st.mech;
  const int i = body_;
  std::vector<BodyView> views;
  makeViews(st.sys, k.q(), nullptr, views);
  Vec2 B;
  double dB;
  space_.bearingPlace(m, st.sys, views, i, B, dB);
  Vec3 dAt = Vec3::Zero();
  if (mv) {  // the bearing's move: its point on the body's, else the ground's in the body's slot
    const Joint& j = m.joints[joint_];
    const PointId on = pointOn(m, st.sys, j, i);
    dAt = flat(mv->point(on ? on : groundPoint(m, st.sys, j)).head<2>(),
               on ? mv->point(on).z() : mv->plane);
  }
  const double dDepth = mv ? mv->depth - dAt.z() : 0;
  const Vec3 rel(0, 0, space_.depth(i) - dB), drel(0, 0, dDepth);
  out.add(flat(b.Q.segment<2>(3 * i)), c ? flat(c->dQ.segment<2>(3 * i)) : Vec3::Zero(), rel, drel);
  if (w.kg != 0 || w.moment != Vec2::Zero()) {
    const Vec2 dr = mv ? Vec2(mv->s.dq().block<2, 1>(3 * i, c->dim)) : Vec2::Zero();
    out.addWeight(w.kg, space_.gravityOut(i), w.kg * (views[i + 1].r - B) + w.moment,
                  w.kg * (dr - dAt.head<2>()) + w.dMoment);
  }
  rowLoads(k, views, b, c, mv, Vec3(B.x(), B.y(), dB), dAt, out);
}

// Every other joint's rows on the body: an in-plane row's force -lambda J_r at the depth of its
// joint's point on the body, a ball rod's pull at its end.
void BearingChange::rowLoads(const Kinematics& k, const std::vector<BodyView>& views,
                             const Balance& b, const BalanceChange* c, const Moves* mv,
                             const Vec3& at, const Vec3& dAt, Load& out) const {
  const KinematicsState& st = state(k);
  const Mechanism& m = st.mech;
  const std::vector<int>& map = st.newton.rowMap();
  const int i = body_;
  for (const Row& r : st.sys.cons) {
    if (r.joint < 0 || r.joint == joint_ || r.isDriver() || r.kind == Primitive::Angles ||
        r.kind == Primitive::Hold)
      continue;
    for (int e = 0; e < 2; ++e) {
      if (r.body[e] != i) continue;
      if (r.kind == Primitive::Distance3) {
        rodLoad(k, views, b, c, mv, r, e, at, dAt, out);
        continue;
      }
      const Joint& j = m.joints[r.joint];
      const PointId p = pointOn(m, st.sys, j, i);
      const Vec3 rel(0, 0, space_.depthOn(m, st.sys, j, i) - at.z());
      const Vec3 drel(0, 0, mv ? (p ? mv->point(p).z() : mv->plane) - dAt.z() : 0);
      for (int row = 0; row < r.rows(); ++row) {
        const int x = map[r.row + row];
        if (x < 0) continue;
        const Vec2 Jr = b.J.block<1, 2>(x, 3 * i).transpose();
        const Vec2 F = -b.lambda[x] * Jr;
        const Vec2 dF =
            c ? Vec2(-c->dlambda[x] * Jr - b.lambda[x] * c->dJ.block<1, 2>(x, 3 * i).transpose())
              : Vec2::Zero();
        out.add(flat(F), flat(dF), rel, drel);
      }
    }
  }
}

// A ball rod's pull on end e (on the body): -+lambda D / l, D from end 0 to end 1 reversed
// (analysis/space_forces.h), in the world, seen in the body's class frame.
void BearingChange::rodLoad(const Kinematics& k, const std::vector<BodyView>& views,
                            const Balance& b, const BalanceChange* c, const Moves* mv, const Row& r,
                            int e, const Vec3& at, const Vec3& dAt, Load& out) const {
  const KinematicsState& st = state(k);
  const int x = st.newton.rowMap()[r.row];
  if (x < 0) return;
  const distance3::End ends[2] = {
      {views[r.body[0] + 1], r.s[0], st.sys.frames[r.frame[0]], r.depth[0]},
      {views[r.body[1] + 1], r.s[1], st.sys.frames[r.frame[1]], r.depth[1]}};
  const Vec3 D = distance3::world(ends[0]) - distance3::world(ends[1]);
  const double l = r.c[0], lam = b.lambda[x], sign = e == 0 ? -1.0 : 1.0;
  const Plane& f = st.sys.frames[st.sys.classOf[body_]];
  const Vec2 P = ends[e].b.r + ends[e].b.R * ends[e].s;
  Vec3 dF = Vec3::Zero(), drel = Vec3::Zero();
  if (mv) {
    const Joint& j = st.mech.joints[r.joint];
    const Vec3 dD = mv->s.point3(k, j.a, c->dim) - mv->s.point3(k, j.b, c->dim);
    const double dl = mv->s.dims()[c->dim].lengthOf == j.id ? 1.0 : 0.0;
    dF = inFrame(f, sign * (c->dlambda[x] * D / l + lam * (dD / l - D * dl / (l * l))));
    drel = mv->point(e == 0 ? j.a : j.b) - dAt;
  }
  out.add(inFrame(f, sign * lam / l * D), dF, flat(P, ends[e].depth) - at, drel);
}

}  // namespace linkage::internal
