// A watched clearance and a timing window's end as targets (linkage/optimize.h): their values
// and exact derivatives come from linkage/clearance_sensitivity.h and window_sensitivity.h (the
// envelope theorem at the closest approach, the implicit function theorem at a window's end).
#include <cmath>

#include "linkage/clearance_sensitivity.h"
#include "linkage/window_sensitivity.h"
#include "optimize/variables.h"

namespace linkage::opt {

namespace {

// Adds weight * r^2 and its gradient 2 weight r dr/dp (dr the residual's per dimension).
void addSquare(const Variables& vars, double weight, double r, const std::vector<double>& dr,
               Evaluation& e) {
  e.objective += weight * r * r;
  for (size_t v = 0; v < e.gradient.size(); ++v)
    if (vars.dim[v] >= 0 && static_cast<size_t>(vars.dim[v]) < dr.size())
      e.gradient[v] += 2 * weight * r * dr[vars.dim[v]];
}

}  // namespace

Status clearanceResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                          const Variables& vars, bool withGradient, Evaluation& e) {
  const OptTarget& t = spec.targets[target];
  const std::vector<ClearanceWatch>& watches = k.mechanism().timing.clearances;
  if (t.index >= watches.size()) return Status::badModel("no such clearance");
  const ClearanceSensitivity cs = clearanceSensitivity(
      k, watches[t.index], withGradient ? vars.dims : std::vector<Dimension>{});
  if (!cs.status.ok()) return cs.status;
  const double least = cs.clearance.closest.distance, r = std::max(0.0, t.gapMm - least);
  e.measures[target] = {least, cs.clearance.closest.crankDeg};
  std::vector<double> dr;
  for (double d : cs.derivative) dr.push_back(-d);
  addSquare(vars, t.weight, r, dr, e);
  return Status::success();
}

Status windowResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                       const Variables& vars, bool withGradient, Evaluation& e) {
  const OptTarget& t = spec.targets[target];
  const WindowSensitivity ws =
      windowSensitivity(k, t.window, withGradient ? vars.dims : std::vector<Dimension>{});
  if (!ws.status.ok()) return ws.status;
  if (ws.intervals.empty())
    return Status::failure(StatusCode::NotConverged,
                           "window \"" + t.window + "\" never opens in this design");
  const WindowEndSensitivity& first = ws.intervals.front();
  const double deg = t.windowEnd ? first.toDeg : first.fromDeg;
  const double r = std::remainder(deg - t.crankDeg, 360.0);
  e.measures[target] = {std::fmod(deg + 360, 360)};
  addSquare(vars, t.weight, r, t.windowEnd ? first.dTo : first.dFrom, e);
  return Status::success();
}

}  // namespace linkage::opt
