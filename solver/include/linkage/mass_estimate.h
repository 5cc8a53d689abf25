// A body's mass properties estimated from its outline as drawn, for a designer who has no CAD
// model yet: a plate (the convex hull of the body's points and slot ends) or a bar (a stadium,
// straight with round ends of half its width, between the two points farthest apart) of a
// chosen material and thickness. Exact for those shapes: polygon sums (area, first and second
// moments by Green's theorem) and the stadium's closed form.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage {

struct Material {
  const char* name;
  double kgPerM3;
};
// Steel, cast iron, aluminium, brass, bronze, nylon (typical densities).
const std::vector<Material>& materials();

struct Outline {
  enum class Shape { Bar, Plate };
  Shape shape = Shape::Bar;
  double kgPerM3 = 7850;
  double thicknessMm = 5;
  double widthMm = 10;  // a bar's
};

struct MassEstimate {
  std::optional<Mass> mass;  // none: `why` says what the outline lacks
  std::string why;
  std::vector<Vec2> outline;  // the polygon used (a plate), or the bar's two end centres
};

MassEstimate estimateMass(const Mechanism& m, BodyId body, const Outline& o);

// Of a simple polygon (either orientation), with density 1 per unit area: area, centroid and
// the second moment about the centroid (polar, mm^4).
struct PolygonMoments {
  double area = 0;
  Vec2 centroid = Vec2::Zero();
  double polar = 0;
};
PolygonMoments polygonMoments(const std::vector<Vec2>& polygon);

}  // namespace linkage
