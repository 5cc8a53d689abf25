#include "linkage/cam_checks.h"

#include <cmath>
#include <functional>
#include <sstream>

#include "analysis/brent.h"

namespace linkage::cam {

namespace {

constexpr double kDeg = M_PI / 180;

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

CamChecks camChecks(const CamGeometry& g) {
  CamChecks c;
  if (g.face == FollowerFace::Flat) {
    c.surfaceRadiusMin = largest(g, [&](double t) { return -camPointAt(g, t).radiusMm; });
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
  const CamExtreme k = largest(g, [&](double t) { return pitchCurvature(g, t); });
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
