// A cam's geometry and profile points: linkage/cam_geometry.h has the formulas.
#include <cmath>

#include "linkage/cam_geometry.h"

namespace linkage::cam {

namespace {

constexpr double kDeg = M_PI / 180;

// The follower's point b in the guide's frame and its first two derivatives by theta.
struct Path {
  Vec2 P, P1, P2;
  Vec2 m;  // b's direction of motion as s grows (unit)
};

// How far along u from the foot of the perpendicular b is drawn: a flat face's at the base.
double d0Of(const CamGeometry& g) {
  if (g.face == FollowerFace::Flat) return g.baseMm;
  const double r = g.baseMm + g.rollerMm;
  return std::sqrt(std::max(0.0, r * r - g.offsetMm * g.offsetMm));
}

Vec2 wOf(const Vec2& u) {
  return Vec2(u.y(), -u.x());  // u turned clockwise
}

Path pathAt(const CamGeometry& g, const Displacement& d) {
  if (g.motion == FollowerMotion::Translating) {
    const Vec2 u = g.u.normalized();
    return {g.offsetMm * wOf(u) + (d0Of(g) + d.s) * u, d.v * u, d.a * u, u};
  }
  const Vec2 arm0 = g.b0 - g.pivot;
  const double L = arm0.norm(), psi = std::atan2(arm0.y(), arm0.x()) + g.sigma * d.s;
  const Vec2 e(std::cos(psi), std::sin(psi));
  return {g.pivot + L * e, L * g.sigma * d.v * perp(e),
          L * (g.sigma * d.a * perp(e) - d.v * d.v * e), g.sigma * perp(e)};
}

// The pitch curve's tangent and second derivative, turned into the guide's frame.
void pitchRates(const Path& p, Vec2& q1, Vec2& q2) {
  q1 = p.P1 - perp(p.P);
  q2 = p.P2 - 2 * perp(p.P1) - p.P;
}

// The flat face's line on the cam: its distance h, the angle gamma of its normal, and their
// rates by theta.
struct FaceLine {
  double h, h1, h2, gamma, g1, g2;
};

FaceLine faceAt(const CamGeometry& g, const Displacement& d, double theta) {
  if (g.motion == FollowerMotion::Translating) {
    const Vec2 u = g.u.normalized();
    return {g.baseMm + d.s, d.v, d.a, std::atan2(u.y(), u.x()) - theta, -1, 0};
  }
  const Vec2 nu0 = g.b0.normalized(), c = g.pivot;
  const Rot R = Rot::of(g.sigma * d.s);
  const Vec2 nu = R * nu0;
  const double cJ = c.dot(perp(nu)), cN = c.dot(nu);
  return {nu0.dot(g.b0 - c) + cN,
          g.sigma * d.v * cJ,
          g.sigma * d.a * cJ - d.v * d.v * cN,
          std::atan2(nu.y(), nu.x()) - theta,
          g.sigma * d.v - 1,
          g.sigma * d.a};
}

Vec2 toCam(const Vec2& v, double theta) {
  return Rot::of(-theta) * v;
}

CamPoint flatAt(const CamGeometry& g, const Displacement& d, double theta) {
  const FaceLine f = faceAt(g, d, theta);
  const double hg = f.h1 / f.g1;
  const double hgg = (f.h2 * f.g1 - f.h1 * f.g2) / (f.g1 * f.g1 * f.g1);
  const Vec2 N(std::cos(f.gamma), std::sin(f.gamma));
  CamPoint p;
  p.surface = f.h * N + hg * perp(N);
  p.pitch = toCam(pathAt(g, d).P, theta);
  p.radiusMm = f.h + hgg;
  return p;
}

// The pitch curve's curvature, convex positive (the curve runs clockwise on the cam).
double curvature(const Vec2& q1, const Vec2& q2) {
  return -cross(q1, q2) / std::pow(q1.norm(), 3);
}

}  // namespace

CamGeometry geometryOf(const CamJoint& c) {
  CamGeometry g;
  g.motion = c.kind.oscillating ? FollowerMotion::Oscillating : FollowerMotion::Translating;
  g.face = c.kind.flat         ? FollowerFace::Flat
           : c.kind.roller > 0 ? FollowerFace::Roller
                               : FollowerFace::Knife;
  g.baseMm = c.kind.base;
  g.rollerMm = c.kind.flat ? 0 : c.kind.roller;
  g.program = c.program;
  g.u = c.drawn.along;
  g.offsetMm = c.offset;
  g.pivot = c.drawn.pivot - c.drawn.centre;
  g.b0 = c.drawn.b - c.drawn.centre;
  g.sigma = c.kind.sign;
  return g;
}

std::string checkCamGeometry(const CamGeometry& g) {
  if (!(g.baseMm > 0)) return "the base radius must be a length above 0";
  if (!(g.rollerMm >= 0)) return "the roller's radius must be 0 (a knife edge) or more";
  if (g.motion == FollowerMotion::Translating) {
    if (!(g.u.norm() > 0)) return "the slot has no direction";
    if (g.face != FollowerFace::Flat && !(std::abs(g.offsetMm) < g.baseMm + g.rollerMm))
      return "the offset reaches past the base circle and the roller";
    return "";
  }
  if (!((g.b0 - g.pivot).norm() > 0)) return "the follower's arm has no length";
  if (!(g.b0.norm() > 0)) return "the follower's point is on the cam's centre";
  return "";
}

CamPoint camPointAt(const CamGeometry& g, double theta) {
  const Displacement d = g.program.at(theta);
  CamPoint p;
  if (g.face == FollowerFace::Flat) {
    p = flatAt(g, d, theta);
  } else {
    const Path path = pathAt(g, d);
    Vec2 q1, q2;
    pitchRates(path, q1, q2);
    const Vec2 n = perp(q1).normalized();  // outward
    p.pitch = toCam(path.P, theta);
    p.surface = toCam(path.P - g.rollerMm * n, theta);
    p.radiusMm = 1 / curvature(q1, q2) - g.rollerMm;
    p.pressureDeg = std::atan(cross(path.m, n) / path.m.dot(n)) / kDeg;
  }
  p.camDeg = theta / kDeg;
  return p;
}

std::vector<CamPoint> camPoints(const CamGeometry& g, int steps) {
  std::vector<CamPoint> out;
  for (int i = 0; i < steps; ++i) out.push_back(camPointAt(g, 2 * M_PI * i / steps));
  return out;
}

double pitchCurvature(const CamGeometry& g, double theta) {
  Vec2 q1, q2;
  pitchRates(pathAt(g, g.program.at(theta)), q1, q2);
  return curvature(q1, q2);
}

}  // namespace linkage::cam
