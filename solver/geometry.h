// Small planar helpers shared by the joint files.
#pragma once

#include <Eigen/Core>

namespace linkage {

using Vec2 = Eigen::Vector2d;

// Rotation by +90 degrees: d/dtheta (R(theta) s) = perp(R(theta) s).
inline Vec2 perp(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}

// Cosine and sine of a body's angle, computed once per evaluation and shared by all its joints.
struct Rot {
  double c = 1, s = 0;
  Vec2 operator*(const Vec2& v) const { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }
};

// A body's pose and velocity as the joints see them. Ground has x = y = theta = 0 and no
// coordinates.
struct BodyView {
  int col = -1;  // first of its three columns (x, y, theta) in q, or -1 for ground
  Vec2 r = Vec2::Zero();
  double theta = 0;
  Rot R;
  Vec2 v = Vec2::Zero();  // velocity of the frame origin (or d/dphi of it)
  double w = 0;           // angular velocity (or d/dphi)
};

}  // namespace linkage
