// A cam's profile and its checks (linkage/cam_checks.h): 3,600 profile points with the checks
// (issue 28: under 5 ms), the checks alone, and the profile alone, for an offset translating
// roller follower and an oscillating one.
//   build/bench/linkage_bench --benchmark_filter=cam/
#include <benchmark/benchmark.h>

#include <cmath>

#include "linkage/cam_checks.h"

namespace {

using namespace linkage;
using namespace linkage::cam;

CamGeometry geometry(bool oscillating) {
  CamGeometry g;
  g.baseMm = 30;
  g.rollerMm = 8;
  const double scale = oscillating ? M_PI / 180 : 1;
  g.program = Program({{90, 10, Law::Cycloidal},
                       {150, 0, std::nullopt},
                       {270, -10, Law::ModifiedSine},
                       {360, 0, std::nullopt}},
                      scale);
  if (oscillating) {
    g.motion = FollowerMotion::Oscillating;
    g.pivot = Vec2(60, 10);
    g.b0 = Vec2(0, 38);
    g.sigma = g.b0.dot(perp(g.b0 - g.pivot)) > 0 ? 1 : -1;
  } else {
    g.offsetMm = 6;
  }
  return g;
}

void profileAndChecks(benchmark::State& state, bool oscillating, bool points, bool check) {
  const CamGeometry g = geometry(oscillating);
  for (auto _ : state) {
    if (points) benchmark::DoNotOptimize(camPoints(g, 3600).back().radiusMm);
    if (check) benchmark::DoNotOptimize(camChecks(g).pressureMax.value);
  }
}

BENCHMARK_CAPTURE(profileAndChecks, translating, false, true, true)
    ->Name("cam/profile_3600_and_checks/translating")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(profileAndChecks, oscillating, true, true, true)
    ->Name("cam/profile_3600_and_checks/oscillating")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(profileAndChecks, checks, false, false, true)
    ->Name("cam/checks/translating")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(profileAndChecks, points, false, true, false)
    ->Name("cam/profile_3600/translating")
    ->Unit(benchmark::kMillisecond);

}  // namespace
