// A cam's profile: linkage/cam_profile.h has the formulas.
#include <algorithm>
#include <cmath>

#include "linkage/cam_profile.h"

namespace linkage::cam {

namespace {

using V = Eigen::Vector2d;

V turned(double angle, const V& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return V(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

}  // namespace

ProfilePoint profileAt(const Follower& f, const Place& drawn, const Program& p, double theta) {
  const Displacement d = p.at(theta);
  Place at = drawn;
  V dbds = drawn.along;
  if (f.oscillating) {
    at.b = drawn.pivot + turned(f.sign * d.s, drawn.b - drawn.pivot);
    at.face = turned(f.sign * d.s, drawn.face);
    dbds = f.sign * V(-(at.b - at.pivot).y(), (at.b - at.pivot).x());
  } else {
    at.b = drawn.b + d.s * drawn.along;
  }
  const Contact c = contact(f, at, d.v);
  ProfilePoint out;
  out.theta = theta;
  out.pitch = turned(-theta, at.b - at.centre);
  const V surface = f.flat ? c.point : V(at.b - f.roller * c.normal);
  out.surface = turned(-theta, surface - at.centre);
  out.normal = turned(-theta, c.normal);
  out.pressureAngle =
      std::atan2(dbds.x() * c.normal.y() - dbds.y() * c.normal.x(), dbds.dot(c.normal));
  return out;
}

std::vector<ProfilePoint> profile(const Follower& f, const Place& drawn, const Program& p,
                                  int steps) {
  steps = std::max(steps, 3);
  std::vector<ProfilePoint> out;
  out.reserve(steps);
  for (int i = 0; i < steps; ++i) out.push_back(profileAt(f, drawn, p, 2 * M_PI * i / steps));
  return out;
}

}  // namespace linkage::cam
