// Dimensions found for targets (linkage/optimize.h): the objective, its exact gradient, and the
// NLopt multistart.
#include "linkage/optimize.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <random>

#include "analysis/crank_roots.h"
#include "linkage/edits.h"
#include "linkage/limits.h"
#include "linkage/sensitivity.h"
#include "linkage/space.h"
#include "linkage/stroke_sensitivity.h"
#include "linkage/transmission.h"
#include "linkage/transmission_sensitivity.h"
#include "optimize/variables.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

// The design x, solved at crank angle 0 from the base's pose (the base's branches).
bool solveDesign(const Kinematics& base, const OptimizeSpec& spec, const std::vector<double>& x,
                 Kinematics& out, std::string& why, Mechanism* design = nullptr) {
  Mechanism m = base.mechanism();
  std::vector<std::pair<std::string, double>> values;
  std::string body;
  int axis = 0;
  for (size_t i = 0; i < spec.variables.size(); ++i)
    if (!opt::counterweightName(spec.variables[i].name, body, axis))
      values.push_back({spec.variables[i].name, x[i]});
  if (Status s = setDimensions(m, values); !s.ok()) {
    why = s.message;
    return false;
  }
  PoseEdit pe = editAtPose(base, std::move(m));
  if (!pe.solved) {
    why = "the design does not assemble";
    return false;
  }
  out = std::move(pe.kinematics);
  out.setAccelerations(true);
  if (design) *design = std::move(pe.design);
  return true;
}

// Where the gradient is read: a crank angle, and what to add there.
struct Probe {
  double deg = 0;
  size_t target = 0;
  Vec2 weightOfDp = Vec2::Zero();  // d objective = weightOfDp . dP/dp
  PointId point;
  size_t index = 0;        // a path's given point
  double angleWeight = 0;  // Transmission: d objective = angleWeight . d mu (degrees)
  // On a machine in space, instead of weightOfDp: d objective = weightOfDp3 . dP/dp, P the
  // point's world position.
  Vec3 weightOfDp3 = Vec3::Zero();
};

// Transmission: the angle's extremes over the turn against the limits.
Status transmissionResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t i, Evaluation& e,
                             std::vector<Probe>& probes) {
  const OptTarget& t = spec.targets[i];
  TransmissionOptions to;
  to.steps = spec.steps;
  const TransmissionSweep sw = sweepTransmission(k, to);
  if (!sw.status.ok()) return sw.status;
  if (t.joint >= sw.summaries.size()) return Status::badModel("no such transmission angle");
  const TransmissionSummary& m = sw.summaries[t.joint];
  const double low = std::max(0.0, t.limitDeg - m.min),
               high = std::max(0.0, m.max - (180 - t.limitDeg));
  e.objective += t.weight * (low * low + high * high);
  e.measures[i] = {m.min, m.max};
  probes.push_back({m.minDeg, i, Vec2::Zero(), {}, 0, -2 * t.weight * low});
  probes.push_back({m.maxDeg, i, Vec2::Zero(), {}, 0, 2 * t.weight * high});
  return Status::success();
}

// A path's given point Q against the point's place P at kk's pose: P - Q and P's first and
// second rates per degree of crank. On a machine in space in the world, z left out where the path
// gives none (pathZ empty: as a position without z).
struct PathGap {
  Vec3 d, v, a;
};
PathGap pathGap(const Kinematics& kk, const OptTarget& t, size_t i, bool space) {
  const double rate = kDeg / kk.omega();
  if (!space) {
    const Kinematics::PointMotion m = kk.motion(t.point);
    const Vec2 d = m.position - t.path[i];
    return {Vec3(d.x(), d.y(), 0), Vec3(m.velocity.x(), m.velocity.y(), 0) * rate,
            Vec3(m.acceleration.x(), m.acceleration.y(), 0) * rate * rate};
  }
  const Kinematics::PointMotion3 m = kk.motionInSpace(t.point);
  const Vec3 mask(1, 1, t.pathZ.empty() ? 0 : 1);
  const Vec3 q(t.path[i].x(), t.path[i].y(), t.pathZ.empty() ? 0 : t.pathZ[i]);
  return {(m.position - q).cwiseProduct(mask), m.velocity.cwiseProduct(mask) * rate,
          m.acceleration.cwiseProduct(mask) * rate * rate};
}

