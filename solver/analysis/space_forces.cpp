// Forces of a machine in space: see space_forces.h.
#include "analysis/space_forces.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "elements/distance3.h"

namespace linkage {

namespace {

Vec3 lift(const Plane& f, const Vec2& v) {
  return distance3::lift(f, v);
}

}  // namespace

std::vector<std::optional<SpaceForces::BodyMass>> SpaceForces::masses(const Mechanism& m,
                                                                      const System& sys) {
  const bool spatial = isSpatial(m);
  const PlaneClasses pc = spatial ? planeClasses(m) : PlaneClasses{};
  std::vector<std::optional<BodyMass>> out(sys.nBodies);
  for (const Body& b : m.bodies) {
    const int k = sys.bodyIndex(b.id);
    if (k < 0 || !b.mass) continue;
    const Vec2 com = spatial ? pc.of(b.plane).toClass(b.mass->com) : b.mass->com;
    out[k] = BodyMass{b.mass->kg, b.mass->jKgMm2, Vec2(com - sys.frameOrigin[k])};
  }
  return out;
}

double SpaceForces::depthOn(const Mechanism& m, const System& sys, const Joint& j, int k) const {
  for (PointId p : {j.a, j.b}) {
    const Point* pt = p ? m.point(p) : nullptr;
    if (pt && sys.bodyIndex(pt->body) == k && p.value < sys.pointDepth.size())
      return sys.pointDepth[p.value];
  }
  return placing_[k].depth;
}

void SpaceForces::bearingPlace(const Mechanism& m, const System& sys,
                               const std::vector<BodyView>& views, int k, Vec2& at,
                               double& depth) const {
  const Joint& j = m.joints[bearing_[k]];
  const Point* p = m.point(j.a);
  if (sys.bodyIndex(p->body) != k && j.b) p = m.point(j.b);
  const PointLocation* on = sys.point(p->id);
  at = on && on->body == k ? Vec2(views[k + 1].r + views[k + 1].R * on->s) : groundAt_[k];
  depth = depthOn(m, sys, j, k);
}

void SpaceForces::prepare(const Mechanism& m, const System& sys,
                          const std::vector<std::optional<BodyMass>>& mass, const Vec3& g) {
  on_ = isSpatial(m);
  unsupported_.clear();
  if (!on_) return;
  const int n = sys.nBodies;
  const PlaneClasses pc = planeClasses(m);
  placing_.assign(n, PlaneInClass{});
  gravityIn_.assign(n, Vec2::Zero());
  gravityOut_.assign(n, 0.0);
  for (int k = 0; k < n; ++k) {
    placing_[k] = pc.of(m.body(sys.bodyIds[k])->plane);
    const Plane& f = sys.frames[sys.classOf[k]];
    gravityIn_[k] = Vec2(g.dot(f.xAxis), g.dot(f.yAxis));
    gravityOut_[k] = g.dot(f.normal());
  }
  // Each body's joints with the ground that hold it in its plane; and whether anything acts on
  // it out of its plane (what no bearing may then take).
  std::vector<std::set<int>> grounded(n);
  std::vector<char> loaded(n, 0);
  for (const Row& r : sys.cons) {
    if (r.joint < 0 || r.kind == Primitive::Angles || r.kind == Primitive::Hold) continue;
    if (r.kind == Primitive::Distance3) {
      for (int b : r.body)
        if (b >= 0) loaded[b] = 1;
      continue;
    }
    if (r.body[0] < 0 && r.body[1] >= 0) grounded[r.body[1]].insert(r.joint);
    if (r.body[1] < 0 && r.body[0] >= 0) grounded[r.body[0]].insert(r.joint);
  }
  // A body's depth: the mean of its points' (where its mass is taken to be); its joints at
  // different depths put moments out of its plane on it.
  std::vector<double> sum(n, 0.0), lo(n, INFINITY), hi(n, -INFINITY);
  std::vector<int> count(n, 0);
  for (const Point& p : m.points)
    if (const int k = sys.bodyIndex(p.body); k >= 0) {
      sum[k] += sys.pointDepth[p.id.value];
      ++count[k];
    }
  for (const Joint& j : m.joints)
    for (PointId id : {j.a, j.b}) {
      const Point* p = id ? m.point(id) : nullptr;
      const int k = p ? sys.bodyIndex(p->body) : -1;
      if (k < 0) continue;
      lo[k] = std::min(lo[k], sys.pointDepth[id.value]);
      hi[k] = std::max(hi[k], sys.pointDepth[id.value]);
    }
  depth_.assign(n, 0.0);
  for (int k = 0; k < n; ++k) {
    depth_[k] = count[k] ? sum[k] / count[k] : placing_[k].depth;
    if (hi[k] - lo[k] > 1e-9 * sys.size) loaded[k] = 1;
  }
  bearing_.assign(n, -1);
  groundAt_.assign(n, Vec2::Zero());
  for (int k = 0; k < n; ++k) {
    if (mass[k] && mass[k]->kg > 0 && gravityOut_[k] != 0) loaded[k] = 1;
    if (grounded[k].size() == 1)
      bearing_[k] = *grounded[k].begin();
    else if (loaded[k])
      unsupported_.push_back(sys.bodyIds[k]);
    if (bearing_[k] < 0) continue;
    const Joint& j = m.joints[bearing_[k]];
    for (PointId id : {j.a, j.b})
      if (const Point* p = id ? m.point(id) : nullptr; p && sys.bodyIndex(p->body) < 0)
        groundAt_[k] = inClassFrame(m, pc, *p, sys.classOf[k]);
  }
}

void SpaceForces::shaking(const System& sys, const std::vector<BodyView>& views,
                          const Eigen::VectorXd& Q,
                          const std::vector<std::optional<BodyMass>>& mass, Vec3& force,
                          Vec3& moment) const {
  force.setZero();
  moment.setZero();
  for (int k = 0; k < sys.nBodies; ++k) {
    const Plane& f = sys.frames[sys.classOf[k]];
    const Vec3 n = f.normal();
    const BodyView& v = views[k + 1];
    const Vec3 O = f.origin + lift(f, v.r) + depth_[k] * n;
    Vec3 F = lift(f, Q.segment<2>(3 * k));
    moment += O.cross(F) + Q[3 * k + 2] * n;
    if (mass[k]) {  // the weight's normal part at the centre of mass
      const Vec3 weight = mass[k]->kg * gravityOut_[k] * n;
      moment += (O + lift(f, v.R * mass[k]->c)).cross(weight);
      F += weight;
    }
    force += F;
  }
  moment /= 1000;
}

void SpaceForces::reactions(const Mechanism& m, const System& sys,
                            const std::vector<BodyView>& views, const Eigen::VectorXd& lambda,
                            const Eigen::VectorXd& Q,
                            const std::vector<std::optional<BodyMass>>& mass, Forces& out) const {
  const int n = sys.nBodies;
  // Per body: its bearing's place (class frame, depth) and the out-of-plane load about it:
  // (force along the normal, moments about the class's x and y axes), N and N mm.
  std::vector<Vec2> B(n, Vec2::Zero());
  std::vector<double> dB(n, 0);
  std::vector<Vec3> W(n, Vec3::Zero());
  for (int k = 0; k < n; ++k)
    if (bearing_[k] >= 0) bearingPlace(m, sys, views, k, B[k], dB[k]);
  // A force (class frame: x, y, along the normal) on body k at P and depth d.
  auto add = [&](int k, const Vec3& F, const Vec2& P, double d) {
    if (k < 0 || bearing_[k] < 0) return;
    const Vec3 rel(P.x() - B[k].x(), P.y() - B[k].y(), d - dB[k]);
    const Vec3 M = rel.cross(F);
    W[k] += Vec3(F.z(), M.x(), M.y());
  };
  for (int k = 0; k < n; ++k) {
    const BodyView& v = views[k + 1];
    add(k, Vec3(Q[3 * k], Q[3 * k + 1], 0), B[k], depth_[k]);
    if (mass[k])
      add(k, Vec3(0, 0, mass[k]->kg * gravityOut_[k]), v.r + v.R * mass[k]->c, depth_[k]);
  }
  RowForce f;
  for (const Row& r : sys.cons) {
    if (r.joint < 0 || r.isDriver() || r.kind == Primitive::Angles || r.kind == Primitive::Hold)
      continue;
    const double* lam = lambda.data() + r.row;
    if (r.kind == Primitive::Distance3) {
      distance3::End e[2] = {{views[r.body[0] + 1], r.s[0], sys.frames[r.frame[0]], r.depth[0]},
                             {views[r.body[1] + 1], r.s[1], sys.frames[r.frame[1]], r.depth[1]}};
      const Vec3 D = distance3::world(e[0]) - distance3::world(e[1]);
      out.joints[r.joint].axialN = lam[0];
      for (int i = 0; i < 2; ++i) {
        if (r.body[i] < 0) continue;
        const Vec3 F = (i == 0 ? -lam[0] : lam[0]) / r.c[0] * D;  // the rod's pull on end i
        const Plane& c = e[i].f;
        add(r.body[i], Vec3(F.dot(c.xAxis), F.dot(c.yAxis), F.dot(c.normal())),
            e[i].b.r + e[i].b.R * e[i].s, e[i].depth);
      }
      continue;
    }
    rowForce(sys, views, r, f);
    Vec2 u = lam[0] * f.u[0];
    if (r.rows() == 2) u += lam[1] * f.u[1];
    const Joint& j = m.joints[r.joint];
    for (int i = 0; i < 2; ++i) {
      const int k = r.body[i];
      if (k < 0 || bearing_[k] == r.joint) continue;  // the bearing takes the rest
      const Vec2 F = i == 0 ? Vec2(-u) : u;
      add(k, Vec3(F.x(), F.y(), 0), f.P, depthOn(m, sys, j, k));
    }
  }
  for (int k = 0; k < n; ++k) {
    if (bearing_[k] < 0) continue;
    const Joint& j = m.joints[bearing_[k]];
    // The bearing's reaction on body k is -W; on the ground, when a is there, W.
    const double sign = sys.bodyIndex(m.point(j.a)->body) == k ? -1.0 : 1.0;
    JointReaction& r = out.joints[bearing_[k]];
    r.at = B[k];
    r.normalN = sign * W[k].x();
    r.tiltNm = sign * Vec2(W[k].y(), W[k].z()) / 1000;
  }
}

}  // namespace linkage
