// A timing window's ends differentiated with respect to the dimensions (issue 29: "the
// derivative of ... a window's ends"), exactly: an end is a crank angle phi_e where the output
// y(phi, p) crosses the window's level, so by the implicit function theorem
//   d(phi_e)/dp = -(dy/dp) / (dy/dphi)
// at that pose: for a point along u, u . dr/dp over u . dr/dphi (linkage/sensitivity.h, the
// velocity solve); for a body's angle, its dtheta/dp over its rate; for the distance between two
// points, e . (dP/dp - dQ/dp) over e . (P' - Q'), e along P - Q. Degrees of crank per unit of the
// dimension. On a machine in space a point's position and a distance are the world's (the
// window's direction with its dz; Sensitivity::Space::World), a body's angle in its plane.
#pragma once

#include <string>
#include <vector>

#include "linkage/sensitivity.h"
#include "linkage/timing.h"

namespace linkage {

struct WindowEndSensitivity {
  double fromDeg = 0, toDeg = 0;   // the interval
  std::vector<double> dFrom, dTo;  // degrees of crank per unit of dimension k
};

struct WindowSensitivity {
  Status status;
  std::vector<Dimension> dims;
  std::vector<WindowEndSensitivity> intervals;  // the window's, in order of their start
};

// The window of the document's timing named `name`.
WindowSensitivity windowSensitivity(const Kinematics& k, const std::string& name,
                                    std::vector<Dimension> dims);

}  // namespace linkage