// A path's given points: each one's nearest point of the curve over the turn, the local minima
// of |P - Q|^2 found as roots of (P - Q) . P' (exact rates, narrowed to 1e-9 degree).
Status nearestPoints(const Kinematics& k, const OptTarget& t, int steps, std::vector<double>& deg) {
  std::vector<RootChannel> channels(t.path.size());
  std::vector<RootChannel*> ptrs;
  const bool space = isSpatial(k.mechanism());
  for (size_t i = 0; i < t.path.size(); ++i) {
    channels[i].f = [&t, i, space](const Kinematics& kk) {
      const PathGap g = pathGap(kk, t, i, space);
      return RootSample{g.d.dot(g.v), g.v.squaredNorm() + g.d.dot(g.a)};
    };
    channels[i].value = [&t, i, space](const Kinematics& kk) {
      return pathGap(kk, t, i, space).d.squaredNorm();
    };
    ptrs.push_back(&channels[i]);
  }
  Kinematics probe = k;
  std::vector<double> crank;
  std::vector<double> best(t.path.size(), std::numeric_limits<double>::infinity());
  deg.assign(t.path.size(), 0);
  for (int i = 0; i <= steps; ++i) {
    crank.push_back(360.0 * i / steps);
    if (Status s = probe.moveTo(crank.back()); !s.ok()) return s;
    for (size_t j = 0; j < channels.size(); ++j) {
      channels[j].samples.push_back(channels[j].f(probe));
      const double d2 = channels[j].value(probe);
      if (d2 < best[j]) best[j] = d2, deg[j] = crank.back();
    }
  }
  probe = k;
  if (Status s = findRoots(probe, crank, ptrs, true); !s.ok()) return s;
  for (size_t j = 0; j < channels.size(); ++j)
    for (const Root& r : channels[j].roots)
      if (r.rising && r.value < best[j]) best[j] = r.value, deg[j] = r.crankDeg;
  return Status::success();
}

// The targets' residuals at the design k: the objective, the measures, and the probes that give
// the gradient.
Status residuals(const Kinematics& k, const OptimizeSpec& spec, const Vec3* strokeDirs,
                 const opt::Variables& vars, const std::vector<double>& x, Sensitivity* sens,
                 Evaluation& e, std::vector<Probe>& probes) {
  e.measures.assign(spec.targets.size(), {});
  for (size_t i = 0; i < spec.targets.size(); ++i) {
    const OptTarget& t = spec.targets[i];
    if (t.kind == OptTarget::Kind::Stroke) {
      LimitOptions lo;
      lo.steps = spec.steps;
      const Limits l = findLimits(k, LimitMeasure::alongInSpace(t.point, strokeDirs[i]), lo);
      if (!l.status.ok()) return l.status;
      const double r = l.stroke - t.stroke;
      e.objective += t.weight * r * r;
      e.measures[i] = {l.stroke};
      // A planar machine's direction has z 0: its weights are the plane's.
      const Vec3 w = 2 * t.weight * r * strokeDirs[i];
      const bool space = isSpatial(k.mechanism());
      probes.push_back({l.maxDeg, i, space ? Vec2::Zero() : Vec2(w.head<2>()), t.point, 0, 0,
                        space ? w : Vec3::Zero()});
      probes.push_back({l.minDeg, i, space ? Vec2::Zero() : Vec2(-w.head<2>()), t.point, 0, 0,
                        space ? Vec3(-w) : Vec3::Zero()});
    } else if (t.kind == OptTarget::Kind::Position) {
      probes.push_back(
          {std::fmod(std::fmod(t.crankDeg, 360) + 360, 360), i, Vec2::Zero(), t.point});
    } else if (t.kind == OptTarget::Kind::Transmission) {
      if (Status s = transmissionResiduals(k, spec, i, e, probes); !s.ok()) return s;
    } else if (t.kind == OptTarget::Kind::Shaking || t.kind == OptTarget::Kind::Force) {
      if (Status s = opt::shakingResiduals(k, spec, i, vars, x, sens, e); !s.ok()) return s;
    } else if (t.kind == OptTarget::Kind::Clearance) {
      if (Status s = opt::clearanceResiduals(k, spec, i, vars, sens != nullptr, e); !s.ok())
        return s;
    } else if (t.kind == OptTarget::Kind::Window) {
      if (Status s = opt::windowResiduals(k, spec, i, vars, sens != nullptr, e); !s.ok()) return s;
    } else {
      std::vector<double> deg;
      if (Status s = nearestPoints(k, t, spec.steps, deg); !s.ok()) return s;
      for (size_t j = 0; j < deg.size(); ++j)
        probes.push_back({deg[j], i, Vec2::Zero(), t.point, j});
    }
  }
  return Status::success();
}

// A position target on a machine in space at the walker's pose: the point's world x, y (and z
// when the target gives one) against the target's.
void spacePosition(const Kinematics& walker, const OptTarget& t, Evaluation& e, Probe& p) {
  const Vec3 at = walker.motionInSpace(p.point).position;
  Vec3 r = at - Vec3(t.at.x(), t.at.y(), t.z.value_or(at.z()));
  if (!t.z) r.z() = 0;
  e.objective += t.weight * r.squaredNorm();
  e.measures[p.target] = {at.x(), at.y()};
  if (t.z) e.measures[p.target].push_back(at.z());
  p.weightOfDp3 = 2 * t.weight * r;
}

