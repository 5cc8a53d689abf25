// The multistart (linkage/optimize.h): starts over the bounds from a fixed seed, each a local
// SLSQP (NLopt) on the exact gradient; the best design and how many starts found it.
#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <random>

#include "linkage/edits.h"
#include "linkage/optimize.h"
#include "linkage/sensitivity.h"
#include "linkage/transmission.h"

namespace linkage {

namespace {

struct Local {
  const Kinematics* base = nullptr;
  const OptimizeSpec* spec = nullptr;
  double worstFeasible = 0;  // the penalty stays above every feasible value seen
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> bestX;
  int evaluations = 0;
};

double objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  Local& l = *static_cast<Local*>(data);
  ++l.evaluations;
  const Evaluation e = evaluate(*l.base, *l.spec, x, !grad.empty());
  if (!e.feasible) {
    // Infeasible: a plateau above everything feasible, flat, so a line search steps back.
    std::fill(grad.begin(), grad.end(), 0.0);
    return 10 * (1 + l.worstFeasible);
  }
  l.worstFeasible = std::max(l.worstFeasible, e.objective);
  if (e.objective < l.best) {
    l.best = e.objective;
    l.bestX = x;
  }
  if (!grad.empty()) grad = e.gradient;
  return e.objective;
}

// One local search from x0 (feasible): the best point it evaluated.
void localSearch(Local& l, std::vector<double> x0) {
  const OptimizeSpec& spec = *l.spec;
  const size_t n = spec.variables.size();
  nlopt::opt o(nlopt::LD_SLSQP, static_cast<unsigned>(n));
  std::vector<double> lo(n), hi(n);
  for (size_t i = 0; i < n; ++i) lo[i] = spec.variables[i].lo, hi[i] = spec.variables[i].hi;
  o.set_lower_bounds(lo);
  o.set_upper_bounds(hi);
  o.set_min_objective(objective, &l);
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
  if (j.kind != TransmissionKind::Dyad || j.linkOuter.arc || j.linkAt.arc || j.otherAt.arc ||
      j.otherOuter.arc)
    return Status::badModel("'" + j.label +
                            "': only a dyad's angle between points is differentiated yet");
  if (!(t.limitDeg >= 0 && t.limitDeg < 90))
    return Status::badModel("'" + j.label + "': the limit must be from 0 to 90 degrees");
  return Status::success();
}

double uniform(std::mt19937_64& g) {
  return static_cast<double>(g() >> 11) * 0x1.0p-53;
}

Status checkSpec(const Kinematics& base, const OptimizeSpec& spec, std::vector<double>& before) {
  if (!base.valid()) return Status::badModel("no mechanism is loaded");
  // What the sensitivities cannot differentiate yet (a spatial model, a cam) is said once here,
  // not found infeasible at every start.
  Sensitivity probe;
  if (Status s = probe.prepare(base, {}); !s.ok()) return Status::badModel(s.message);
  if (spec.variables.empty()) return Status::badModel("no dimension to vary");
  if (spec.targets.empty()) return Status::badModel("no target");
  if (spec.starts < 1 || spec.steps < 4) return Status::badModel("starts >= 1, steps >= 4");
  const std::vector<Dimension> dims = dimensions(base.mechanism());
  for (const OptVariable& v : spec.variables) {
    auto it = std::find_if(dims.begin(), dims.end(),
                           [&](const Dimension& d) { return d.name == v.name; });
    if (it == dims.end()) return Status::badModel("no dimension '" + v.name + "' in the mechanism");
    if (!(std::isfinite(v.lo) && std::isfinite(v.hi) && v.lo < v.hi))
      return Status::badModel("'" + v.name + "': its bounds need LO < HI, both finite");
    before.push_back(it->value);
  }
  for (const OptTarget& t : spec.targets) {
    if (!base.mechanism().contains(t.point))
      return Status::badModel("a target's point is not in the mechanism");
    if (!(t.weight > 0 && std::isfinite(t.weight)))
      return Status::badModel("a target's weight must be positive");
    if (t.kind == OptTarget::Kind::Path && t.path.empty())
      return Status::badModel("a path target has no points");
    if (t.kind == OptTarget::Kind::Transmission)
      if (Status s = checkTransmission(base.mechanism(), t); !s.ok()) return s;
  }
  return Status::success();
}

}  // namespace

OptimizeResult optimize(const Kinematics& base, const OptimizeSpec& spec) {
  OptimizeResult r;
  if (r.status = checkSpec(base, spec, r.before); !r.status.ok()) return r;
  const size_t n = spec.variables.size();
  r.atBefore = evaluate(base, spec, r.before);
  std::mt19937_64 gen(spec.seed);
  std::vector<double> finals;
  std::vector<std::vector<double>> xs;
  for (int s = 0; s < spec.starts; ++s) {
    std::vector<double> x0(n);
    for (size_t i = 0; i < n; ++i) {
      const OptVariable& v = spec.variables[i];
      x0[i] = s == 0 ? std::clamp(r.before[i], v.lo, v.hi) : v.lo + (v.hi - v.lo) * uniform(gen);
    }
    ++r.starts;
    Local l;
    l.base = &base;
    l.spec = &spec;
    std::vector<double> g;
    objective(x0, g, &l);
    if (l.bestX.empty()) {
      ++r.infeasibleStarts;
      continue;
    }
    localSearch(l, x0);
    r.evaluations += l.evaluations;
    finals.push_back(l.best);
    xs.push_back(l.bestX);
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
  std::vector<std::pair<std::string, double>> values;
  for (size_t i = 0; i < n; ++i) values.push_back({spec.variables[i].name, r.after[i]});
  setDimensions(m, values);
  PoseEdit pe = editAtPose(base, std::move(m));
  r.design = std::move(pe.design);
  return r;
}

}  // namespace linkage
