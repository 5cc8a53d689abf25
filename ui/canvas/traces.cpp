#include "canvas/traces.h"

#include <algorithm>
#include <cmath>

namespace linkage::ui {

namespace {

// Calls visit(k) at the current pose and every stepDeg over a revolution, or, for a crank
// that cannot turn fully, out to both limit positions; on copies of k.
template <class Visit>
void sweep(const Kinematics& k, double stepDeg, Visit visit) {
  Kinematics fwd = k;
  fwd.setAccelerations(false);
  const double start = k.crankDeg();
  visit(fwd, false);
  const int steps = static_cast<int>(std::ceil(360.0 / stepDeg));
  bool stopped = false;
  for (int s = 1; s <= steps && !stopped; ++s) {
    stopped = !fwd.moveTo(start + s * stepDeg).ok();
    visit(fwd, false);  // where it stopped, if it did: the limit position
  }
  if (!stopped) return;
  Kinematics back = k;
  back.setAccelerations(false);
  for (int s = 1; s <= steps; ++s) {
    const bool ok = back.moveTo(start - s * stepDeg).ok();
    visit(back, true);
    if (!ok) break;
  }
}

}  // namespace

std::pair<Vec2, Vec2> motionExtent(const Kinematics& k, const PlaneView& view, double stepDeg) {
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  if (!k.valid()) return {Vec2::Zero(), Vec2::Zero()};
  const Mechanism& m = k.mechanism();
  auto add = [&](const Vec2& p) {
    if (!p.allFinite()) return;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  // A body free with the crank held goes where the solver's hold puts it, which is no motion:
  // only where it is drawn now counts (its sweep wandered metres off with a pin deleted).
  const std::vector<BodyId> free = k.structure().freeBodies;
  auto isFree = [&](BodyId b) { return std::find(free.begin(), free.end(), b) != free.end(); };
  auto visit = [&](const Kinematics& c, bool moving) {
    for (const Point& p : m.points)
      if (moving != isFree(p.body)) add(view.point(c, p.id));
    for (const Slot& s : m.slots) {
      if (moving == isFree(s.body)) continue;
      const Kinematics::Segment e = view.slotEnds(c, s.id);
      add(e.p0);
      add(e.p1);
    }
  };
  visit(k, false);
  sweep(k, stepDeg, [&](const Kinematics& c, bool) { visit(c, true); });
  if (!lo.allFinite()) return {Vec2::Zero(), Vec2::Zero()};
  return {lo, hi};
}

std::vector<std::vector<Vec2>> tracePaths(const Kinematics& k, const PlaneView& view,
                                          double stepDeg) {
  const Mechanism& m = k.mechanism();
  std::vector<std::vector<Vec2>> paths(m.outputs.size());
  if (!k.valid() || m.outputs.empty()) return paths;
  // Forward samples in order; the other way (a crank that stops) gathered separately and put
  // in front, reversed, so each path runs from one limit to the other.
  std::vector<std::vector<Vec2>> before(m.outputs.size());
  sweep(k, stepDeg, [&](const Kinematics& c, bool back) {
    for (size_t i = 0; i < m.outputs.size(); ++i)
      (back ? before : paths)[i].push_back(view.point(c, m.outputs[i]));
  });
  for (size_t i = 0; i < paths.size(); ++i) {
    std::reverse(before[i].begin(), before[i].end());
    before[i].insert(before[i].end(), paths[i].begin(), paths[i].end());
    paths[i] = std::move(before[i]);
  }
  return paths;
}

}  // namespace linkage::ui
