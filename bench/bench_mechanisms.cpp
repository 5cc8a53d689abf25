// A machine's mechanisms solved on their own (issue 18): the 30-body machine of 14 mechanisms
// on one main shaft (tests/mechanisms.h shaftMachine), an edit of one mechanism's dimensions
// (rod 0 made 2 mm longer and back) against a solve of the whole machine, on the closed-form
// path and on the general (Newton) path; the split into mechanisms itself, and one animation
// step of the whole machine.
#include <benchmark/benchmark.h>

#include "linkage/kinematics.h"
#include "linkage/mechanisms.h"
#include "mechanisms.h"

namespace {

using namespace linkage;

Mechanism longerRod0(const Mechanism& m) {
  Mechanism e = m;
  for (const char* p : {"rod0.B", "block0.B"}) e.point(*e.findPoint(p))->pos.x() += 2;
  return e;
}

// closedForm false: the general path, where an edit is solved by Newton on the touched groups'
// bodies alone (KinematicsState::editBlocks).
void editOneMechanism(benchmark::State& state, bool closedForm) {
  const Mechanism m = test::shaftMachine(14), e = longerRod0(m);
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  if (!k.load(m).ok() || !k.moveTo(40).ok()) std::abort();
  int groups = 0;
  for (auto _ : state) {
    if (!k.edit(e).ok()) std::abort();
    groups = k.lastEditGroups();
    if (!k.edit(m).ok()) std::abort();
  }
  state.counters["groups_solved"] = groups;
  state.counters["edits"] = benchmark::Counter(2, benchmark::Counter::kIsIterationInvariantRate);
}

void solveWholeMachine(benchmark::State& state, bool closedForm) {
  const Mechanism m = test::shaftMachine(14), e = longerRod0(m);
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  for (auto _ : state) {
    Kinematics k(opt);
    if (!k.load(e).ok() || !k.moveTo(40).ok()) std::abort();
    benchmark::DoNotOptimize(k);
  }
}

void split(benchmark::State& state) {
  const Mechanism m = test::shaftMachine(14);
  size_t n = 0;
  for (auto _ : state) {
    const std::vector<SubMechanism> all = subMechanisms(m);
    n = all.size();
    benchmark::DoNotOptimize(all);
  }
  state.counters["mechanisms"] = static_cast<double>(n);
}

void step(benchmark::State& state) {
  Kinematics k;
  if (!k.load(test::shaftMachine(14)).ok()) std::abort();
  double deg = 0;
  for (auto _ : state) {
    deg += 1;
    if (!k.moveTo(deg).ok()) std::abort();
  }
}

}  // namespace

BENCHMARK_CAPTURE(editOneMechanism, closed_form, true)
    ->Name("mechanisms/edit_one_of_14_30_bodies")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(editOneMechanism, general, false)
    ->Name("mechanisms/edit_one_of_14_30_bodies_general")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solveWholeMachine, closed_form, true)
    ->Name("mechanisms/load_whole_30_bodies")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(solveWholeMachine, general, false)
    ->Name("mechanisms/load_whole_30_bodies_general")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(split)->Name("mechanisms/split_30_bodies")->Unit(benchmark::kMicrosecond);
BENCHMARK(step)->Name("mechanisms/step_1deg_30_bodies")->Unit(benchmark::kMicrosecond);
