// A machine's cycle analyses (issue 18): the cycle (timing) diagram of a 30-body machine on one
// main shaft with 6 windows and 3 conflicts, every event found exactly (dead centres, dwells,
// crossings of every output); the clearance of two moving points over the cycle; the slot
// travel of its blocks. Goals: the diagram under 20 ms on one core, a clearance under 5 ms.
#include <benchmark/benchmark.h>

#include "bench_common.h"
#include "linkage/clearance.h"
#include "linkage/slot_travel.h"
#include "linkage/timing.h"
#include "mechanisms.h"

namespace {

using namespace linkage;

// 14 mechanisms, 2 shafts: 30 moving bodies.
Kinematics machine() {
  Kinematics k;
  if (!k.load(test::shaftMachine(14)).ok()) std::abort();
  return k;
}

std::vector<CycleWindow> windows(const Mechanism& m) {
  std::vector<CycleWindow> w;
  for (const char* text :
       {"b0=block0.B:1,0>45", "b4=block4.B:-0.2225,0.9749<42", "b8=block8.B:-0.9009,-0.4339>47",
        "r1=rocker1:angle>3", "r5=rocker5:angle<-2", "hook=hook.K:y>-195"}) {
    std::string why;
    std::optional<CycleWindow> x = parseWindow(m, text, &why);
    if (!x) {
      std::fprintf(stderr, "%s: %s\n", text, why.c_str());
      std::abort();
    }
    w.push_back(*x);
  }
  return w;
}

void cycleDiagram30(benchmark::State& state) {
  const Kinematics k = machine();
  const std::vector<CycleWindow> w = windows(k.mechanism());
  const std::vector<std::pair<std::string, std::string>> conflicts = {
      {"b0", "b4"}, {"r1", "r5"}, {"b8", "hook"}};
  size_t intervals = 0;
  for (auto _ : state) {
    const CycleDiagram d = cycleDiagram(k, {}, w, conflicts);
    if (!d.status.ok()) std::abort();
    intervals = 0;
    for (const WindowIntervals& x : d.windows) intervals += x.intervals.size();
    benchmark::DoNotOptimize(d);
  }
  state.counters["bodies"] = static_cast<double>(k.mechanism().bodies.size() - 1);
  state.counters["intervals"] = static_cast<double>(intervals);
}

void clearanceOf(benchmark::State& state, Kinematics k, const char* a, const char* b) {
  const Mechanism& m = k.mechanism();
  const ClearancePart x = ClearancePart::of(*m.findPoint(a)),
                      y = ClearancePart::of(*m.findPoint(b));
  for (auto _ : state) {
    const Clearance c = findClearance(k, x, y);
    if (!c.status.ok()) std::abort();
    benchmark::DoNotOptimize(c);
  }
}

void clearanceLockstitch(benchmark::State& state) {
  Kinematics k;
  if (!k.load(bench::example("lockstitch-arm-shaft")).ok()) std::abort();
  clearanceOf(state, k, "hook.K", "needlebar.N");
}

void clearance30(benchmark::State& state) {
  clearanceOf(state, machine(), "hook.K", "block0.B");
}

void slotTravel30(benchmark::State& state) {
  const Kinematics k = machine();
  for (auto _ : state) {
    const SlotTravels t = slotTravel(k);
    if (!t.status.ok()) std::abort();
    benchmark::DoNotOptimize(t);
  }
}

void sweep30(benchmark::State& state) {  // the 361 steps alone, for comparison
  const Kinematics k0 = machine();
  for (auto _ : state) {
    Kinematics k = k0;
    for (int i = 0; i <= 360; ++i) benchmark::DoNotOptimize(k.moveTo(i));
  }
}

}  // namespace

BENCHMARK(cycleDiagram30)
    ->Name("machine/cycle_diagram_30_bodies_6_windows")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(sweep30)->Name("machine/turn_361_steps_30_bodies")->Unit(benchmark::kMillisecond);
BENCHMARK(clearanceLockstitch)
    ->Name("machine/clearance_lockstitch_hook_needle")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(clearance30)->Name("machine/clearance_30_bodies")->Unit(benchmark::kMillisecond);
BENCHMARK(slotTravel30)
    ->Name("machine/slot_travel_30_bodies_7_blocks")
    ->Unit(benchmark::kMillisecond);
