// A cam and its follower (elements/cam.cpp): follower body f = body[0] is displaced from its
// drawing by s(theta), theta the turn of cam body c = body[1] relative to guide body g = body[2]
// (counter-clockwise from the drawing, from the rotations: theta = angle(R_g^T R_c)); s' etc.
// its derivatives (linkage/cam.h).
//
// Translating (a block in a straight slot of g, rise direction u_g in g's frame; b = s_f on f,
// drawn at s_g in g's frame):
//   Phi   = n . (p - q) - s(theta),  n = R_g u_g, p = r_f + R_f s_f, q = r_g + R_g s_g   (mm)
//   J     = the OnLine row's (on_line.h, f against g with "normal" n) and
//           -s' in c's theta column, +s' in g's
//   gamma = the OnLine row's + s'' (w_c - w_g)^2
// Oscillating (pinned to g; a rise turns f by `sign` relative to g; s in radians):
//   Phi   = L (sign phi - s(theta)),  phi = angle(R_g^T R_f)                              (mm)
//   J     = L sign in f's theta column, -L s' in c's, L (s' - sign) in g's
//   gamma = L s'' (w_c - w_g)^2
// (From Phi'' = J q'' - gamma = 0: the s-part's second derivative is
// -s' theta'' - s'' theta'^2.)
//
// Its reaction is not this row's: J^T of it would push the follower along its slot and turn the
// cam by a couple, where the cam pushes the follower along the common normal at the contact. On
// the motion both rows vanish together and, with the follower's own joint and the cam's pin,
// span the same constraints (the contact row's share on the follower's free motion is
// cos(pressure angle), not 0), so the forces are solved with the contact row in its place:
// the point C and unit normal n of linkage/cam.h's contact(), a point on a curve of the cam:
//   J_contact = [ n^T, cross(C - r_f, n) | -n^T, -cross(C - r_c, n) | 0 ]
// and the multiplier is minus the contact force (compression positive).
#pragma once

#include "elements/on_line.h"
#include "elements/rows.h"
#include "linkage/cam.h"
#include "linkage/cam_joint.h"

namespace linkage {

struct CamRow {
  cam::Program program;
  cam::Follower kind;
  Vec2 centre = Vec2::Zero();  // the cam's centre a, in c's frame
  Vec2 along = Vec2::UnitY();  // translating: u, in g's frame
  Vec2 pivot = Vec2::Zero();   // oscillating: the follower's pivot, in g's frame
  Vec2 face = Vec2::UnitY();   // a flat face's normal, in f's frame
  bool operator==(const CamRow&) const = default;
};

namespace cam_row {

inline double theta(const BodyView& c, const BodyView& g) {
  return camAngle(c.R, g.R);
}

inline double residual(const Row& r, const BodyView& f, const BodyView& c, const BodyView& g,
                       double L) {
  const CamRow& k = *r.cam;
  const double s = k.program.at(theta(c, g)).s;
  if (!k.kind.oscillating) return on_line::residual(f, r.s[0], g, r.s[1], k.along) - s;
  return L * (k.kind.sign * camAngle(f.R, g.R) - s);
}

template <class Mat>
inline void jacobian(Mat& J, int row, const Row& r, const BodyView& f, const BodyView& c,
                     const BodyView& g, double L) {
  const CamRow& k = *r.cam;
  const double v = k.program.at(theta(c, g)).v;
  const double scale = k.kind.oscillating ? L : 1.0;
  if (!k.kind.oscillating)
    on_line::jacobian(J, row, f, r.s[0], g, k.along);
  else if (f.col >= 0)
    J(row, f.col + 2) += L * k.kind.sign;
  if (c.col >= 0) J(row, c.col + 2) -= scale * v;
  if (g.col >= 0) J(row, g.col + 2) += scale * v - (k.kind.oscillating ? L * k.kind.sign : 0.0);
}

inline double gamma(const Row& r, const BodyView& f, const BodyView& c, const BodyView& g,
                    double L) {
  const CamRow& k = *r.cam;
  const double a = k.program.at(theta(c, g)).a, w = c.w - g.w;
  if (!k.kind.oscillating) return on_line::gamma(f, r.s[0], g, r.s[1], k.along) + a * w * w;
  return L * a * w * w;
}

// The contact at the views' pose, in the world.
inline cam::Contact contact(const Row& r, const BodyView& f, const BodyView& c, const BodyView& g) {
  const CamRow& k = *r.cam;
  cam::Place at;
  at.centre = c.r + c.R * k.centre;
  at.b = f.r + f.R * r.s[0];
  at.along = g.R * k.along;
  at.pivot = g.r + g.R * k.pivot;
  at.face = f.R * k.face;
  return cam::contact(k.kind, at, k.program.at(theta(c, g)).v);
}

// The contact row's Jacobian block: three columns for each of f, c, g (g's zero).
template <class Mat>
inline void contactJacobian(Mat& J, const Row& r, const BodyView& f, const BodyView& c,
                            const BodyView& g) {
  const cam::Contact k = contact(r, f, c, g);
  const Vec2& n = k.normal;
  J(0, 0) = n.x();
  J(0, 1) = n.y();
  J(0, 2) = cross(k.point - f.r, n);
  J(0, 3) = -n.x();
  J(0, 4) = -n.y();
  J(0, 5) = -cross(k.point - c.r, n);
}

}  // namespace cam_row
}  // namespace linkage
