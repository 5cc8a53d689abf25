// The motion table of the spec (../shared/specs/model-format.md): header, then one row per crank
// angle with t, crank angle and x, y, vx, vy, ax, ay of each point (x, y, z, vx, vy, vz, ax, ay,
// az in the world for a model with planes: linkage/space.h). Shared by every front end.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

struct MotionTableSpec {
  std::vector<PointId> points;
  long long steps = 360;  // per revolution
  double revs = 1;
  double rpm = 0;  // 0: the mechanism's own
};

std::string motionTableHeader(const Mechanism& m, const std::vector<PointId>& points);

// One row at the kinematics' current position; t_s = crank angle / (6 rpm).
std::string motionTableRow(const Kinematics& k, double crankDeg,
                           const std::vector<PointId>& points);

// Number of rows for a sweep: steps * revs + 1, or -1 when steps * revs is not whole.
long long motionTableRows(const MotionTableSpec& spec);

// Moves k through the sweep and hands every row (header first) to `sink`. Stops at the first
// angle that fails, returning its status; the rows before it have been handed over.
Status sweepMotionTable(Kinematics& k, const MotionTableSpec& spec,
                        const std::function<void(const std::string&)>& sink);

}  // namespace linkage
