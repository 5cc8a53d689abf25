// Forces and balancing (issue 17):
//   step/ and forces/      a pose's forces (ForceSolver::compute) next to its kinematic step
//                          (Kinematics::moveTo by 1 degree), and both together, for the
//                          examples with masses (the Wanzer needle bar, the 22-A slider-crank,
//                          the drop feed);
//   balance/               the exact balance of the drop feed's two counterweights (lower shaft,
//                          feed rock shaft) minimising the peak of |shaking fx|, from 360 and
//                          3,600 samples (issue 17's goal: 3,600 under 50 ms);
//   nelder_mead/           seed 003's method on the same model: Nelder-Mead minimising the
//                          largest |fx| of a table of the shaking force sampled at N angles,
//                          over each counterweight split in two masses 10 mm from its axis,
//                          above it and to its right (the paper's mv1, mv2), from zero.
//   build/bench/linkage_bench --benchmark_filter='forces|step/|balance|nelder' \
//       --benchmark_min_time=0.5
// The counters give each method's peak (N), what Nelder-Mead's answer peaks at between the
// table's angles, the exact optimum and the gap. Results: docs/balancing.md, docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "analysis/chebyshev_lp.h"
#include "bench_common.h"
#include "linkage/balance.h"
#include "linkage/dynamics.h"
#include "linkage/kinematics.h"

namespace {

using namespace linkage;

Kinematics loaded(const std::string& name) {
  Kinematics k;
  if (!k.load(bench::example(name)).ok()) std::abort();
  return k;
}

BodyId bodyNamed(const Kinematics& k, const std::string& name) {
  const Body* b = k.mechanism().bodyNamed(name);
  if (!b) std::abort();
  return b->id;
}

void kinematicStep(benchmark::State& state, const std::string& name) {
  Kinematics k = loaded(name);
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) std::abort();
    benchmark::DoNotOptimize(k.crankDeg());
  }
  state.SetItemsProcessed(state.iterations());
}

// The forces at one pose (the kinematics already there): the reactions, the driver's torque,
// the shaking force and moment.
void forcesAtPose(benchmark::State& state, const std::string& name) {
  Kinematics k = loaded(name);
  ForceSolver f;
  if (!f.prepare(k).ok() || !k.moveTo(37).ok()) std::abort();
  for (auto _ : state) {
    const Forces& r = f.compute(k);
    benchmark::DoNotOptimize(r.driverTorqueNm + r.shakingForceN.x());
  }
  state.SetItemsProcessed(state.iterations());
}

void stepAndForces(benchmark::State& state, const std::string& name) {
  Kinematics k = loaded(name);
  ForceSolver f;
  if (!f.prepare(k).ok()) std::abort();
  double angle = 0;
  for (auto _ : state) {
    angle += 1.0;
    if (!k.moveTo(angle).ok()) std::abort();
    const Forces& r = f.compute(k);
    benchmark::DoNotOptimize(r.driverTorqueNm + r.shakingForceN.x());
  }
  state.SetItemsProcessed(state.iterations());
}

// ----------------------------------------------------------------------------------------------
// The drop feed's counterweights: on the lower shaft, and on the feed rock shaft.
const char* const kShafts[] = {"lowershaft", "feedrock"};

BalanceOptions feedOptions(const Kinematics& k, int counterweights, int steps) {
  BalanceOptions opt;
  for (int i = 0; i < counterweights; ++i) opt.bodies.push_back(bodyNamed(k, kShafts[i]));
  opt.measure = BalanceMeasure::Fx;
  opt.steps = steps;
  return opt;
}

void exactBalance(benchmark::State& state, int counterweights, int steps, double bound) {
  const Kinematics k = loaded("drop-feed");
  BalanceOptions opt = feedOptions(k, counterweights, steps);
  if (bound > 0) opt.maxKgMm = bound;
  BalanceResult r;
  for (auto _ : state) {
    r = balanceShaking(k, opt);
    if (!r.status.ok()) std::abort();
    const double peak = r.peakAfter;  // a copy: DoNotOptimize(lvalue) may clobber it (GCC, "+m,r")
    benchmark::DoNotOptimize(peak);
  }
  state.counters["peak_before_N"] = r.peakBefore;
  state.counters["peak_N"] = r.peakAfter;
  state.counters["gap_N"] = r.gap();
  state.counters["exchanges"] = r.exchanges;
  for (size_t i = 0; i < r.counterweights.size(); ++i)
    state.counters[std::string("kgmm_") + kShafts[i]] = r.counterweights[i].kgMm();
}

