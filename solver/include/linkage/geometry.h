// Planar geometry every part of the program shares: vectors in millimetres, rotations kept as
// (cos, sin) so that no angle is turned into a sine twice, and rigid transforms from a body's
// drawn (sketch) coordinates to the world at a pose.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace linkage {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Rotation by +90 degrees: d/dtheta (R(theta) s) = perp(R(theta) s).
inline Vec2 perp(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}

inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A rotation as the cosine and sine of its angle.
struct Rot {
  double c = 1, s = 0;
  static Rot of(double angle) { return Rot{std::cos(angle), std::sin(angle)}; }
  Vec2 operator*(const Vec2& v) const { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }
  Rot inverse() const { return Rot{c, -s}; }
  double angle() const { return std::atan2(s, c); }
};

// A rigid motion: world = R * sketch + t. A body's transform at a pose maps the coordinates it
// was drawn in (the file's global sketch coordinates) to where they are now; at the drawing
// itself it is the identity.
struct Transform {
  Rot R;
  Vec2 t = Vec2::Zero();
  Vec2 operator*(const Vec2& sketch) const { return R * sketch + t; }
  Vec2 inverse(const Vec2& world) const { return R.inverse() * (world - t); }
};

// The convex hull, counter-clockwise (Andrew's monotone chain), without collinear points: a row
// of points gives its two ends.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

}  // namespace linkage
