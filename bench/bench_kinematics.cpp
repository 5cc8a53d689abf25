// Steps per second of a full kinematic step (position by Newton from the predictor, then exact
// velocity and acceleration solves, then the output point's x, v, a), for the example
// mechanisms at 1 degree per step, next to the closed-form slider-crank in the same run.
//   build/bench/linkage_bench --benchmark_min_time=1
// Results and their discussion: docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_common.h"
#include "cam_fixtures.h"
#include "kinematics/kinematics_state.h"
#include "linkage/kinematics.h"

namespace {

using namespace linkage;

using bench::example;

void kinematicStep(benchmark::State& state, const std::string& name, bool accelerations,
                   bool closedForm = true, const std::vector<std::string>& without = {},
                   const std::string& output = "") {
  // A name starting with '{' is the mechanism's file text.
  Mechanism m = name.starts_with('{') ? *parseMechanism(name).mechanism : example(name);
  std::vector<BodyId> gone;
  for (const std::string& b : without) gone.push_back(m.bodyNamed(b)->id);
  if (!gone.empty()) m.remove(gone);
  KinematicsOptions opt;
  opt.accelerations = accelerations;
  opt.closedForm = closedForm;
  Kinematics k(opt);
  if (!k.load(m).ok()) std::abort();
  const PointId out = output.empty() ? m.outputs.at(0) : *m.findPoint(output);
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) std::abort();
    const Kinematics::PointMotion m = k.motion(out);
    benchmark::DoNotOptimize(m.position.x() + m.velocity.x() + m.acceleration.x());
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["bodies"] = static_cast<double>(linkage::internal::system(k).nBodies + 1);
}

// The exact closed form of the central slider-crank (r = 15, l = 30, 1000 rpm): what a
// hand-written program for this one mechanism costs per step.
void closedFormSliderCrank(benchmark::State& state) {
  const double r = 15, l = 30, w = 1000 * 2 * M_PI / 60, lambda = r / l;
  double phi = 0;
  const double step = M_PI / 180;
  for (auto _ : state) {
    phi += step;
    const double c = std::cos(phi), s = std::sin(phi);
    const double D = std::sqrt(1 - lambda * lambda * s * s);
    const double y = r * c + l * D;
    const double v = -r * w * s * (1 + lambda * c / D);
    const double a =
        -r * w * w *
        (c + lambda * (c * c - s * s) / D + lambda * lambda * lambda * s * s * c * c / (D * D * D));
    benchmark::DoNotOptimize(y + v + a);
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(closedFormSliderCrank)->Name("closed_form/slider_crank");
BENCHMARK_CAPTURE(kinematicStep, slider_crank, std::string("slider-crank-22a-lambda-0.5"), true)
    ->Name("step/slider_crank");
BENCHMARK_CAPTURE(kinematicStep, four_bar, std::string("four-bar-crank-rocker"), true)
    ->Name("step/four_bar");
BENCHMARK_CAPTURE(kinematicStep, wanzer, std::string("wanzer-inversion-2"), true)
    ->Name("step/wanzer");
// Machines in space (issue 27): the RSSR crank-rocker (a ball rod between a crank and a rocker
// on crossed shafts: the spatial part of seed 004's needle arm), and seed 004's whole machine.
BENCHMARK_CAPTURE(kinematicStep, rssr, std::string("rssr-crank-rocker"), true)
    ->Name("step/rssr_space");
BENCHMARK_CAPTURE(kinematicStep, overedge, std::string("overedge-machine"), true)
    ->Name("step/overedge_machine_space");
// Its needle arm alone (the crank R1, the ball rod L1, the rocker W1-W2 on its inclined axis,
// L2 and the needle arm in its guide): the measure, against the planar four-bar.
BENCHMARK_CAPTURE(kinematicStep, needle_arm, std::string("overedge-machine"), true, true,
                  std::vector<std::string>{"upper", "lowerlink", "lower", "feedrod", "feedrock1",
                                           "feedlink", "feedrock2", "liftrod", "feedbar"})
    ->Name("step/needle_arm_space");
// The gear, belt and arc examples, in closed form (geared bodies, a pin in an arc, a block in a
// curved guide) and by the general Newton, for the comparison.
BENCHMARK_CAPTURE(kinematicStep, lockstitch, std::string("lockstitch-arm-shaft"), true)
    ->Name("step/lockstitch");
BENCHMARK_CAPTURE(kinematicStep, gear_four_bar, std::string("gear-four-bar"), true)
    ->Name("step/gear_four_bar");
BENCHMARK_CAPTURE(kinematicStep, planet, std::string("planet-epicycloid"), true)
    ->Name("step/planet");
BENCHMARK_CAPTURE(kinematicStep, curved_guide, std::string("curved-guide"), true)
    ->Name("step/curved_guide");
BENCHMARK_CAPTURE(kinematicStep, lockstitch, std::string("lockstitch-arm-shaft"), true, false)
    ->Name("step_general/lockstitch");
BENCHMARK_CAPTURE(kinematicStep, gear_four_bar, std::string("gear-four-bar"), true, false)
    ->Name("step_general/gear_four_bar");
BENCHMARK_CAPTURE(kinematicStep, planet, std::string("planet-epicycloid"), true, false)
    ->Name("step_general/planet");
BENCHMARK_CAPTURE(kinematicStep, curved_guide, std::string("curved-guide"), true, false)
    ->Name("step_general/curved_guide");
// A cam and its follower against a gear pair of as many bodies (issue 28: a cam joint's step no
// slower than a gear's). Each is a driven body and one body solved from it by a single row
// (the follower: its slider and the cam's row; the gear: its pin and the gear's row), the
// output a point of that second body: the cam example as it is, and the gear four-bar without
// its coupler and rocker (the pinion driving the gear, gear.A the output).
BENCHMARK_CAPTURE(kinematicStep, cam, std::string("cam-translating-roller"), true)
    ->Name("step/cam_translating");
BENCHMARK_CAPTURE(kinematicStep, gear_pair, std::string("gear-four-bar"), true, true,
                  std::vector<std::string>{"coupler", "rocker"}, std::string("gear.A"))
    ->Name("step/gear_pair");
// An oscillating roller follower (tests/cam_fixtures.h): its turn needs a sine and cosine.
BENCHMARK_CAPTURE(kinematicStep, cam_oscillating, linkage::test::OscillatingCam{}.text(), true)
    ->Name("step/cam_oscillating");
BENCHMARK_CAPTURE(kinematicStep, cam, std::string("cam-translating-roller"), true, false)
    ->Name("step_general/cam_translating");
BENCHMARK_CAPTURE(kinematicStep, cam_oscillating, linkage::test::OscillatingCam{}.text(), true,
                  false)
    ->Name("step_general/cam_oscillating");
BENCHMARK_CAPTURE(kinematicStep, gear_pair, std::string("gear-four-bar"), true, false,
                  std::vector<std::string>{"coupler", "rocker"}, std::string("gear.A"))
    ->Name("step_general/gear_pair");
// The same steps without accelerations (positions and velocities only): what leaving them out
// saves.
BENCHMARK_CAPTURE(kinematicStep, slider_crank, std::string("slider-crank-22a-lambda-0.5"), false)
    ->Name("step_no_acceleration/slider_crank");
BENCHMARK_CAPTURE(kinematicStep, four_bar, std::string("four-bar-crank-rocker"), false)
    ->Name("step_no_acceleration/four_bar");
BENCHMARK_CAPTURE(kinematicStep, wanzer, std::string("wanzer-inversion-2"), false)
    ->Name("step_no_acceleration/wanzer");

}  // namespace
