// The shaking force's derivative with respect to a dimension: see linkage/shaking_sensitivity.h.
#include "linkage/shaking_sensitivity.h"

#include <limits>

#include "elements/distance3.h"
#include "kinematics/kinematics_state.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage {

Vec2 shakingForceSensitivity(const Kinematics& k, const Sensitivity& s, int dim) {
  Vec2 dF = Vec2::Zero();
  for (const Body& b : k.mechanism().bodies)
    if (!b.ground && b.mass && b.mass->kg != 0)
      dF -= b.mass->kg * s.acceleration(k, b.id, b.mass->com, dim) / 1000;  // kg mm/s^2 -> N
  return dF;
}

Vec3 shakingForceSensitivity3(const Kinematics& k, const Sensitivity& s, int dim) {
  const Eigen::VectorXd dQ = generalizedForcesChange(k, s, dim);
  const System& sys = internal::system(k);
  Vec3 dF = Vec3::Zero();
  for (int i = 0; i < sys.nBodies && dQ.size(); ++i) {
    const Plane& f = sys.frames[sys.classOf.empty() ? 0 : sys.classOf[i]];
    dF += dQ[3 * i] * f.xAxis + dQ[3 * i + 1] * f.yAxis;
  }
  return dF;
}

double shakingMomentSensitivity(const Kinematics& k, const Sensitivity& s, int dim) {
  const Eigen::VectorXd Q = generalizedForces(k), dQ = generalizedForcesChange(k, s, dim);
  if (Q.size() == 0 || dQ.size() != Q.size()) return std::numeric_limits<double>::quiet_NaN();
  double dM = 0;  // N mm
  for (int b = 0; 3 * b < Q.size(); ++b) {
    const Vec2 r = k.q().segment<2>(3 * b), dr = s.dq().block<2, 1>(3 * b, dim);
    dM += dQ[3 * b + 2] + cross(dr, Q.segment<2>(3 * b)) + cross(r, dQ.segment<2>(3 * b));
  }
  return dM / 1000;
}

// M = sum_k [O_k x F_k + Qm_k n + C_k x W_k] / 1000 (analysis/space_forces.cpp shaking): O_k the
// body's frame origin at its depth (the mean of its points'), C_k its centre of mass there, W_k
// its weight's part along the normal (the same in every design). The class frames stay put; a
// dimension moves O_k by lift(dr) + d(depth) n and C_k by that, the centre's turn and, for a
// plane's origin, its own move in the body (linkage/force_sensitivity.h forcesChangeOf's comMove).
Vec3 shakingMomentSensitivity3(const Kinematics& k, const Sensitivity& s, int dim) {
  const Mechanism& m = k.mechanism();
  const System& sys = internal::system(k);
  const Eigen::VectorXd Q = generalizedForces(k), dQ = generalizedForcesChange(k, s, dim);
  if (Q.size() == 0 || dQ.size() != Q.size()) return Vec3::Constant(std::nan(""));
  if (!isSpatial(m)) {  // the planar moment about z, and the weights' tilt (dynamics.cpp)
    Vec3 dM(0, 0, shakingMomentSensitivity(k, s, dim));
    const double gz = m.gravityZ.value_or(0);
    for (const Body& b : m.bodies)
      if (!b.ground && b.mass && gz != 0) {
        const Vec2 dc = s.point(k, b.id, b.mass->com, Vec2::Zero(), dim);
        dM += Vec3(dc.x(), dc.y(), 0).cross(Vec3(0, 0, b.mass->kg * gz)) / 1000;
      }
    return dM;
  }
  const int n = sys.nBodies;
  std::vector<double> depth(n, 0.0), dDepth(n, 0.0);
  std::vector<int> count(n, 0);
  std::vector<PointId> first(n);
  for (const Point& p : m.points)
    if (const int b = sys.bodyIndex(p.body); b >= 0) {
      const Vec3 nb = sys.frames[sys.classOf[b]].normal();
      depth[b] += sys.pointDepth[p.id.value];
      dDepth[b] += nb.dot(s.point3(k, p.id, dim));
      if (!count[b]++) first[b] = p.id;
    }
  const PlaneClasses pc = planeClasses(m);
  const Vec3 g = m.gravityWorld();
  Vec3 dM = Vec3::Zero();  // N mm
  for (int b = 0; b < n; ++b) {
    const Plane& f = sys.frames[sys.classOf[b]];
    const Vec3 nb = f.normal();
    if (count[b])
      depth[b] /= count[b], dDepth[b] /= count[b];
    else
      depth[b] = pc.of(m.body(sys.bodyIds[b])->plane).depth;
    const Vec2 r = k.q().segment<2>(3 * b), dr = s.dq().block<2, 1>(3 * b, dim);
    const double th = k.q()[3 * b + 2], dth = s.dq()(3 * b + 2, dim);
    const Vec3 O = f.origin + distance3::lift(f, r) + depth[b] * nb;
    const Vec3 dO = distance3::lift(f, dr) + dDepth[b] * nb;
    dM += dO.cross(distance3::lift(f, Q.segment<2>(3 * b))) +
          O.cross(distance3::lift(f, dQ.segment<2>(3 * b))) + dQ[3 * b + 2] * nb;
    const Body& body = *m.body(sys.bodyIds[b]);
    if (!body.mass) continue;
    const PlaneInClass in = pc.of(body.plane);
    const Vec2 Rc = Rot::of(th) * Vec2(in.toClass(body.mass->com) - sys.frameOrigin[b]);
    Vec2 own = Vec2::Zero();  // a plane's origin moves the centre with the body's points
    if (s.dims()[dim].carriesMasses && count[b]) {
      const PointLocation* at = sys.point(first[b]);
      own = s.point(k, first[b], dim) - dr - dth * perp(Vec2(Rot::of(th) * at->s));
    }
    const Vec3 dC = dO + distance3::lift(f, Vec2(dth * perp(Rc) + own));
    dM += dC.cross(body.mass->kg * g.dot(nb) * nb);
  }
  return dM / 1000;
}

}  // namespace linkage
