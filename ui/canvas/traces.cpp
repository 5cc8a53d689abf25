#include "canvas/traces.h"

#include <algorithm>
#include <cmath>

namespace linkage::ui {

std::vector<std::vector<Vec2>> tracePaths(const Kinematics& k, double stepDeg) {
  const Mechanism& m = k.mechanism();
  std::vector<std::vector<Vec2>> paths(m.outputs.size());
  if (!k.valid() || m.outputs.empty()) return paths;
  auto sample = [&](Kinematics& c, std::vector<std::vector<Vec2>>& out) {
    for (size_t i = 0; i < m.outputs.size(); ++i) out[i].push_back(c.position(m.outputs[i]));
  };
  Kinematics fwd = k;
  fwd.setAccelerations(false);
  const double start = k.crankDeg();
  sample(fwd, paths);
  const int steps = static_cast<int>(std::ceil(360.0 / stepDeg));
  bool stopped = false;
  for (int s = 1; s <= steps && !stopped; ++s) {
    stopped = !fwd.moveTo(start + s * stepDeg).ok();
    sample(fwd, paths);  // where it stopped, if it did: the limit position
  }
  if (!stopped) return paths;
  // It cannot turn fully: the other way from the start, to the other limit, in front.
  Kinematics back = k;
  back.setAccelerations(false);
  std::vector<std::vector<Vec2>> before(m.outputs.size());
  for (int s = 1; s <= steps; ++s) {
    const bool ok = back.moveTo(start - s * stepDeg).ok();
    sample(back, before);
    if (!ok) break;
  }
  for (size_t i = 0; i < paths.size(); ++i) {
    std::reverse(before[i].begin(), before[i].end());
    before[i].insert(before[i].end(), paths[i].begin(), paths[i].end());
    paths[i] = std::move(before[i]);
  }
  return paths;
}

}  // namespace linkage::ui