// ----------------------------------------------------------------------------------------------
// Seed 003's table: at N crank angles the shaking force fx of the mechanism (fmech) and the
// x accelerations of the counterweights' two point masses per shaft, 10 mm from the axis above
// it (mv1) and to its right (mv2), taken with the shaft (the paper's aVP1x, aVP2x):
//   fx(mv) = fmech - sum mv_i aVP_i,x.
struct Table {
  std::vector<double> fmech;
  std::vector<std::vector<double>> a;  // per angle, per unknown: m/s^2
  double at(size_t i, const std::vector<double>& mv) const {
    double f = fmech[i];
    for (size_t u = 0; u < mv.size(); ++u) f -= mv[u] * a[i][u];
    return f;
  }
};

Table sampleTable(int counterweights, int n) {
  Kinematics k = loaded("drop-feed");
  const Mechanism& m = k.mechanism();
  std::vector<std::pair<BodyId, Vec2>> masses;  // body, sketch position of the point mass
  for (int c = 0; c < counterweights; ++c) {
    const BodyId b = bodyNamed(k, kShafts[c]);
    Vec2 pivot = Vec2::Zero();
    for (const Joint& j : m.joints)
      for (const auto& [p, q] : {std::pair{j.a, j.b}, std::pair{j.b, j.a}})
        if (m.point(p) && m.point(q) && m.point(p)->body == b && m.body(m.point(q)->body)->ground)
          pivot = m.point(p)->pos;
    masses.emplace_back(b, pivot + Vec2(0, 10));
    masses.emplace_back(b, pivot + Vec2(10, 0));
  }
  Table t;
  for (int i = 0; i < n; ++i) {
    if (!k.moveTo(360.0 * i / n).ok()) std::abort();
    Vec2 F;
    double M;
    shaking(k, F, M);
    t.fmech.push_back(F.x());
    t.a.emplace_back();
    for (const auto& [b, p] : masses) t.a.back().push_back(k.motionOf(b, p).acceleration.x() / 1e3);
  }
  return t;
}

const Table& table(int counterweights, int n) {
  static std::map<std::pair<int, int>, Table> cache;
  auto it = cache.find({counterweights, n});
  if (it == cache.end())
    it = cache.emplace(std::pair{counterweights, n}, sampleTable(counterweights, n)).first;
  return it->second;
}

double tablePeak(const Table& t, const std::vector<double>& mv) {
  double peak = 0;
  for (size_t i = 0; i < t.fmech.size(); ++i) peak = std::max(peak, std::abs(t.at(i, mv)));
  return peak;
}

// The local maxima of |fx| over the (cyclic) table within 1e-6 of the largest: one where the
// maximum is smooth, several at a kink of the max (the minimax optimum has unknowns + 1).
int activePeaks(const Table& t, const std::vector<double>& mv) {
  const size_t n = t.fmech.size();
  std::vector<double> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = std::abs(t.at(i, mv));
  const double top = *std::max_element(v.begin(), v.end());
  int count = 0;
  for (size_t i = 0; i < n; ++i)
    if (v[i] >= v[(i + n - 1) % n] && v[i] > v[(i + 1) % n] && v[i] >= top * (1 - 1e-6)) ++count;
  return count;
}

// The table's own minimax optimum, exactly: the linear programme on its rows (CLP).
struct TableOptimum {
  std::vector<double> mv;
  double peak = NAN;
};

TableOptimum tableOptimum(const Table& t, size_t unknowns) {
  ChebyshevLP lp(static_cast<int>(unknowns));
  std::vector<double> c(unknowns);
  for (size_t i = 0; i < t.fmech.size(); ++i)
    for (const double sign : {1.0, -1.0}) {
      for (size_t u = 0; u < unknowns; ++u) c[u] = -sign * t.a[i][u];
      lp.addRow(c.data(), -sign * t.fmech[i]);
    }
  TableOptimum o;
  if (!lp.solve(o.mv, o.peak)) std::abort();
  return o;
}

