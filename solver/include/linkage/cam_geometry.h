// A cam's geometry and its profile points, from its follower's motion programme (linkage/cam.h)
// and the geometry as drawn (../shared/specs/model-format.md, "Cams"). Everything is in the guiding
// body's frame with the cam's centre at the origin, theta the cam's turn counter-clockwise; the
// cam's own frame is the guide's turned by theta, so a point P of the guide's frame is
// p = R(-theta) P on the cam, and, writing J for a quarter turn counter-clockwise,
//
//   p' = R(-theta) (P' - J P),   p'' = R(-theta) (P'' - 2 J P' - P).
//
// Roller and knife edge: the pitch curve is the follower's point b on the cam,
//   translating  P = e w + (d0 + s) u,  d0 = sqrt((base + roller)^2 - e^2), w = u turned clockwise
//   oscillating  P = c + L (cos psi, sin psi), psi = psi0 + sigma s (the arm about its pivot c)
// traced clockwise as the cam turns, so its radius of curvature is convex-positive
//   rho = -|q1|^3 / (q1 x q2),  q1 = P' - J P,  q2 = P'' - 2 J P' - P;
// the surface is the pitch curve moved in by the roller along the normal J q1 / |q1| (radius
// rho - roller); the pressure angle is the angle between b's direction of motion m (u, or
// sigma J (cos psi, sin psi)) and the common normal n = J q1: atan((m x n) / (m . n)), for a
// translating roller atan((s' - e) / (d0 + s)).
// Flat face: the face is a line of the follower, normal nu, at h from the cam's centre; on the
// cam its normal is at gamma = angle(nu) - theta (+ sigma s when it oscillates), and the surface
// is the envelope of those lines: the contact point h N + h_gamma J N, N = (cos, sin) gamma, its
// radius h + h_gamma_gamma (base + s + s'' for a translating face), with
//   translating  h = base + s
//   oscillating  h = nu0 . (b0 - c) + c . R(sigma s) nu0   (nu0 = b0 / |b0|, the face through b0)
// One implementation: the cam joint draws its profile with it (elements/cam.cpp), the checks
// (linkage/cam_checks.h) and the exports (linkage/tables/cam_export.h) read it.
#pragma once

#include <string>
#include <vector>

#include "linkage/cam.h"
#include "linkage/cam_joint.h"
#include "linkage/geometry.h"

namespace linkage::cam {

enum class FollowerMotion : unsigned char { Translating, Oscillating };
enum class FollowerFace : unsigned char { Roller, Knife, Flat };

struct CamGeometry {
  FollowerMotion motion = FollowerMotion::Translating;
  FollowerFace face = FollowerFace::Roller;
  double baseMm = 0, rollerMm = 0;  // rollerMm 0 for a knife edge and a flat face
  Program program;                  // s in mm, or in radians for an oscillating follower
  // Translating: the unit rise direction and the offset e (b - a) . w.
  Vec2 u{0, 1};
  double offsetMm = 0;
  // Oscillating: the arm's pivot and the follower's point b as drawn; sigma = +1 when the arm
  // turning counter-clockwise moves b away from the cam's centre, else -1.
  Vec2 pivot = Vec2::Zero(), b0 = Vec2::Zero();
  double sigma = 1;
};

// A cam joint's geometry as drawn (linkage/cam_joint.h), its centre the origin.
CamGeometry geometryOf(const CamJoint& c);

// What is wrong with the geometry, "" when nothing (an offset beyond base + roller, a rise
// direction of no length, an arm of no length).
std::string checkCamGeometry(const CamGeometry& g);

// The profile at one cam angle, in the cam's frame (mm; the origin at its centre, axes as drawn).
struct CamPoint {
  double camDeg = 0;
  Vec2 surface = Vec2::Zero(), pitch = Vec2::Zero();  // pitch: the follower's point b
  double pressureDeg = 0;                             // signed; 0 for a flat face
  double radiusMm = 0;  // the surface's radius of curvature, convex positive
};
CamPoint camPointAt(const CamGeometry& g, double theta);
// The pitch curve's curvature at theta, convex positive (roller and knife edge).
double pitchCurvature(const CamGeometry& g, double theta);
// `steps` points a turn, from 0 to 360 - 360 / steps degrees.
std::vector<CamPoint> camPoints(const CamGeometry& g, int steps);

}  // namespace linkage::cam
