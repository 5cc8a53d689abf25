// The shaking force's derivative with respect to a dimension: see linkage/shaking_sensitivity.h.
#include "linkage/shaking_sensitivity.h"

#include "kinematics/kinematics_state.h"
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

}  // namespace linkage
