// How a step's cost grows with the mechanism: chains of four-bars (each rocker drives the next
// loop) from 11 to 501 bodies, by the closed-form group solve (linear in the number of bodies)
// and by the general Newton solve on all coordinates (dense LU: cubic), which stops at 101.
#include <benchmark/benchmark.h>

#include "kinematics.h"
#include "mechanisms.h"

namespace {

using namespace linkage;

void chainStep(benchmark::State& state, bool closedForm) {
  const int loops = static_cast<int>(state.range(0));
  const Mechanism m = test::fourBarChain(loops);
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  if (!k.load(m).ok() || k.closedForm() != closedForm) {
    state.SkipWithError("cannot load the chain");
    return;
  }
  const PointId out = m.outputs[0];
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) {
      state.SkipWithError("the chain stopped");
      return;
    }
    benchmark::DoNotOptimize(k.acceleration(out));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["bodies"] = 1 + 2 * loops;
  state.counters["ns_per_body"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * (1 + 2 * loops),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void chainLoad(benchmark::State& state) {
  const Mechanism m = test::fourBarChain(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Kinematics k;
    benchmark::DoNotOptimize(k.load(m).ok());
  }
  state.counters["bodies"] = 1 + 2 * static_cast<double>(state.range(0));
}

BENCHMARK_CAPTURE(chainStep, closed_form, true)
    ->Name("scale/step_closed_form")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Arg(250)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(chainStep, general, false)
    ->Name("scale/step_general")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(chainLoad)
    ->Name("scale/load")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Unit(benchmark::kMillisecond);

}  // namespace
