// What an editor asks of the solver once per mouse move: a drag (the mechanism moved along its
// freedom so that a point follows the mouse) and a live edit of one design point (Ctrl+drag),
// on the Wanzer needle bar (example wanzer-inversion-2, one core group) and on a 51-body chain
// of four-bars (test::fourBarChain(25)), by the closed-form groups and by the general solve.
//   build/bench/linkage_bench --benchmark_filter=editor
// Results: docs/benchmarks.md, "An editor's mouse move".
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "bench_common.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"
#include "solve/kinematics_state.h"

namespace {

using namespace linkage;

struct Scene {
  Mechanism m;
  PointId dragged;  // a point the mouse drags
  PointId edited;   // a design point the mouse moves (Ctrl+drag)
};

Scene wanzer() {
  Scene s{bench::example("wanzer-inversion-2"), {}, {}};
  s.dragged = *s.m.findPoint("needlebar.G");
  s.edited = *s.m.findPoint("triangle.G");
  return s;
}

Scene chain() {
  Scene s{test::fourBarChain(25), {}, {}};
  s.dragged = *s.m.findPoint("coupler0.B");
  s.edited = *s.m.findPoint("coupler12.B");
  return s;
}

Scene scene(int which) {
  return which == 0 ? wanzer() : chain();
}

KinematicsOptions options(bool closedForm) {
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  return opt;
}

void load(benchmark::State& state, Kinematics& k, const Mechanism& m, bool closedForm) {
  if (!k.load(m).ok() || k.closedForm() != closedForm)
    state.SkipWithError("cannot load the mechanism, or not by the solve asked for");
  state.counters["bodies"] = linkage::internal::system(k).nBodies;
}

// The mouse goes round a small circle about where the point was, 0.2 degree of it per move: a
// drag that moves the mechanism a little each call.
void drag(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const bool closedForm = state.range(1) != 0;
  Kinematics k(options(closedForm));
  load(state, k, s.m, closedForm);
  const Vec2 centre = k.position(s.dragged);
  const double radius = 0.02 * k.size();
  double t = 0;
  for (auto _ : state) {
    t += 0.2 * M_PI / 180;
    const Kinematics::DragResult r =
        k.dragTo(s.dragged, centre + radius * Vec2(std::cos(t), std::sin(t)));
    benchmark::DoNotOptimize(r.distance);
  }
  state.SetItemsProcessed(state.iterations());
}

// The design point goes back and forth by up to 0.5 mm, a new position each move.
void editPoint(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const bool closedForm = state.range(1) != 0;
  Kinematics k(options(closedForm));
  load(state, k, s.m, closedForm);
  if (!k.moveTo(30).ok()) state.SkipWithError("cannot turn the crank");
  Mechanism m = s.m;
  const Vec2 start = m.point(s.edited)->pos;
  double t = 0;
  for (auto _ : state) {
    t += 0.05;
    m.point(s.edited)->pos = start + 0.5 * Vec2(std::sin(t), std::sin(0.7 * t));
    if (!k.edit(m).ok()) {
      state.SkipWithError("the edit failed");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

// Baselines in the same run: one tracker step of 1 degree (moveTo), and a load of the design
// from scratch (what an edit would cost without the kept analysis).
void step(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const bool closedForm = state.range(1) != 0;
  Kinematics k(options(closedForm));
  load(state, k, s.m, closedForm);
  double angle = 0;
  for (auto _ : state) {
    angle += 1;
    if (!k.moveTo(angle).ok()) {
      state.SkipWithError("the mechanism stopped");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

void loadAgain(benchmark::State& state) {
  const Scene s = scene(static_cast<int>(state.range(0)));
  const bool closedForm = state.range(1) != 0;
  Kinematics k(options(closedForm));
  load(state, k, s.m, closedForm);
  for (auto _ : state) {
    if (!k.load(s.m).ok()) {
      state.SkipWithError("cannot load");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

// range(0): 0 the Wanzer, 1 the chain; range(1): 1 closed-form groups, 0 general solve.
BENCHMARK(drag)->Name("editor/drag")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(editPoint)->Name("editor/edit_point")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(step)->Name("editor/step_1deg")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(loadAgain)->Name("editor/load")->ArgsProduct({{0, 1}, {1, 0}});

}  // namespace
