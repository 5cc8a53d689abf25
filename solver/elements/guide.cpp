#include "linkage/guide.h"

#include <algorithm>
#include <cmath>

namespace linkage {

namespace {
// Beyond this the arc is a straight line to every digit a drawing carries.
constexpr double kLargestRadius = 1e12;  // mm
}  // namespace

bool circleThrough(const Vec2& a, const Vec2& b, const Vec2& c, Vec2& centre, double& radius) {
  // Relative to a: the centre x solves 2 (b - a) . x = |b - a|^2, 2 (c - a) . x = |c - a|^2.
  const Vec2 u = b - a, v = c - a;
  const double det = 2 * cross(u, v);
  if (!(std::abs(det) > 1e-12 * u.norm() * v.norm())) return false;
  const Vec2 x((v.y() * u.squaredNorm() - u.y() * v.squaredNorm()) / det,
               (u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) / det);
  centre = a + x;
  radius = x.norm();
  return std::isfinite(radius);
}

std::optional<Guide> guideOf(const Slot& s, std::string* why) {
  auto fail = [&](const char* text) -> std::optional<Guide> {
    if (why) *why = text;
    return std::nullopt;
  };
  Guide g;
  g.p0 = s.p0;
  g.p1 = s.p1;
  if (!s.mid) {
    const Vec2 d = s.p1 - s.p0;
    const double scale = std::max(s.p0.cwiseAbs().maxCoeff(), s.p1.cwiseAbs().maxCoeff());
    if (!(d.norm() > 1e-12 * scale) || !(d.norm() > 0)) return fail("zero-length slot");
    g.direction = d.normalized();
    g.normal = perp(g.direction);
    return g;
  }
  const Vec2 m = *s.mid;
  if (s.p0 == s.p1 || s.p0 == m || m == s.p1) return fail("two of the arc's three points coincide");
  if (!circleThrough(s.p0, m, s.p1, g.centre, g.radius) || g.radius > kLargestRadius)
    return fail("its three points lie on one line: an arc needs them off it");
  g.arc = true;
  const Vec2 e0 = s.p0 - g.centre, em = m - g.centre, e1 = s.p1 - g.centre;
  g.a0 = std::atan2(e0.y(), e0.x());
  // Counter-clockwise from p0, mid comes before p1 exactly when the arc runs that way.
  auto ccwAngle = [&](const Vec2& e) {
    double a = std::atan2(cross(e0, e), e0.dot(e));
    return a < 0 ? a + 2 * M_PI : a;
  };
  const double toMid = ccwAngle(em), toEnd = ccwAngle(e1);
  g.sweep = toMid < toEnd ? toEnd : toEnd - 2 * M_PI;
  return g;
}

bool soundSlot(const Slot& s, std::string* why) {
  const size_t n = s.arc() ? 3 : 2;
  if (s.z.size() != n) return guideOf(s, why).has_value();
  const Vec3 w0(s.p0.x(), s.p0.y(), s.z[0]), w1(s.p1.x(), s.p1.y(), s.z[n - 1]);
  const Vec3 u = w1 - w0;
  const double scale = std::max(w0.cwiseAbs().maxCoeff(), w1.cwiseAbs().maxCoeff());
  if (!s.mid) {
    const bool sound = u.norm() > 1e-12 * scale && u.norm() > 0;
    if (!sound && why) *why = "zero-length slot";
    return sound;
  }
  // The arc drawn in its own plane, p0 at the origin and p1 along x, at the same distances: its
  // tests (points that coincide, on one line) are guideOf's.
  const Vec3 wm = Vec3(s.mid->x(), s.mid->y(), s.z[1]) - w0;
  const Vec3 e = u.norm() > 0 ? Vec3(u.normalized()) : Vec3::UnitX();
  const double along = e.dot(wm);
  Slot flat = s;
  flat.z.clear();
  flat.p0 = Vec2::Zero();
  flat.p1 = Vec2(u.norm(), 0);
  flat.mid = Vec2(along, (wm - along * e).norm());
  if (wm.isZero(0)) flat.mid = flat.p0;
  return guideOf(flat, why).has_value();
}

double Guide::length() const {
  return arc ? radius * std::abs(sweep) : (p1 - p0).norm();
}

Vec2 Guide::normalAt(const Vec2& p) const {
  if (!arc) return normal;
  const Vec2 d = p - centre;
  const double n = d.norm();
  return n > 0 ? Vec2(d / n) : Vec2(Rot::of(a0) * Vec2::UnitX());
}

Vec2 Guide::tangentAt(const Vec2& p) const {
  if (!arc) return direction;
  const Vec2 t = perp(normalAt(p));
  return sweep >= 0 ? t : Vec2(-t);
}

Vec2 Guide::at(double t) const {
  if (!arc) return p0 + t * direction;
  const double a = a0 + (sweep >= 0 ? t : -t) / radius;
  return centre + radius * Vec2(std::cos(a), std::sin(a));
}

double Guide::along(const Vec2& p) const {
  if (!arc) return (p - p0).dot(direction);
  const Vec2 e0 = p0 - centre, e = p - centre;
  // The angle from p0 in the arc's direction, put where the gap past the ends is split evenly.
  double a = std::atan2(cross(e0, e), e0.dot(e)) * (sweep >= 0 ? 1 : -1);
  const double span = std::abs(sweep), gap = 2 * M_PI - span;
  if (a < -gap / 2) a += 2 * M_PI;
  if (a > span + gap / 2) a -= 2 * M_PI;
  return a * radius;
}

Vec2 Guide::nearest(const Vec2& p) const {
  return at(std::clamp(along(p), 0.0, length()));
}

Vec2 Guide::project(const Vec2& p) const {
  if (!arc) return p0 + (p - p0).dot(direction) * direction;
  const Vec2 e = p - centre;
  const double n = e.norm();
  return n > 0 ? Vec2(centre + radius * e / n) : p0;
}

}  // namespace linkage
