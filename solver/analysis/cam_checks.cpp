#include "linkage/cam_checks.h"

#include <cmath>
#include <functional>
#include <sstream>

#include "analysis/brent.h"

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

// The largest of f over the turn, at the smallest angle that reaches it: every local maximum
// of the grid refined by Brent's method between its neighbours, the best kept.
CamExtreme largest(const CamGeometry& g, const std::function<double(double)>& f) {
  std::vector<double> grid;
  const auto& segs = g.program.segments();
  const size_t n = std::max<size_t>(1, segs.size());
  for (size_t k = 0; k < n; ++k) {
    const double a = segs.empty() ? 0 : g.program.startOf(k);
    const double b = segs.empty() ? 2 * M_PI : segs[k].toDeg * kDeg;
    for (int i = 0; i < 64; ++i) grid.push_back(a + (b - a) * i / 64);
  }
  const size_t N = grid.size();
  std::vector<double> v(N);
  for (size_t i = 0; i < N; ++i) v[i] = f(grid[i]);
  CamExtreme best;
  auto take = [&](double value, double theta) {
    if (std::isfinite(value) && (!best.found || value > best.value)) best = {true, value, theta};
  };
  for (size_t i = 0; i < N; ++i) {
    const size_t prev = (i + N - 1) % N, next = (i + 1) % N;
    take(v[i], grid[i]);
    if (!(v[i] >= v[prev] && v[i] >= v[next])) continue;
    const double lo = i == 0 ? grid[N - 1] - 2 * M_PI : grid[prev];
    const double hi = i + 1 == N ? 2 * M_PI : grid[next];
    double fmin = 0;
    const double x = brent::minimum([&](double t) { return -f(t); }, lo, hi, 1e-12, &fmin);
    take(-fmin, x);
  }
  if (!best.found) return best;
  best.atDeg = std::remainder(best.atDeg, 2 * M_PI) / kDeg;
  if (best.atDeg < 0) best.atDeg += 360;
  return best;
}

std::string at(double deg) {
  std::ostringstream s;
  s.precision(6);
  s << deg;
  return s.str();
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

CamChecks camChecks(const CamGeometry& g) {
  CamChecks c;
  if (g.face == FollowerFace::Flat) {
    c.surfaceRadiusMin =
        largest(g, [&](double t) { return -flatAt(g, g.program.at(t), t).radiusMm; });
    c.surfaceRadiusMin.value = -c.surfaceRadiusMin.value;
    if (c.surfaceRadiusMin.found && c.surfaceRadiusMin.value < 0) {
      c.undercut = true;
      c.undercutWhy = "the surface is not convex at " + at(c.surfaceRadiusMin.atDeg) +
                      " degrees (radius " + at(c.surfaceRadiusMin.value) +
                      " mm): the flat face cannot follow it";
    }
    return c;
  }
  c.pressureMax = largest(g, [&](double t) { return std::abs(camPointAt(g, t).pressureDeg); });
  const CamExtreme k = largest(g, [&](double t) {
    Vec2 q1, q2;
    pitchRates(pathAt(g, g.program.at(t)), q1, q2);
    return curvature(q1, q2);
  });
  if (k.found && k.value > 0) c.pitchRadiusMin = {true, 1 / k.value, k.atDeg};
  if (g.face == FollowerFace::Roller && c.pitchRadiusMin.found &&
      c.pitchRadiusMin.value <= g.rollerMm) {
    c.undercut = true;
    c.undercutWhy = "the roller (" + at(g.rollerMm) + " mm) is larger than the pitch curve's " +
                    "convex radius " + at(c.pitchRadiusMin.value) + " mm at " +
                    at(c.pitchRadiusMin.atDeg) + " degrees";
  }
  return c;
}

CamGeometry withBase(const CamGeometry& g, double baseMm) {
  CamGeometry h = g;
  h.baseMm = baseMm;
  if (g.motion != FollowerMotion::Oscillating) return h;
  // The pivot and the arm stay: b on the arm's circle at base + roller from the centre, on
  // the side of the line centre-pivot it is drawn on.
  const Vec2 c = g.pivot;
  const double d = c.norm(), L = (g.b0 - c).norm(), R = baseMm + g.rollerMm;
  if (!(d > 0)) return h;
  const double x = (R * R - L * L + d * d) / (2 * d), y2 = R * R - x * x;
  const Vec2 e = c / d;
  const double side = cross(c, g.b0) >= 0 ? 1 : -1;
  h.b0 = x * e + side * std::sqrt(std::max(0.0, y2)) * perp(e);
  if (!(y2 >= 0)) h.b0 = Vec2::Zero();  // no such arm: refused by checkCamGeometry
  return h;
}

std::optional<double> smallestBaseFor(const CamGeometry& g, double limitDeg) {
  if (g.face == FollowerFace::Flat || !(limitDeg > 0 && limitDeg < 90)) return std::nullopt;
  auto meets = [&](double base) {
    const CamGeometry h = withBase(g, base);
    if (!checkCamGeometry(h).empty()) return false;
    const CamChecks c = camChecks(h);
    return c.pressureMax.found && c.pressureMax.value <= limitDeg;
  };
  // The bases the geometry allows: a translating follower's offset inside the prime circle,
  // where its angle falls as the base grows; an oscillating one's arm reaching the circle
  // (|d - L| to d + L), where it need not: the first of a scan that meets the limit.
  double lo, hi;
  if (g.motion == FollowerMotion::Translating) {
    lo = std::max(0.0, std::abs(g.offsetMm) - g.rollerMm) + 1e-9;
    hi = std::max(g.baseMm, 2 * lo);
    while (!meets(hi))
      if ((hi *= 2) > 1e6) return std::nullopt;
  } else {
    const double d = g.pivot.norm(), L = (g.b0 - g.pivot).norm();
    lo = std::max(std::abs(d - L) - g.rollerMm, 0.0) + 1e-9;
    hi = d + L - g.rollerMm - 1e-9;
    if (!(hi > lo)) return std::nullopt;
  }
  double below = lo, first = NAN;
  for (int i = 0; i <= 256 && std::isnan(first); ++i) {
    const double b = lo + (hi - lo) * i / 256;
    (meets(b) ? first : below) = b;
  }
  if (std::isnan(first)) return std::nullopt;
  if (first == lo) return lo;
  while (first - below > 1e-9 * std::max(1.0, first)) {
    const double mid = (below + first) / 2;
    (meets(mid) ? first : below) = mid;
  }
  return first;
}

std::optional<double> largestRoller(const CamGeometry& g) {
  if (g.face == FollowerFace::Flat) return std::nullopt;
  const CamChecks c = camChecks(g);
  if (!c.pitchRadiusMin.found) return std::nullopt;
  return c.pitchRadiusMin.value;
}

}  // namespace linkage::cam
