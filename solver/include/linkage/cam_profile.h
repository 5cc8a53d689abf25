// A cam's profile, cut from its follower's motion (linkage/cam.h): at each cam angle theta, in
// the cam's own frame (origin its centre a, axes as drawn, so that it turns with the cam), the
// pitch curve (where the follower's point b is: a roller's centre, a knife's edge) and the
// working surface (where the contact is: the pitch curve less the roller along the common
// normal, the knife's edge itself, or a flat face's contact point), and the pressure angle.
//
// With the cam turned by theta counter-clockwise relative to the guide, the follower, as drawn
// at b0 (and its pivot P, or its rise direction u), is at
//   translating:   b = b0 + s u
//   oscillating:   b = P + R(sign s) (b0 - P), a flat face's normal turned by sign s too
// in the guide's frame; contact() gives the contact point c and the common normal n there, and
//   pitch = R(-theta) (b - a),   surface = R(-theta) (c - a)   (c = b - roller n for a roller)
// The pressure angle is the signed angle from the follower's direction of motion db/ds (u, or
// sign perp(b - P)) to n: atan2(cross(db/ds, n), db/ds . n). For a translating roller follower
// with offset e that is atan((s' - e) / (sqrt((base + roller)^2 - e^2) + s)), the spec's.
// It is the cam joint's own (its drawing; elements/ cannot call analysis/): the checks of a
// profile (extremes found exactly, radii of curvature, undercut) and its export are
// linkage/cam_checks.h's and linkage/tables/cam_export.h's, from the same formulas.
#pragma once

#include <vector>

#include "linkage/cam.h"

namespace linkage::cam {

struct ProfilePoint {
  double theta = 0;  // radians
  Eigen::Vector2d pitch = Eigen::Vector2d::Zero();
  Eigen::Vector2d surface = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  // the common normal, the cam's frame
  double pressureAngle = 0;                           // radians
};

// At theta (radians), from the follower as drawn (`drawn`: the places at the drawing, in the
// guide's frame).
ProfilePoint profileAt(const Follower& f, const Place& drawn, const Program& p, double theta);
// At `steps` equal steps of a turn from theta = 0 (at least 3).
std::vector<ProfilePoint> profile(const Follower& f, const Place& drawn, const Program& p,
                                  int steps);

}  // namespace linkage::cam
