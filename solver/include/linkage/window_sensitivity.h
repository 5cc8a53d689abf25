// A timing window's ends differentiated with respect to the dimensions (issue 29: "the
// derivative of ... a window's ends"), exactly: an end is a crank angle phi_e where the output
// u . r(phi) crosses the window's level, so by the implicit function theorem
//   d(phi_e)/dp = -(u . dr/dp) / (u . dr/dphi)
// at that pose, dr/dp from linkage/sensitivity.h and dr/dphi the point's velocity per unit of
// crank (the velocity solve), in degrees of crank per unit of the dimension. Windows on a
// point's position; a body's angle or a distance between points, not yet (said).
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
