// Tolerances (linkage/tolerance.h), issue 29's speed targets on the Wanzer needle bar
// (wanzer-inversion-2, needlebar.G), every dimension toleranced (0.02 mm, 0.05 degrees):
// - 10^5 Monte Carlo samples of its stroke, each solved exactly over a turn and its stroke
//   narrowed from its limit positions, on two threads: under 5 s;
// - the first-order band of every dimension at 360 crank angles: under 50 ms.
//   build/bench/linkage_bench --benchmark_filter=tolerance/
#include <benchmark/benchmark.h>

#include "bench_common.h"
#include "linkage/sensitivity.h"
#include "linkage/tolerance.h"

namespace {

using namespace linkage;

ToleranceSpec wanzerSpec(const Mechanism& m) {
  ToleranceSpec spec;
  spec.point = *m.findPoint("needlebar.G");
  for (const Dimension& d : dimensions(m))
    spec.tolerances.push_back({d.name, d.unit == Dimension::Unit::Deg ? 0.05 : 0.02, false});
  return spec;
}

void monteCarloStroke(benchmark::State& state) {
  const Mechanism m = bench::example("wanzer-inversion-2");
  ToleranceSpec spec = wanzerSpec(m);
  spec.samples = static_cast<int>(state.range(0));
  spec.threads = 2;
  spec.band = false;
  for (auto _ : state) {
    const ToleranceResult r = tolerances(m, spec);
    if (r.used != spec.samples) state.SkipWithError(r.firstFailure.c_str());
    benchmark::DoNotOptimize(r.stroke.sd);
  }
  state.counters["samples_per_s"] =
      benchmark::Counter(static_cast<double>(spec.samples), benchmark::Counter::kIsRate);
}
BENCHMARK(monteCarloStroke)
    ->Name("tolerance/wanzer_stroke_monte_carlo_2_threads")
    ->Arg(100000)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void firstOrderBand(benchmark::State& state) {
  const Mechanism m = bench::example("wanzer-inversion-2");
  ToleranceSpec spec = wanzerSpec(m);
  spec.steps = 360;
  spec.stroke = false;
  for (auto _ : state) benchmark::DoNotOptimize(tolerances(m, spec).rows.back().worst);
}
BENCHMARK(firstOrderBand)
    ->Name("tolerance/wanzer_first_order_band_360_angles")
    ->Unit(benchmark::kMillisecond);

}  // namespace
