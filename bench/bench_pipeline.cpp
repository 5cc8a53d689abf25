// What the evaluation pipeline saves by not repeating work, on chains of four-bars:
//   edit_in_place  an edit of one body's dimensions (the last rocker's arm, alternately moved
//                  and moved back) re-solves only the groups it touches (Kinematics::edit);
//   edit_whole     the same change handled as a new mechanism: load (structure analysis,
//                  assembly, plan) and turn the crank to the same angle;
//   step_moved     for comparison, one closed-form step of the whole chain.
//   build/bench/linkage_bench --benchmark_filter=pipeline
#include <benchmark/benchmark.h>

#include "linkage/kinematics.h"
#include "mechanisms.h"

namespace {

using namespace linkage;

constexpr double kAngle = 40;

Mechanism moved(const Mechanism& m, int loops, double dx) {
  Mechanism e = m;
  const Body* rocker = e.bodyNamed("rocker" + std::to_string(loops - 1));
  e.point(e.pointNamed(rocker->id, "A")->id)->pos += Vec2(dx, 0);
  return e;
}

void editInPlace(benchmark::State& state) {
  const int loops = static_cast<int>(state.range(0));
  const Mechanism m = test::fourBarChain(loops), e = moved(m, loops, 0.5);
  Kinematics k;
  if (!k.load(m).ok() || !k.moveTo(kAngle).ok()) return state.SkipWithError("cannot load");
  bool flip = false;
  for (auto _ : state) {
    flip = !flip;
    if (!k.edit(flip ? e : m).ok() || k.lastEditGroups() != 1)
      return state.SkipWithError("the edit was not solved in place");
    benchmark::DoNotOptimize(k.acceleration(m.outputs[0]));
  }
  state.counters["bodies"] = 1 + 2 * loops;
}

void editWhole(benchmark::State& state) {
  const int loops = static_cast<int>(state.range(0));
  const Mechanism m = test::fourBarChain(loops), e = moved(m, loops, 0.5);
  bool flip = false;
  for (auto _ : state) {
    flip = !flip;
    Kinematics k;
    if (!k.load(flip ? e : m).ok() || !k.moveTo(kAngle).ok())
      return state.SkipWithError("cannot load");
    benchmark::DoNotOptimize(k.acceleration(m.outputs[0]));
  }
  state.counters["bodies"] = 1 + 2 * loops;
}

void stepChain(benchmark::State& state) {
  const int loops = static_cast<int>(state.range(0));
  const Mechanism m = test::fourBarChain(loops);
  Kinematics k;
  if (!k.load(m).ok()) return state.SkipWithError("cannot load");
  double angle = 0;
  for (auto _ : state) {
    angle += 1;
    if (!k.moveTo(angle).ok()) return state.SkipWithError("the chain stopped");
    benchmark::DoNotOptimize(k.acceleration(m.outputs[0]));
  }
  state.counters["bodies"] = 1 + 2 * loops;
}

BENCHMARK(editInPlace)
    ->Name("pipeline/edit_in_place")
    ->Arg(5)
    ->Arg(50)
    ->Arg(125)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(editWhole)
    ->Name("pipeline/edit_whole")
    ->Arg(5)
    ->Arg(50)
    ->Arg(125)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(stepChain)
    ->Name("pipeline/step")
    ->Arg(5)
    ->Arg(50)
    ->Arg(125)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
