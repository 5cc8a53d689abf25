#include "analysis/angle_intervals.h"

#include <algorithm>

namespace linkage {

namespace {

constexpr double kTouch = 1e-12;  // degrees: intervals closer than this touch

std::vector<AngleInterval> joinAcrossZero(std::vector<AngleInterval> v, bool periodic) {
  if (periodic && v.size() >= 2 && v.front().fromDeg <= kTouch && v.back().toDeg >= 360 - kTouch) {
    v.back().toDeg = 360 + v.front().toDeg;
    v.erase(v.begin());
  }
  return v;
}

// Pieces within [0, 360], in order.
std::vector<AngleInterval> unwrapped(const std::vector<AngleInterval>& v) {
  std::vector<AngleInterval> out;
  for (const AngleInterval& i : v) {
    if (i.toDeg > 360) {
      out.push_back({i.fromDeg, 360});
      out.push_back({0, i.toDeg - 360});
    } else {
      out.push_back(i);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const AngleInterval& a, const AngleInterval& b) { return a.fromDeg < b.fromDeg; });
  return out;
}

}  // namespace

std::vector<AngleInterval> intervalsOf(bool holdsAtStart, const std::vector<double>& toggles,
                                       bool periodic) {
  std::vector<AngleInterval> out;
  bool holds = holdsAtStart;
  double start = 0;
  for (double t : toggles) {
    if (!(t > 0 && t < 360)) continue;
    if (holds && t - start > kTouch) out.push_back({start, t});
    start = t;
    holds = !holds;
  }
  if (holds && 360 - start > kTouch) out.push_back({start, 360});
  return joinAcrossZero(out, periodic);
}

std::vector<AngleInterval> overlapOf(const std::vector<AngleInterval>& a,
                                     const std::vector<AngleInterval>& b, bool periodic) {
  const std::vector<AngleInterval> x = unwrapped(a), y = unwrapped(b);
  std::vector<AngleInterval> out;
  for (const AngleInterval& i : x)
    for (const AngleInterval& j : y) {
      const double from = std::max(i.fromDeg, j.fromDeg), to = std::min(i.toDeg, j.toDeg);
      if (to - from > kTouch) out.push_back({from, to});
    }
  std::sort(out.begin(), out.end(),
            [](const AngleInterval& p, const AngleInterval& q) { return p.fromDeg < q.fromDeg; });
  // Pieces that touch (a wrapping interval was split at 360) are one.
  std::vector<AngleInterval> merged;
  for (const AngleInterval& i : out) {
    if (!merged.empty() && i.fromDeg - merged.back().toDeg <= kTouch)
      merged.back().toDeg = std::max(merged.back().toDeg, i.toDeg);
    else
      merged.push_back(i);
  }
  return joinAcrossZero(merged, periodic);
}

}  // namespace linkage
