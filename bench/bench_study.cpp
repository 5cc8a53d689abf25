// The parameter study of seed 001: 1,000 variants of the eight-link 876-class needle mechanism
// (its pivot F moved on its arc, alpha from 0 to 35 degrees), each loaded afresh and swept at
// 360 steps a turn, with the needle's exact extremes and the three transmission angles' exact
// extremes found by root finding; on 1 thread and on every core. Beside it, the parts of one
// variant: the load, the 360-step sweep alone, and a design check on one (limits).
//   build/bench/linkage_bench --benchmark_filter=study --benchmark_min_time=1
// Results: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <thread>

#include "bench_common.h"
#include "linkage/limits.h"
#include "linkage/study.h"
#include "linkage/transmission.h"

namespace {

using namespace linkage;

StudySpec needleStudy(const Mechanism& m, int values, int threads) {
  StudySpec s;
  s.move.point = *m.findPoint("ground.F");
  s.move.kind = PointMove::Kind::Arc;
  s.move.centre = m.point(*m.findPoint("rocker.E"))->pos;
  s.move.angleDeg = -1;  // t is alpha in degrees: clockwise about E
  s.from = 0;
  s.to = 35;
  s.values = values;
  s.point = *m.findPoint("needlebar.G");
  s.threads = threads;
  return s;
}

void study(benchmark::State& state) {
  const Mechanism m = bench::example("needle-876-alpha-0");
  const int threads = static_cast<int>(state.range(0));
  const StudySpec spec = needleStudy(m, 1000, threads);
  for (auto _ : state) {
    const Study s = runStudy(m, spec);
    if (!s.status.ok() || s.rows.size() != 1000 || !s.rows.back().turns) std::abort();
    benchmark::DoNotOptimize(s.rows.back().point.stroke);
  }
  state.SetItemsProcessed(state.iterations() * 1000);  // variants
  state.counters["threads"] = threads;
}
BENCHMARK(study)
    ->Name("study/needle876_1000_variants")
    ->Arg(1)
    ->Arg(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void load(benchmark::State& state) {
  const Mechanism m = bench::example("needle-876-alpha-0");
  for (auto _ : state) {
    Kinematics k;
    if (!k.load(m).ok()) std::abort();
    benchmark::DoNotOptimize(k.q());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(load)->Name("study/part/load")->Unit(benchmark::kMicrosecond);

void sweep(benchmark::State& state) {
  const Mechanism m = bench::example("needle-876-alpha-0");
  const PointId G = *m.findPoint("needlebar.G");
  Kinematics k0;
  if (!k0.load(m).ok()) std::abort();
  for (auto _ : state) {
    Kinematics k = k0;
    for (int i = 0; i <= 360; ++i) {
      if (!k.moveTo(i).ok()) std::abort();
      benchmark::DoNotOptimize(k.motion(G));
    }
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(sweep)->Name("study/part/sweep_360_steps")->Unit(benchmark::kMicrosecond);

void limits(benchmark::State& state) {
  const Mechanism m = bench::example("needle-876-alpha-0");
  Kinematics k;
  if (!k.load(m).ok()) std::abort();
  const LimitMeasure what = LimitMeasure::along(*m.findPoint("needlebar.G"), Vec2(0, 1));
  for (auto _ : state) {
    const Limits l = findLimits(k, what);
    if (!l.status.ok()) std::abort();
    benchmark::DoNotOptimize(l.stroke);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(limits)->Name("study/part/limits_360_steps")->Unit(benchmark::kMicrosecond);

void transmission(benchmark::State& state) {
  const Mechanism m = bench::example("needle-876-alpha-0");
  Kinematics k;
  if (!k.load(m).ok()) std::abort();
  for (auto _ : state) {
    const TransmissionSweep s = sweepTransmission(k);
    if (!s.status.ok()) std::abort();
    benchmark::DoNotOptimize(s.summaries.back().min);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(transmission)->Name("study/part/transmission_360_steps")->Unit(benchmark::kMicrosecond);

}  // namespace