// Walks the probes in crank order on one copy of k: the pose-dependent residuals (positions,
// path distances) and every probe's gradient from the exact dP/dp.
Status walkProbes(const Kinematics& k, const OptimizeSpec& spec, const opt::Variables& vars,
                  Sensitivity* sens, std::vector<Probe>& probes, Evaluation& e) {
  std::stable_sort(probes.begin(), probes.end(),
                   [](const Probe& a, const Probe& b) { return a.deg < b.deg; });
  std::vector<double> sumSq(spec.targets.size(), 0), largest(spec.targets.size(), 0);
  Kinematics walker = k;
  const std::vector<TransmissionJoint> joints = transmissionJoints(k.mechanism());
  const bool space = isSpatial(k.mechanism());
  for (Probe& p : probes) {
    if (Status s = walker.moveTo(p.deg); !s.ok()) return s;
    const OptTarget& t = spec.targets[p.target];
    const Vec2 at = walker.position(p.point);
    if (t.kind == OptTarget::Kind::Position && space) {
      spacePosition(walker, t, e, p);
    } else if (t.kind == OptTarget::Kind::Position) {
      const Vec2 r = at - t.at;
      e.objective += t.weight * r.squaredNorm();
      e.measures[p.target] = {at.x(), at.y()};
      p.weightOfDp = 2 * t.weight * r;
    } else if (t.kind == OptTarget::Kind::Path) {
      const Vec3 r = pathGap(walker, t, p.index, space).d;
      e.objective += t.weight * r.squaredNorm();
      sumSq[p.target] += r.squaredNorm();
      largest[p.target] = std::max(largest[p.target], r.norm());
      if (space)
        p.weightOfDp3 = 2 * t.weight * r;
      else
        p.weightOfDp = 2 * t.weight * Vec2(r.head<2>());
    }
    if (!sens || vars.dims.empty() ||
        (p.angleWeight == 0 && p.weightOfDp.isZero() && p.weightOfDp3.isZero()))
      continue;
    if (Status s = sens->at(walker); !s.ok()) return s;
    for (size_t v = 0; v < e.gradient.size(); ++v) {
      const int dim = vars.dim[v];
      if (dim < 0) continue;  // a counterweight moves no point
      if (t.kind == OptTarget::Kind::Transmission) {
        double d = 0;
        transmissionAngleSensitivity(walker, joints[t.joint], sens, dim, &d);
        e.gradient[v] += p.angleWeight * d;
      } else if (space) {
        e.gradient[v] += p.weightOfDp3.dot(sens->point3(walker, p.point, dim));
      } else {
        e.gradient[v] += p.weightOfDp.dot(sens->point(walker, p.point, dim));
      }
    }
  }
  for (size_t i = 0; i < spec.targets.size(); ++i)
    if (spec.targets[i].kind == OptTarget::Kind::Path)
      e.measures[i] = {std::sqrt(sumSq[i] / std::max<size_t>(1, spec.targets[i].path.size())),
                       largest[i]};
  return Status::success();
}

// A point whose motion tells whether the design turns fully: the first target's, else the
// first point of a moving body.
PointId turnPoint(const OptimizeSpec& spec, const Mechanism& m) {
  for (const OptTarget& t : spec.targets)
    if (t.point) return t.point;
  for (const Point& p : m.points)
    if (!m.body(p.body)->ground) return p.id;
  return PointId{};
}

}  // namespace

Evaluation evaluate(const Kinematics& base, const OptimizeSpec& spec, const std::vector<double>& x,
                    bool withGradient) {
  Evaluation e;
  Kinematics k;
  if (!solveDesign(base, spec, x, k, e.why)) return e;
  std::vector<Vec3> dirs;
  for (const OptTarget& t : spec.targets)
    dirs.push_back(t.direction ? Vec3(t.direction->normalized())
                   : t.point   ? strokeDirection(base.mechanism(), t.point)
                               : Vec3(0, 1, 0));
  // Every design turns fully: a target read at one angle does not make a locking design good.
  LimitOptions lo;
  lo.steps = std::max(4, spec.steps / 8);
  const PointId turn = turnPoint(spec, base.mechanism());
  if (Limits l = findLimits(
          k, LimitMeasure::alongInSpace(turn, strokeDirection(base.mechanism(), turn)), lo);
      !l.status.ok()) {
    e.why = l.status.message;
    return e;
  }
  std::vector<Probe> probes;
  Sensitivity sens;
  // A point come onto its body's line P0P1 changes how it is measured (along and across): the
  // variables no longer describe the design there, with or without a gradient.
  opt::Variables vars;
  Status ds = opt::mapVariables(base.mechanism(), k.mechanism(), spec, vars);
  if (ds.ok() && withGradient) {
    e.gradient.assign(spec.variables.size(), 0);
    e.peakGradient.assign(spec.variables.size(), 0);
    if (!vars.dims.empty())
      ds = sens.prepare(
          k, vars.dims,
          isSpatial(k.mechanism()) ? Sensitivity::Space::World : Sensitivity::Space::Refuse);
  }
  if (!ds.ok()) {
    e.why = ds.message;
    return e;
  }
  Sensitivity* sp = withGradient ? &sens : nullptr;
  Status s = residuals(k, spec, dirs.data(), vars, x, sp, e, probes);
  if (s.ok()) s = walkProbes(k, spec, vars, sp, probes, e);
  if (!s.ok()) {
    e.why = s.message;
    e.objective = 0;
    return e;
  }
  e.feasible = std::isfinite(e.objective);
  if (!e.feasible) e.why = "the objective is not finite";
  return e;
}

}  // namespace linkage
