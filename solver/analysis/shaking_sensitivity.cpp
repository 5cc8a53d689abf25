// The shaking force's derivative with respect to a dimension: see linkage/shaking_sensitivity.h.
#include "linkage/shaking_sensitivity.h"

#include <limits>

#include "kinematics/kinematics_state.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
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

}  // namespace linkage