// ----------------------------------------------------------------------------------------------
// Nelder-Mead as Lagarias, Reeds, Wright and Wright (1998) state it: reflection 1, expansion 2,
// contraction 1/2, shrink 1/2; the start's simplex its point and one step along each unknown.
// Stops when the values at the simplex's vertices agree to `ftol` and its vertices to `xtol`,
// or after `maxEvals` evaluations.
struct NelderMeadResult {
  std::vector<double> x;
  double f = 0;
  int evals = 0;
};

template <class F>
NelderMeadResult nelderMead(const F& f, const std::vector<double>& start, double step, double ftol,
                            double xtol, int maxEvals) {
  const size_t n = start.size();
  std::vector<std::vector<double>> s(n + 1, start);
  for (size_t i = 0; i < n; ++i) s[i + 1][i] += step;
  std::vector<double> v(n + 1);
  int evals = 0;
  auto eval = [&](const std::vector<double>& x) { return ++evals, f(x); };
  for (size_t i = 0; i <= n; ++i) v[i] = eval(s[i]);
  std::vector<size_t> order(n + 1);
  auto along = [&](const std::vector<double>& c, double t) {  // c + t (c - worst)
    std::vector<double> x(n);
    for (size_t j = 0; j < n; ++j) x[j] = c[j] + t * (c[j] - s[order[n]][j]);
    return x;
  };
  while (evals < maxEvals) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
    double size = 0;
    for (size_t i = 1; i <= n; ++i)
      for (size_t j = 0; j < n; ++j)
        size = std::max(size, std::abs(s[order[i]][j] - s[order[0]][j]));
    if (v[order[n]] - v[order[0]] <= ftol && size <= xtol) break;
    std::vector<double> c(n, 0.0);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = 0; j < n; ++j) c[j] += s[order[i]][j] / n;
    const size_t w = order[n];
    const std::vector<double> r = along(c, 1);
    const double fr = eval(r);
    if (fr < v[order[0]]) {
      const std::vector<double> e = along(c, 2);
      const double fe = eval(e);
      s[w] = fe < fr ? e : r, v[w] = std::min(fe, fr);
    } else if (fr < v[order[n - 1]]) {
      s[w] = r, v[w] = fr;
    } else {
      const std::vector<double> k = along(c, fr < v[w] ? 0.5 : -0.5);
      const double fk = eval(k);
      if (fk < std::min(fr, v[w])) {
        s[w] = k, v[w] = fk;
      } else {  // shrink towards the best
        for (size_t i = 1; i <= n; ++i) {
          for (size_t j = 0; j < n; ++j)
            s[order[i]][j] = s[order[0]][j] + 0.5 * (s[order[i]][j] - s[order[0]][j]);
          v[order[i]] = eval(s[order[i]]);
        }
      }
    }
  }
  const size_t best = std::min_element(v.begin(), v.end()) - v.begin();
  return {s[best], v[best], evals};
}

// Seed 003's optimisation on a table of n angles: the unknowns are the point masses (kg) 10 mm
// from each shaft's axis, above and to the right, from zero, a first step of `step` kg. The
// counters: the table's peak it reaches, the table's own optimum (exact, by the programme), the
// true peak of its answer over the cycle (a table of 36,000 angles), the exact continuous
// optimum (balanceShaking), the active peaks where it stops, evaluations.
void nelderMeadOnTable(benchmark::State& state, int counterweights, int n, double step,
                       int restarts) {
  const Table& t = table(counterweights, n);
  const std::vector<double> start(2 * counterweights, 0.0);
  auto f = [&](const std::vector<double>& mv) { return tablePeak(t, mv); };
  NelderMeadResult r;
  int evals = 0, rounds = 0;
  for (auto _ : state) {
    r = nelderMead(f, start, step, 1e-12, 1e-12, 20000);
    evals = r.evals;
    // Restarted from where it stopped, with a new simplex of the first size, while that helps.
    for (rounds = 0; rounds < restarts; ++rounds) {
      const NelderMeadResult again = nelderMead(f, r.x, step, 1e-12, 1e-12, 20000);
      evals += again.evals;
      const bool better = again.f < r.f * (1 - 1e-12);
      if (again.f < r.f) r = again;
      if (!better) break;
    }
    const double peak = r.f;
    benchmark::DoNotOptimize(peak);
  }
  const Kinematics k = loaded("drop-feed");
  const BalanceResult exact = balanceShaking(k, feedOptions(k, counterweights, 360));
  const TableOptimum best = tableOptimum(t, start.size());
  state.counters["table_peak_N"] = r.f;
  state.counters["table_optimum_N"] = best.peak;
  state.counters["true_peak_N"] = tablePeak(table(counterweights, 36000), r.x);
  state.counters["exact_N"] = exact.peakAfter;
  state.counters["active_peaks"] = activePeaks(t, r.x);
  state.counters["optimum_active_peaks"] = activePeaks(t, best.mv);
  state.counters["evals"] = evals;
  state.counters["restarts"] = rounds;
  for (int c = 0; c < counterweights; ++c)  // static moments, kg mm
    state.counters[std::string("kgmm_") + kShafts[c]] = 10 * std::hypot(r.x[2 * c], r.x[2 * c + 1]);
}

