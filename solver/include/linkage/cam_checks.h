// A cam's checks (../shared/specs/model-format.md, "Cams") on its geometry and profile
// (linkage/cam_geometry.h): the extremes over the turn found by Brent's method on the exact
// functions, from a fixed grid of each segment (64 intervals: the laws' pieces at eighths are
// grid points), so they do not depend on how many profile points are asked for; and the
// dimensions found for them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/cam_geometry.h"

namespace linkage::cam {

struct CamExtreme {
  bool found = false;
  double value = 0, atDeg = 0;  // at the smallest cam angle that reaches it
};

struct CamChecks {
  CamExtreme pressureMax;       // degrees, magnitude (roller, knife)
  CamExtreme pitchRadiusMin;    // the pitch curve's smallest convex radius (roller, knife)
  CamExtreme surfaceRadiusMin;  // flat face: the surface's smallest radius (negative: not convex)
  bool undercut = false;
  std::string undercutWhy;  // where and why, "" without
};
CamChecks camChecks(const CamGeometry& g);

// Dimensions found for the checks (the editor's "find" buttons), each exact to 1e-9 mm:
// - the smallest base radius whose largest pressure angle is at most limitDeg (30 translating,
//   35 oscillating, by custom), the roller and the motion kept; an oscillating follower keeps
//   its pivot and arm, its point moving round the arm's circle. The first base of a scan that
//   meets the limit, then bisection on the exact checks; nullopt when none does (a translating
//   follower: none up to a million mm), or for a flat face (no pressure angle).
// - the largest roller that does not undercut with the pitch curve kept (base + roller
//   fixed): the pitch curve's smallest convex radius; nullopt for a flat face.
std::optional<double> smallestBaseFor(const CamGeometry& g, double limitDeg);
std::optional<double> largestRoller(const CamGeometry& g);
// g with another base radius (as smallestBaseFor moves it).
CamGeometry withBase(const CamGeometry& g, double baseMm);

}  // namespace linkage::cam
