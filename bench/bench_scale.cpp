// How a step's cost grows with the mechanism: chains of four-bars (each rocker drives the next
// loop) from 11 to 501 bodies, by the closed-form group solve (linear in the number of bodies)
// and by the general Newton solve on all coordinates (sparse LU from 64 coordinates; the
// `_dense` variants force the dense LU and the dense structure analysis, as before, to compare);
// chains of triads, which do not decompose into groups, by the general solve; and loading.
#include <benchmark/benchmark.h>

#include <climits>

#include "kinematics/kinematics_state.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace {

using namespace linkage;

KinematicsOptions options(bool closedForm, bool dense) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  if (dense) opt.sparseFrom = INT_MAX;
  return opt;
}

void step(benchmark::State& state, const Mechanism& m, const KinematicsOptions& opt, bool groups) {
  Kinematics k(opt);
  if (!k.load(m).ok() || k.closedForm() != groups) {
    state.SkipWithError("cannot load the mechanism, or not by the solve asked for");
    return;
  }
  const PointId out = m.outputs[0];
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) {
      state.SkipWithError("the mechanism stopped");
      return;
    }
    benchmark::DoNotOptimize(k.acceleration(out));
  }
  const double bodies =
      linkage::internal::system(k).nBodies;  // moving ones, as in docs/benchmarks.md
  state.SetItemsProcessed(state.iterations());
  state.counters["bodies"] = bodies;
  state.counters["ns_per_body"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * bodies,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void chainStep(benchmark::State& state, bool closedForm, bool dense) {
  step(state, test::fourBarChain(static_cast<int>(state.range(0))), options(closedForm, dense),
       closedForm);
}

void triadStep(benchmark::State& state, bool dense) {
  // Groups allowed: the triads do not decompose, so the general solve is what runs.
  step(state, test::triadChain(static_cast<int>(state.range(0))), options(true, dense), false);
}

void chainLoad(benchmark::State& state, bool dense) {
  const Mechanism m = test::fourBarChain(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Kinematics k(options(true, dense));
    benchmark::DoNotOptimize(k.load(m).ok());
  }
  state.counters["bodies"] = 1 + 2 * static_cast<double>(state.range(0));
}

BENCHMARK_CAPTURE(chainStep, closed_form, true, false)
    ->Name("scale/step_closed_form")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Arg(250)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(chainStep, general, false, false)
    ->Name("scale/step_general")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Arg(250)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(chainStep, general_dense, false, true)
    ->Name("scale/step_general_dense")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMicrosecond);
// 1 + 4 units bodies: 21, 101, 249, 501.
BENCHMARK_CAPTURE(triadStep, sparse, false)
    ->Name("scale/step_triads")
    ->Arg(5)
    ->Arg(25)
    ->Arg(62)
    ->Arg(125)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(triadStep, dense, true)
    ->Name("scale/step_triads_dense")
    ->Arg(5)
    ->Arg(25)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(chainLoad, sparse, false)
    ->Name("scale/load")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Arg(250)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(chainLoad, dense, true)
    ->Name("scale/load_dense")
    ->Arg(5)
    ->Arg(25)
    ->Arg(50)
    ->Arg(125)
    ->Unit(benchmark::kMillisecond);

}  // namespace
