// Instant-centre sets per second: all n(n-1)/2 centres of a mechanism at one position (primary
// centres, Kennedy's circle-diagram passes, the velocity-derived centres and the cross-check),
// over 360 solved positions one degree apart, next to step/<name> of bench_kinematics.cpp; and a
// kinematic step followed by its centres.
//   build/bench/linkage_bench --benchmark_filter=wanzer --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_common.h"
#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"

namespace {

using namespace linkage;

using bench::example;

void centreSets(benchmark::State& state, const std::string& name) {
  Kinematics k;
  if (!k.load(example(name)).ok()) std::abort();
  std::vector<Kinematics> poses;
  poses.reserve(360);
  for (int deg = 0; deg < 360; ++deg) {
    if (!k.moveTo(deg).ok()) std::abort();
    poses.push_back(k);
  }
  InstantCentreSolver solver;
  if (!solver.prepare(k).ok()) std::abort();
  size_t i = 0;
  for (auto _ : state) {
    const InstantCentres& ics = solver.compute(poses[i]);
    benchmark::DoNotOptimize(ics.centres.back().h.x());
    if (++i == poses.size()) i = 0;
  }
  if (!solver.result().disagreements.empty()) state.SkipWithError("centres disagree");
  state.SetItemsProcessed(state.iterations());
  state.counters["centres"] = static_cast<double>(solver.result().centres.size());
}

void stepThenCentres(benchmark::State& state, const std::string& name) {
  Kinematics k;
  if (!k.load(example(name)).ok()) std::abort();
  InstantCentreSolver solver;
  if (!solver.prepare(k).ok()) std::abort();
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) std::abort();
    benchmark::DoNotOptimize(solver.compute(k).centres.back().h.x());
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK_CAPTURE(centreSets, wanzer, std::string("wanzer-inversion-2"))->Name("ics/wanzer");
BENCHMARK_CAPTURE(centreSets, four_bar, std::string("four-bar-crank-rocker"))->Name("ics/four_bar");
BENCHMARK_CAPTURE(stepThenCentres, wanzer, std::string("wanzer-inversion-2"))
    ->Name("step_and_ics/wanzer");

}  // namespace
