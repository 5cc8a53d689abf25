// The cycle diagram: see linkage/timing.h.
#include "linkage/timing.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/angle_intervals.h"
#include "analysis/measure_track.h"

namespace linkage {

bool CycleDiagram::anyConflict() const {
  return std::any_of(conflicts.begin(), conflicts.end(),
                     [](const Conflict& c) { return !c.overlaps.empty(); });
}

namespace {

double onCycle(double deg, bool periodic) {
  return periodic && deg >= 360 ? deg - 360 : deg;
}

// The row's track: extremes, its windows' levels, the dwell threshold (once the samples say
// the range).
CycleTrack trackOf(const Kinematics& k, const CycleOutput& o, const std::vector<double>& levels,
                   const CycleOptions& opt) {
  CycleTrack t;
  const LimitMeasure w = o.measure.unit();
  t.quantity = [w](const Kinematics& at) { return readMeasure(at, w); };
  t.extremes = true;
  t.levels = levels;
  t.noise = w.body ? 1e-12 : 1e-12 * k.size() * M_PI / 180;
  const double speed = opt.dwellSpeed;
  t.onSampled = [speed](CycleTrack& s) {
    double lo = s.samples.front().value, hi = lo;
    for (const CycleReading& r : s.samples) lo = std::min(lo, r.value), hi = std::max(hi, r.value);
    const double threshold = speed > 0 ? speed : 1e-4 * (hi - lo);
    if (threshold > 0) s.slopeLevels = {threshold};
  };
  return t;
}

CycleRow rowOf(const CycleOutput& o, const CycleTrack& t, const CycleSweep& sweep,
               const CycleOptions& opt) {
  CycleRow r;
  r.output = o;
  r.periodic = t.periodic;
  r.crankDeg = sweep.crank;
  for (const CycleReading& s : t.samples) r.value.push_back(s.value);
  r.min = r.max = r.value.front();
  if (!t.periodic) {
    r.min = std::min(r.min, r.value.back());
    r.max = std::max(r.max, r.value.back());
  }
  for (const Root& x : t.stationary) {
    r.extremes.push_back({!x.rising, onCycle(x.crankDeg, t.periodic), x.value});
    r.min = std::min(r.min, x.value);
    r.max = std::max(r.max, x.value);
  }
  std::sort(r.extremes.begin(), r.extremes.end(),
            [](const LocalExtreme& a, const LocalExtreme& b) { return a.crankDeg < b.crankDeg; });
  for (double v : r.value)
    r.normalised.push_back(r.max > r.min ? (v - r.min) / (r.max - r.min) : 0.0);
  for (size_t i = 0; i < t.levels.size(); ++i)
    for (const Root& x : t.crossings[i])
      r.crossings.push_back({onCycle(x.crankDeg, t.periodic), t.levels[i], x.rising});
  std::sort(r.crossings.begin(), r.crossings.end(),
            [](const Crossing& a, const Crossing& b) { return a.crankDeg < b.crankDeg; });
  if (!t.slopeLevels.empty()) {
    std::vector<double> toggles;
    for (const Root& x : t.slopeCrossings.front()) toggles.push_back(x.crankDeg);
    const bool slow = std::abs(t.samples.front().d1) < t.slopeLevels.front();
    for (const AngleInterval& i : intervalsOf(slow, toggles, t.periodic))
      if (i.toDeg - i.fromDeg >= opt.dwellMinDeg) r.dwells.push_back(i);
  }
  return r;
}

WindowIntervals windowOf(const CycleWindow& w, const CycleTrack& t) {
  const size_t level = std::find(t.levels.begin(), t.levels.end(), w.level) - t.levels.begin();
  std::vector<double> toggles;
  for (const Root& x : t.crossings[level]) toggles.push_back(x.crankDeg);
  const CycleReading& s = t.samples.front();
  // Where the value starts exactly at the level, the side it moves to decides (at a dead
  // centre on the level, the side it turns back to).
  const double g = s.value != w.level ? s.value - w.level : std::abs(s.d1) > t.noise ? s.d1 : s.d2;
  const bool holds = w.below ? g < 0 : g > 0;
  return {w.name, intervalsOf(holds, toggles, t.periodic)};
}

Status checkNames(const std::vector<CycleWindow>& windows,
                  const std::vector<std::pair<std::string, std::string>>& conflicts) {
  std::map<std::string, int> seen;
  for (const CycleWindow& w : windows)
    if (seen[w.name]++) return Status::badModel("window " + w.name + " is given twice");
  for (const auto& [a, b] : conflicts) {
    for (const std::string& n : {a, b})
      if (!seen.count(n))
        return Status::badModel("conflict " + a + "," + b + ": no window named " + n);
    if (a == b)
      return Status::badModel("conflict " + a + "," + b + ": a window cannot conflict with itself");
  }
  return Status::success();
}

}  // namespace

CycleDiagram cycleDiagram(const Kinematics& k, const std::vector<CycleOutput>& outputs,
                          const std::vector<CycleWindow>& windows,
                          const std::vector<std::pair<std::string, std::string>>& conflicts,
                          const CycleOptions& opt) {
  CycleDiagram out;
  if (!k.valid()) {
    out.status = Status::badModel("no mechanism is loaded");
    return out;
  }
  if (out.status = checkNames(windows, conflicts); !out.status.ok()) return out;
  // The rows: every output once, first use first, with its windows' levels.
  std::vector<CycleOutput> rows;
  std::vector<std::vector<double>> levels;
  std::map<std::string, size_t> rowOfName;
  auto row = [&](const CycleOutput& o) {
    auto [it, added] = rowOfName.emplace(o.name, rows.size());
    if (added) rows.push_back(o), levels.emplace_back();
    return it->second;
  };
  for (const CycleOutput& o : outputs) row(o);
  for (const CycleWindow& w : windows) {
    std::vector<double>& l = levels[row(w.output)];
    if (std::find(l.begin(), l.end(), w.level) == l.end()) l.push_back(w.level);
  }
  for (const CycleOutput& o : rows)
    if (Status s = checkMeasure(k, o.measure); !s.ok()) {
      out.status = s;
      out.status.message = o.name + ": " + s.message;
      return out;
    }
  std::vector<CycleTrack> tracks;
  for (size_t i = 0; i < rows.size(); ++i) tracks.push_back(trackOf(k, rows[i], levels[i], opt));
  std::vector<CycleTrack*> ptrs;
  for (CycleTrack& t : tracks) ptrs.push_back(&t);
  const CycleSweep sweep = sweepCycle(k, ptrs, opt.steps);
  if (out.status = sweep.status; !out.status.ok()) return out;
  for (size_t i = 0; i < rows.size(); ++i)
    out.rows.push_back(rowOf(rows[i], tracks[i], sweep, opt));
  std::map<std::string, size_t> windowIndex;
  for (const CycleWindow& w : windows) {
    windowIndex[w.name] = out.windows.size();
    out.windows.push_back(windowOf(w, tracks[rowOfName[w.output.name]]));
  }
  for (const auto& [a, b] : conflicts) {
    const size_t i = windowIndex[a], j = windowIndex[b];
    const bool periodic = tracks[rowOfName[windows[i].output.name]].periodic &&
                          tracks[rowOfName[windows[j].output.name]].periodic;
    out.conflicts.push_back(
        {a, b, overlapOf(out.windows[i].intervals, out.windows[j].intervals, periodic)});
  }
  return out;
}

}  // namespace linkage