// The table alone (what the paper's simulation exported), for the comparison of times.
void sampleTableOnly(benchmark::State& state, int n) {
  for (auto _ : state) benchmark::DoNotOptimize(sampleTable(2, n).fmech.back());
}

const std::string kWanzer = "wanzer-inversion-2-masses", k22a = "slider-crank-22a-masses",
                  kFeed = "drop-feed";

BENCHMARK_CAPTURE(kinematicStep, wanzer, kWanzer)->Name("forces_step/wanzer_masses");
BENCHMARK_CAPTURE(forcesAtPose, wanzer, kWanzer)->Name("forces/wanzer_masses");
BENCHMARK_CAPTURE(stepAndForces, wanzer, kWanzer)->Name("forces_step_and_forces/wanzer_masses");
BENCHMARK_CAPTURE(kinematicStep, slider_crank, k22a)->Name("forces_step/slider_crank_22a");
BENCHMARK_CAPTURE(forcesAtPose, slider_crank, k22a)->Name("forces/slider_crank_22a");
BENCHMARK_CAPTURE(stepAndForces, slider_crank, k22a)
    ->Name("forces_step_and_forces/slider_crank_22a");
BENCHMARK_CAPTURE(kinematicStep, feed, kFeed)->Name("forces_step/drop_feed");
BENCHMARK_CAPTURE(forcesAtPose, feed, kFeed)->Name("forces/drop_feed");
BENCHMARK_CAPTURE(stepAndForces, feed, kFeed)->Name("forces_step_and_forces/drop_feed");

BENCHMARK_CAPTURE(exactBalance, two_360, 2, 360, 0.0)
    ->Name("balance/drop_feed_fx_2cw_360")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(exactBalance, two_3600, 2, 3600, 0.0)
    ->Name("balance/drop_feed_fx_2cw_3600")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(exactBalance, bounded_3600, 2, 3600, 0.5)
    ->Name("balance/drop_feed_fx_2cw_3600_max0.5kgmm")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(exactBalance, one_3600, 1, 3600, 0.0)
    ->Name("balance/drop_feed_fx_lowershaft_3600")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(sampleTableOnly, t3600, 3600)
    ->Name("nelder_mead/table_3600_sampled")
    ->Unit(benchmark::kMillisecond);
// The paper's table (t from 0 to 0.05 s by 0.001 s at 1200 rpm: 50 angles a turn) and 3,600.
BENCHMARK_CAPTURE(nelderMeadOnTable, one_50, 1, 50, 0.1, 0)
    ->Name("nelder_mead/lowershaft_table_50")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nelderMeadOnTable, one_3600, 1, 3600, 0.1, 0)
    ->Name("nelder_mead/lowershaft_table_3600")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nelderMeadOnTable, two_50, 2, 50, 0.1, 0)
    ->Name("nelder_mead/2cw_table_50")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nelderMeadOnTable, two_3600, 2, 3600, 0.1, 0)
    ->Name("nelder_mead/2cw_table_3600")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nelderMeadOnTable, two_3600_big, 2, 3600, 1.0, 0)
    ->Name("nelder_mead/2cw_table_3600_step1kg")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(nelderMeadOnTable, two_3600_restarted, 2, 3600, 0.1, 100)
    ->Name("nelder_mead/2cw_table_3600_restarted")
    ->Unit(benchmark::kMillisecond);

}  // namespace
