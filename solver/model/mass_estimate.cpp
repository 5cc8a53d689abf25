#include "linkage/mass_estimate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace linkage {

const std::vector<Material>& materials() {
  static const std::vector<Material> list = {
      {"steel", 7850}, {"cast iron", 7200}, {"aluminium", 2700},
      {"brass", 8500}, {"bronze", 8800},    {"nylon", 1150},
  };
  return list;
}

// Green's theorem over the edges; moments taken about the first vertex so that a polygon far
// from the origin loses no digits.
PolygonMoments polygonMoments(const std::vector<Vec2>& polygon) {
  PolygonMoments r;
  if (polygon.size() < 3) return r;
  const Vec2 o = polygon[0];
  double a2 = 0, jo = 0;
  Vec2 c6 = Vec2::Zero();
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 p = polygon[i] - o, q = polygon[(i + 1) % polygon.size()] - o;
    const double w = cross(p, q);
    a2 += w;
    c6 += w * (p + q);
    jo += w * (p.squaredNorm() + p.dot(q) + q.squaredNorm());
  }
  r.area = std::abs(a2) / 2;
  if (a2 == 0) return r;
  const Vec2 c = c6 / (3 * a2);
  r.centroid = o + c;
  r.polar = std::abs(jo / 12) - r.area * c.squaredNorm();
  return r;
}

namespace {

std::vector<Vec2> drawnPoints(const Mechanism& m, BodyId body) {
  std::vector<Vec2> pts;
  for (const Point& p : m.points)
    if (p.body == body) pts.push_back(p.pos);
  for (const Slot& s : m.slots)
    if (s.body == body) pts.insert(pts.end(), {s.p0, s.p1});
  return pts;
}

// A stadium: a rectangle L x w and two half discs of radius r = w/2 at its ends. About its
// centre, per unit area: the rectangle's L w (L^2 + w^2)/12, and each half disc
// (L/2)^2 A_h + L (2 r^3 / 3) + pi r^4 / 4 (its polar moment about its flat side's middle is
// pi r^4 / 4, its first moment along the bar 2 r^3 / 3).
void stadium(double L, double w, double& area, double& polar) {
  const double r = w / 2, pi = std::numbers::pi;
  const double halfDisc = pi * r * r / 2;
  area = L * w + 2 * halfDisc;
  polar = L * w * (L * L + w * w) / 12 +
          2 * (L * L / 4 * halfDisc + L * 2 * r * r * r / 3 + pi * r * r * r * r / 4);
}

}  // namespace

MassEstimate estimateMass(const Mechanism& m, BodyId body, const Outline& o) {
  MassEstimate e;
  const Body* b = m.body(body);
  if (!b) return e.why = "no such body", e;
  if (!(o.kgPerM3 > 0 && o.thicknessMm > 0 && std::isfinite(o.kgPerM3 * o.thicknessMm)))
    return e.why = "the density and the thickness must be positive", e;
  const double perMm2 = o.kgPerM3 * 1e-9 * o.thicknessMm;  // kg per mm^2 of outline
  const std::vector<Vec2> pts = drawnPoints(m, body);
  if (o.shape == Outline::Shape::Plate) {
    e.outline = convexHull(pts);
    const PolygonMoments pm = polygonMoments(e.outline);
    if (e.outline.size() < 3 || !(pm.area > 0))
      return e.why = "a plate needs three points of '" + b->name + "' not in line: try a bar", e;
    e.mass = Mass{perMm2 * pm.area, pm.centroid, perMm2 * pm.polar, "", {}};
    return e;
  }
  if (!(o.widthMm > 0 && std::isfinite(o.widthMm)))
    return e.why = "the bar's width must be positive", e;
  double best = -1;
  for (size_t i = 0; i < pts.size(); ++i)
    for (size_t j = i + 1; j < pts.size(); ++j)
      if ((pts[i] - pts[j]).norm() > best)
        best = (pts[i] - pts[j]).norm(), e.outline = {pts[i], pts[j]};
  if (best <= 0) return e.why = "a bar needs two points of '" + b->name + "' apart", e;
  double area = 0, polar = 0;
  stadium(best, o.widthMm, area, polar);
  e.mass = Mass{perMm2 * area, (e.outline[0] + e.outline[1]) / 2, perMm2 * polar, "", {}};
  return e;
}

}  // namespace linkage
