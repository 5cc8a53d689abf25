// How a body's later point is given among its dimensions (linkage/sensitivity.h): by its
// distances from the body's first two points P0 and P1, or, where those do not place it well,
// by its coordinates along and across P0->P1. The dimensions and their exact changes
// (linkage/dimension_change.h) read it from here, so they agree on every drawing.
#pragma once

#include <cmath>

#include "linkage/geometry.h"

namespace linkage {

// Seen from Pk, P0 and P1 closer than this to one line (rad): two distances do not place Pk
// well (their sensitivities grow as 1 / this), so it is placed along and across P0->P1.
inline constexpr double kOnLine = 1e-3;

// Whether c (Pk) is given along and across a->b (P0->P1, apart) rather than by two distances.
inline bool alongAndAcross(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double len = (b - a).norm(), r0 = (c - a).norm(), r1 = (c - b).norm();
  if (!(r0 > 1e-9 * len && r1 > 1e-9 * len)) return true;
  return !(std::abs(cross(Vec2((c - a) / r0), Vec2((c - b) / r1))) > kOnLine);
}

}  // namespace linkage
