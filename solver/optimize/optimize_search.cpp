// The multistart (linkage/optimize.h): starts over the bounds from a fixed seed, each a local
// SLSQP (NLopt) on the exact gradient; the best design and how many starts found it.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <nlopt.hpp>
#include <random>
#include <thread>

#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/force_sensitivity.h"
#include "linkage/optimize.h"
#include "linkage/optimize_text.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"
#include "linkage/transmission.h"
#include "linkage/transmission_sensitivity.h"
#include "optimize/variables.h"

namespace linkage {

namespace {

struct Local {
  const Kinematics* base = nullptr;
  const OptimizeSpec* spec = nullptr;
  double worstFeasible = 0;  // the penalty stays above every feasible value seen
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> bestX;
  int evaluations = 0;
  // The peak targets' epigraph variables t follow the design's in the search's vector; the
  // objective and the rows are read from one evaluation of the design (NLopt asks for both at
  // the same point).
  std::vector<size_t> peakTargets;
  std::vector<double> lastX;
  bool lastWithGradient = false;
  Evaluation last;

  size_t n() const { return spec->variables.size(); }
  const Evaluation& at(const double* x, bool withGradient) {
    std::vector<double> design(x, x + n());
    if (design == lastX && (lastWithGradient || !withGradient)) return last;
    ++evaluations;
    last = evaluate(*base, *spec, design, withGradient);
    lastX = design;
    lastWithGradient = withGradient;
    if (last.feasible) {
      worstFeasible = std::max(worstFeasible, last.objective);
      if (last.objective < best) best = last.objective, bestX = design;
    }
    return last;
  }
};

// The design's objective; with peak targets, the other targets' part plus weight * t^2 (the rows
// hold each peak below its t).
double objective(unsigned count, const double* x, double* grad, void* data) {
  Local& l = *static_cast<Local*>(data);
  const Evaluation& e = l.at(x, grad != nullptr);
  if (!e.feasible) {
    // Infeasible: a plateau above everything feasible, flat, so a line search steps back.
    if (grad) std::fill(grad, grad + count, 0.0);
    return 10 * (1 + l.worstFeasible);
  }
  double f = e.objective - e.peakObjective;
  for (size_t v = 0; grad && v < l.n(); ++v) grad[v] = e.gradient[v] - e.peakGradient[v];
  for (size_t j = 0; j < l.peakTargets.size(); ++j) {
    const double w = l.spec->targets[l.peakTargets[j]].weight, t = x[l.n() + j];
    f += w * t * t;
    if (grad) grad[l.n() + j] = 2 * w * t;
  }
  return f;
}

// Every peak row <= its target's t.
void peakRows(unsigned m, double* result, unsigned count, const double* x, double* grad,
              void* data) {
  Local& l = *static_cast<Local*>(data);
  const Evaluation& e = l.at(x, grad != nullptr);
  if (grad) std::fill(grad, grad + size_t(m) * count, 0.0);
  size_t row = 0;
  for (size_t j = 0; j < l.peakTargets.size(); ++j) {
    const size_t rows = m / l.peakTargets.size();
    for (size_t i = 0; i < rows; ++i, ++row) {
      // An infeasible design's rows hold (its objective's plateau keeps the search away).
      const bool known = e.feasible && j < e.peaks.size() && i < e.peaks[j].value.size();
      result[row] = known ? e.peaks[j].value[i] - x[l.n() + j] : -1;
      if (!grad) continue;
      grad[row * count + l.n() + j] = -1;
      if (known && i < e.peaks[j].gradient.size())
        for (size_t v = 0; v < l.n(); ++v) grad[row * count + v] = e.peaks[j].gradient[i][v];
    }
  }
}

// One local search from x0 (feasible): the best point it evaluated.
void localSearch(Local& l, std::vector<double> x0) {
  const OptimizeSpec& spec = *l.spec;
  const size_t n = spec.variables.size(), p = l.peakTargets.size();
  nlopt::opt o(nlopt::LD_SLSQP, static_cast<unsigned>(n + p));
  std::vector<double> lo(n + p, 0.0), hi(n + p, HUGE_VAL);
  for (size_t i = 0; i < n; ++i) lo[i] = spec.variables[i].lo, hi[i] = spec.variables[i].hi;
  const Evaluation& e0 = l.at(x0.data(), true);
  for (size_t j = 0; j < p; ++j) {
    double top = 0;
    for (double v : e0.peaks[j].value) top = std::max(top, v);
    x0.push_back(top);
  }
  o.set_lower_bounds(lo);
  o.set_upper_bounds(hi);
  o.set_min_objective(objective, &l);
  if (p > 0)
    o.add_inequality_mconstraint(peakRows, &l,
                                 std::vector<double>(p * static_cast<size_t>(spec.steps), 1e-12));
  o.set_xtol_rel(1e-14);
  o.set_ftol_abs(0);
  o.set_maxeval(spec.maxEvaluations);
  double f = 0;
  try {
    o.optimize(x0, f);
  } catch (const std::exception&) {
    // Round-off limits and the like: the best point seen stands (l.bestX).
  }
}

Status checkTransmission(const Mechanism& m, const OptTarget& t) {
  const std::vector<TransmissionJoint> js = transmissionJoints(m);
  if (t.joint >= js.size()) return Status::badModel("no such transmission angle");
  const TransmissionJoint& j = js[t.joint];
  if (!(t.limitDeg >= 0 && t.limitDeg < 90))
    return Status::badModel("'" + j.label + "': the limit must be from 0 to 90 degrees");
  return Status::success();
}

// The targets that name no point: a shaking force, a watched clearance, a timing window.
Status checkWatched(const Mechanism& m, const OptTarget& t) {
  if (t.kind == OptTarget::Kind::Shaking) {
    if (t.measure == BalanceMeasure::Fz && !isSpatial(m))
      return Status::badModel("a planar machine's shaking force has no fz to target");
    if (!(t.limitN >= 0 && std::isfinite(t.limitN)))
      return Status::badModel("a shaking-force target's limit must be a number >= 0");
  }
  if (t.kind == OptTarget::Kind::Force) {
    if (t.index >= m.joints.size()) return Status::badModel("a force target's joint is not there");
    if (!(t.limitN >= 0 && std::isfinite(t.limitN)))
      return Status::badModel("a force target's limit must be a number >= 0");
  }
  if (t.kind == OptTarget::Kind::Clearance) {
    if (t.index >= m.timing.clearances.size())
      return Status::badModel("clearance " + std::to_string(t.index) + ": the file watches " +
                              std::to_string(m.timing.clearances.size()) +
                              " (\"timing\": \"clearances\", counted from 0)");
    if (!(t.gapMm >= 0 && std::isfinite(t.gapMm)))
      return Status::badModel("a clearance target's gap must be a number >= 0");
  }
  if (t.kind == OptTarget::Kind::Window) {
    bool found = false;
    for (const TimingWindow& w : m.timing.windows) found = found || w.name == t.window;
    if (!found) return Status::badModel("no window named \"" + t.window + "\" in the timing");
    if (!std::isfinite(t.crankDeg))
      return Status::badModel("a window target's crank angle must be a number");
  }
  return Status::success();
}

// What a target may be on a machine in space (a stroke along any direction, a position and a
// path with or without z, a timing window's end, a joint's in-plane reaction, a bearing's load
// out of its plane or a ball rod's tension, the shaking force and moment and a clearance in the
// world, a transmission angle in its plane) and on a planar one (a position or a path without z, a
// stroke in the plane).
Status checkSpace(bool space, const OptTarget& t) {
  using K = OptTarget::Kind;
  if (t.kind == K::Path && !t.pathZ.empty() && t.pathZ.size() != t.path.size())
    return Status::badModel("a path target's points have z for some and not for others");
  if (!space) {
    if (t.kind == K::Position && t.z)
      return Status::badModel(
          "a position's z is of a machine in space (planes); this one is "
          "planar: give x, y");
    if (t.kind == K::Path && !t.pathZ.empty())
      return Status::badModel(
          "a path's z is of a machine in space (planes); this one is planar: give x,y a line");
    if (t.kind == K::Stroke && t.direction && t.direction->z() != 0)
      return Status::badModel(
          "a stroke's direction out of the plane is of a machine in space (planes); this one is "
          "planar: give DX,DY");
    return Status::success();
  }
  if (t.kind == K::Position && !(t.at.allFinite() && std::isfinite(t.z.value_or(0))))
    return Status::badModel("a position target's coordinates must be numbers");
  return Status::success();
}

// A force target out of a joint's plane: a bearing's on a machine in space.
Status checkOutOfPlane(const Kinematics& base, const OptTarget& t) {
  if (t.kind != OptTarget::Kind::Force || t.reaction == OptTarget::Reaction::InPlane)
    return Status::success();
  const Mechanism& m = base.mechanism();
  const std::string name = optTargetName(m, t);
  if (!isSpatial(m))
    return Status::badModel("'" + name +
                            "': what a joint bears out of its plane is a machine in space's "
                            "(planes); this one is planar");
  if (!bearsOutOfPlane(base, m.joints[t.index].id))
    return Status::badModel("'" + name +
                            "': the joint is no body's one joint with the ground (its bearing), "
                            "so it bears nothing out of its plane");
  return Status::success();
}

double uniform(std::mt19937_64& g) {
  return static_cast<double>(g() >> 11) * 0x1.0p-53;
}

Status checkSpec(const Kinematics& base, const OptimizeSpec& spec, std::vector<double>& before) {
  if (!base.valid()) return Status::badModel("no mechanism is loaded");
  // What the sensitivities cannot differentiate yet (a cam, and in space what is not in the
  // world's sensitivities) is said once here, not found infeasible at every start.
  const bool space = isSpatial(base.mechanism());
  Sensitivity probe;
  if (Status s =
          probe.prepare(base, {}, space ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
      !s.ok())
    return Status::badModel(s.message);
  if (spec.variables.empty()) return Status::badModel("no dimension to vary");
  if (spec.targets.empty()) return Status::badModel("no target");
  if (spec.starts < 1 || spec.steps < 4) return Status::badModel("starts >= 1, steps >= 4");
  opt::Variables vars;
  if (Status s = opt::mapVariables(base.mechanism(), base.mechanism(), spec, vars); !s.ok())
    return s;
  for (size_t i = 0; i < spec.variables.size(); ++i) {
    const OptVariable& v = spec.variables[i];
    if (!(std::isfinite(v.lo) && std::isfinite(v.hi) && v.lo < v.hi))
      return Status::badModel("'" + v.name + "': its bounds need LO < HI, both finite");
    before.push_back(vars.dim[i] >= 0 ? vars.dims[vars.dim[i]].value : 0.0);
  }
  for (const OptTarget& t : spec.targets) {
    if (Status s = checkSpace(space, t); !s.ok()) return s;
    if (Status s = checkWatched(base.mechanism(), t); !s.ok()) return s;
    const bool named = t.kind == OptTarget::Kind::Shaking || t.kind == OptTarget::Kind::Force ||
                       t.kind == OptTarget::Kind::Clearance || t.kind == OptTarget::Kind::Window;
    if (!named && !base.mechanism().contains(t.point))
      return Status::badModel("a target's point is not in the mechanism");
    if (!(t.weight > 0 && std::isfinite(t.weight)))
      return Status::badModel("a target's weight must be positive");
    if (t.kind == OptTarget::Kind::Path && t.path.empty())
      return Status::badModel("a path target has no points");
    if (t.kind == OptTarget::Kind::Transmission)
      if (Status s = checkTransmission(base.mechanism(), t); !s.ok()) return s;
    if (Status s = checkOutOfPlane(base, t); !s.ok()) return s;
  }
  return Status::success();
}

// One start's outcome.
struct Start {
  std::vector<double> x0;
  bool feasible = false;
  double best = 0;
  std::vector<double> bestX;
  int evaluations = 0;
};

void runStart(const Kinematics& base, const OptimizeSpec& spec, Start& s) {
  Local l;
  l.base = &base;
  l.spec = &spec;
  for (size_t t = 0; t < spec.targets.size(); ++t)
    if (spec.targets[t].kind == OptTarget::Kind::Shaking ||
        spec.targets[t].kind == OptTarget::Kind::Force)
      l.peakTargets.push_back(t);
  l.at(s.x0.data(), true);
  if (l.bestX.empty()) return;
  localSearch(l, s.x0);
  s.feasible = true;
  s.best = l.best;
  s.bestX = l.bestX;
  s.evaluations = l.evaluations;
}

// The starts on the cores: each its own copy of the base, the starts drawn beforehand, so that
// the answer is the same on any number of threads.
void runStarts(const Kinematics& base, const OptimizeSpec& spec, std::vector<Start>& starts) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads =
      std::clamp(spec.threads > 0 ? spec.threads : cores, 1, static_cast<int>(starts.size()));
  std::vector<Kinematics> bases(threads, base);
  std::atomic<size_t> next{0};
  auto work = [&](int t) {
    for (size_t i; (i = next++) < starts.size();) runStart(bases[t], spec, starts[i]);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& th : pool) th.join();
}

}  // namespace

OptimizeResult optimize(const Kinematics& base, const OptimizeSpec& spec) {
  OptimizeResult r;
  if (r.status = checkSpec(base, spec, r.before); !r.status.ok()) return r;
  const size_t n = spec.variables.size();
  r.atBefore = evaluate(base, spec, r.before);
  std::mt19937_64 gen(spec.seed);
  std::vector<Start> starts(spec.starts);
  for (int s = 0; s < spec.starts; ++s)
    for (size_t i = 0; i < n; ++i) {
      const OptVariable& v = spec.variables[i];
      starts[s].x0.push_back(s == 0 ? std::clamp(r.before[i], v.lo, v.hi)
                                    : v.lo + (v.hi - v.lo) * uniform(gen));
    }
  runStarts(base, spec, starts);
  std::vector<double> finals;
  std::vector<std::vector<double>> xs;
  for (const Start& s : starts) {
    ++r.starts;
    if (!s.feasible) {
      ++r.infeasibleStarts;
      continue;
    }
    r.evaluations += s.evaluations;
    finals.push_back(s.best);
    xs.push_back(s.bestX);
  }
  if (finals.empty()) {
    r.status =
        Status::failure(StatusCode::AssemblyFailed,
                        "no start assembles and turns fully" +
                            (r.atBefore.why.empty() ? "" : " (as drawn: " + r.atBefore.why + ")"));
    return r;
  }
  const size_t b = std::min_element(finals.begin(), finals.end()) - finals.begin();
  for (double f : finals) r.foundBest += f <= finals[b] + spec.sameBest + 1e-6 * finals[b];
  r.after = xs[b];
  r.atAfter = evaluate(base, spec, r.after);
  Mechanism m = base.mechanism();
  opt::Variables vars;
  opt::mapVariables(base.mechanism(), base.mechanism(), spec, vars);
  std::vector<std::pair<std::string, double>> values;
  for (size_t i = 0; i < n; ++i)
    if (vars.dim[i] >= 0) values.push_back({spec.variables[i].name, r.after[i]});
  setDimensions(m, values);
  PoseEdit pe = editAtPose(base, std::move(m));
  r.design = std::move(pe.design);
  for (size_t c = 0; c < vars.counterweights.size(); ++c) {
    Counterweight cw = vars.counterweights[c];
    cw.staticMoment = vars.moment(r.after, c);
    cw.kg = vars.kg(r.after, c);
    if (!cw.none()) r.counterweights.push_back(cw);
  }
  addCounterweights(r.design, r.counterweights);
  return r;
}

}  // namespace linkage
