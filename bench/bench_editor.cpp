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
#include "kinematics/kinematics_state.h"
#include "linkage/kinematics.h"
#include "mechanisms.h"

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

// The scene of range(0) (0 the Wanzer, 1 the chain) loaded by the solve of range(1) (1 the
// closed-form groups, 0 the general solve).
struct Loaded {
  Scene s;
  Kinematics k;
};

Loaded loaded(benchmark::State& state) {
  const bool closedForm = state.range(1) != 0;
  KinematicsOptions opt;
  opt.closedForm = closedForm;
  Loaded l{scene(static_cast<int>(state.range(0))), Kinematics(opt)};
  if (!l.k.load(l.s.m).ok() || l.k.closedForm() != closedForm)
    state.SkipWithError("cannot load the mechanism, or not by the solve asked for");
  state.counters["bodies"] = linkage::internal::system(l.k).nBodies;
  return l;
}

// Runs `call` once per iteration until it fails.
template <class Call>
void each(benchmark::State& state, const char* failure, Call call) {
  for (auto _ : state) {
    if (!call()) {
      state.SkipWithError(failure);
      break;
    }
  }
  state.SetItemsProcessed(state.iterations());
}

// The mouse goes round a small circle about where the point was, 0.2 degree of it per move: a
// drag that moves the mechanism a little each call.
void drag(benchmark::State& state) {
  Loaded l = loaded(state);
  const Vec2 centre = l.k.position(l.s.dragged);
  const double radius = 0.02 * l.k.size();
  double t = 0;
  each(state, "", [&] {
    t += 0.2 * M_PI / 180;
    const Kinematics::DragResult r =
        l.k.dragTo(l.s.dragged, centre + radius * Vec2(std::cos(t), std::sin(t)));
    benchmark::DoNotOptimize(r.distance);
    return true;
  });
}

// The design point goes back and forth by up to 0.5 mm, a new position each move.
void editPoint(benchmark::State& state) {
  Loaded l = loaded(state);
  if (!l.k.moveTo(30).ok()) state.SkipWithError("cannot turn the crank");
  Mechanism m = l.s.m;
  const Vec2 start = m.point(l.s.edited)->pos;
  double t = 0;
  each(state, "the edit failed", [&] {
    t += 0.05;
    m.point(l.s.edited)->pos = start + 0.5 * Vec2(std::sin(t), std::sin(0.7 * t));
    return l.k.edit(m).ok();
  });
}

// Baselines in the same run: one tracker step of 1 degree (moveTo), and a load of the design
// from scratch (what an edit would cost without the kept analysis).
void step(benchmark::State& state) {
  Loaded l = loaded(state);
  double angle = 0;
  each(state, "the mechanism stopped", [&] { return l.k.moveTo(angle += 1).ok(); });
}

void loadAgain(benchmark::State& state) {
  Loaded l = loaded(state);
  each(state, "cannot load", [&] { return l.k.load(l.s.m).ok(); });
}

// range(0): 0 the Wanzer, 1 the chain; range(1): 1 closed-form groups, 0 general solve.
BENCHMARK(drag)->Name("editor/drag")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(editPoint)->Name("editor/edit_point")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(step)->Name("editor/step_1deg")->ArgsProduct({{0, 1}, {1, 0}});
BENCHMARK(loadAgain)->Name("editor/load")->ArgsProduct({{0, 1}, {1, 0}});

}  // namespace
