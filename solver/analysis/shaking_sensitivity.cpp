// The shaking force's derivative with respect to a dimension: see linkage/shaking_sensitivity.h.
#include "linkage/shaking_sensitivity.h"

namespace linkage {

Vec2 shakingForceSensitivity(const Kinematics& k, const Sensitivity& s, int dim) {
  Vec2 dF = Vec2::Zero();
  for (const Body& b : k.mechanism().bodies)
    if (!b.ground && b.mass && b.mass->kg != 0)
      dF -= b.mass->kg * s.acceleration(k, b.id, b.mass->com, dim) / 1000;  // kg mm/s^2 -> N
  return dF;
}

}  // namespace linkage
