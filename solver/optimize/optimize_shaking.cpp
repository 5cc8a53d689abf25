// The shaking force's (or moment's) peak as a target (linkage/optimize.h): the rows a minimax is
// met by.
//
// With counterweights of static moments s_k added (kg mm, in their bodies' drawings, at their
// pivots), the frame feels F = F0 + sum_k (1e-3 (omega_k^2 I - alpha_k perp) R(theta_k) s_k +
// m_k g) (linkage/balance.h; on a machine in space the world's, each counterweight turning in
// its plane: counterweightForcePerMoment): linear in s_k, its gradient exact; the moment adds each
// one's (Shaker::counterweightMoment, the world's 3-vector in space; smooth but where s_k
// is 0). A dimension's is F0's (M0's)
// (linkage/shaking_sensitivity.h). The turn is cut into `steps` intervals; an interval's row is
// its largest |F| (or component): its ends' values, or a local maximum of the samples refined by
// Brent's method on the exact motion where it falls inside the interval. The largest row is the
// continuous peak, and every row moves continuously with the design, so the search's epigraph
// (every row <= t) is smooth where the peak itself has corners.
#include <algorithm>
#include <cmath>

#include "analysis/brent.h"
#include "linkage/dynamics.h"
#include "linkage/force_sensitivity.h"
#include "linkage/shaking_sensitivity.h"
#include "linkage/space.h"
#include "optimize/variables.h"

namespace linkage::opt {

namespace {

// A body's mass acts at its points' mean depth along its plane's normal (SpaceForces), so a
// counterweight written in as its mass is that far from its pivot's depth: `depth` a point's
// depth (or its change).
template <class Depth>
double depthFromPivot(const Mechanism& m, const Counterweight& cw, Depth depth) {
  double sum = 0;
  int n = 0;
  for (const Point& p : m.points)
    if (p.body == cw.body) {
      sum += depth(p);
      ++n;
    }
  return isSpatial(m) && n > 0 ? sum / n - depth(*m.point(cw.pivot)) : 0.0;
}
double depthFromPivotOf(const Mechanism& m, const Counterweight& cw) {
  return depthFromPivot(m, cw, [](const Point& p) { return p.third.value_or(0.0); });
}
double depthFromPivotChange(const Mechanism& m, const Counterweight& cw, const Dimension& d) {
  return depthFromPivot(m, cw, [&](const Point& p) {
    for (const auto& [id, change] : d.depths)
      if (id == p.id) return change;
    return 0.0;
  });
}

struct Shaker {
  const Kinematics& design;
  const OptTarget& t;
  const Variables& vars;
  const std::vector<double>& x;
  // N per kg: a planar machine's in its drawing (gravity's z along its normal changes no force in
  // the plane), a machine in space's in the world.
  Vec3 g = Vec3::Zero();
  std::vector<CounterweightPlacing> placings;  // by counterweight
  std::vector<double> depthFromPivot;          // by counterweight (mm; 0 on a planar machine)
  // By counterweight, by dimension: its body's turn at crank angle 0 (where each design is drawn
  // again, editAtPose), with counterweights and dimensions varied together.
  std::vector<std::vector<double>> turn0;
  // A joint's reaction (OptTarget::Kind::Force) instead of the shaking force, and the
  // counterweights' shares of it (prepared once for the design).
  JointId joint;
  mutable ForceSolver solver;
  CounterweightShares shares;

  // Counterweight c's inertia force with static moment s (N, the world's; linkage/balance.h).
  Vec3 inertia(const Kinematics& k, size_t c, const Vec2& s) const {
    return counterweightForcePerMoment(k, vars.counterweights[c].body, placings[c]) * s;
  }

  // Counterweight c at x, as optimize's variables make it.
  Counterweight placed(size_t c) const {
    Counterweight cw = vars.counterweights[c];
    cw.staticMoment = vars.moment(x, c);
    cw.kg = vars.kg(x, c);
    return cw;
  }
  // A joint's force as the target reads it: a ball rod's (a machine in space) is its tension; a
  // bearing's load out of its plane its normal force or its tilts.
  Vec2 part(const JointReaction& r) const {
    if (t.reaction == OptTarget::Reaction::Normal) return Vec2(r.normalN, 0);
    if (t.reaction == OptTarget::Reaction::Tilt) return r.tiltNm;
    return kindOf(design.mechanism().joints[t.index]).role == Role::Distance ? Vec2(r.axialN, 0)
                                                                             : r.force;
  }
  // What the frame feels (or the joint bears), in the world: a planar machine's z is 0. The
  // shaking moment (OptTarget::moment) as the world's 3-vector, N m (a planar machine's (0, 0,
  // M)).
  Vec3 force(const Kinematics& k) const {
    if (joint) {  // the design's reaction and the counterweights' shares (the forces add)
      Vec2 F = part(solver.compute(k).joints[t.index]);
      for (size_t c = 0; c < vars.counterweights.size(); ++c)
        F += part(shares.at(k, placed(c)).share);
      return Vec3(F.x(), F.y(), 0);
    }
    Vec3 F = Vec3::Zero(), M = Vec3::Zero();
    if (isSpatial(k.mechanism())) {
      shaking(k, F, M);
    } else {
      Vec2 planar;
      shaking(k, planar, M.z());
      F.head<2>() = planar;
    }
    for (size_t c = 0; c < vars.counterweights.size(); ++c) {
      const Vec2 s = vars.moment(x, c);
      F += inertia(k, c, s) + vars.kg(x, c) * g;
      if (t.moment) M += counterweightMoment(k, c, s);
    }
    return t.moment ? M : F;
  }
  // Counterweight c's pivot in the world at its body's depth (where the counterweight written in
  // as the body's mass acts), and the arm r = E R(theta) P s of static moment s (kg mm, in the
  // world).
  Vec3 pivot(const Kinematics& k, size_t c) const {
    return k.motionInSpace(vars.counterweights[c].pivot).position +
           depthFromPivot[c] * placings[c].normal;
  }
  Vec3 arm(const Kinematics& k, size_t c, const Vec2& s) const {
    const CounterweightPlacing& p = placings[c];
    return p.E * Vec2(Rot::of(k.bodyAngle(vars.counterweights[c].body)) * Vec2(p.P * s));
  }
  // Counterweight c's part of the shaking moment (N m, the world's) with static moment s: a point
  // mass m at c = p + r / m bears m g and the inertia force f of counterweightForcePerMoment
  // there; c x (f + m g) = p x (f + m g) + r x g + r x f / m (r x f / m is -1e-3 alpha |s| R
  // along the plane's normal: 0 with s).
  Vec3 counterweightMoment(const Kinematics& k, size_t c, const Vec2& s) const {
    const Vec3 p = pivot(k, c), r = arm(k, c, s), f = inertia(k, c, s);
    const double m = s.norm() / vars.counterweights[c].maxRadiusMm;
    const Vec3 spin = m > 0 ? Vec3(r.cross(f) / m) : Vec3::Zero();
    return (p.cross(f + m * g) + r.cross(g) + spin) / 1000;
  }
  // Its derivative along the unit u of s (in the body's drawing).
  Vec3 counterweightMomentChange(const Kinematics& k, size_t c, const Vec2& s,
                                 const Vec2& u) const {
    const Vec3 p = pivot(k, c), r = arm(k, c, s), f = inertia(k, c, s), dr = arm(k, c, u),
               df = inertia(k, c, u);
    const double R = vars.counterweights[c].maxRadiusMm, n = s.norm(), m = n / R;
    const double dm = n > 0 ? s.dot(u) / (n * R) : 0.0;
    const Vec3 dspin =
        m > 0 ? Vec3((dr.cross(f) + r.cross(df)) / m - r.cross(f) * dm / (m * m)) : Vec3::Zero();
    return (p.cross(df + dm * g) + dr.cross(g) + dspin) / 1000;
  }
  // Counterweight c's force (with `moment`, its moment) per unit of dimension dim: its body's
  // turn, spin and spin's rate change, its pivot moves. Each design is drawn again at crank angle
  // 0, so the counterweight, fixed in the drawing, turns with the body's turn from there.
  Vec3 counterweightChange(const Kinematics& k, const Sensitivity& sens, size_t c, int dim) const {
    const Counterweight& cw = vars.counterweights[c];
    const Vec2 s = vars.moment(x, c);
    const double dTheta = sens.angle(k, cw.body, dim) - turn0[c][dim],
                 dAlpha = sens.angularAcceleration(k, cw.body, dim);
    const Vec3 df =
        counterweightForcePerMomentChange(k, cw.body, placings[c], dTheta,
                                          sens.angularVelocity(k, cw.body, dim), dAlpha) *
        s;
    if (!t.moment) return df;
    const Vec3 n = placings[c].normal, p = pivot(k, c), r = arm(k, c, s), f = inertia(k, c, s);
    const Vec3 dp = sens.point3(k, cw.pivot, dim) +
                    depthFromPivotChange(k.mechanism(), cw, sens.dims()[dim]) * n;
    const Vec3 dr = dTheta * n.cross(r);  // the arm turns with its body in its plane
    const double m = s.norm() / cw.maxRadiusMm;
    const Vec3 dspin = m > 0 ? Vec3((dr.cross(f) + r.cross(df)) / m) : Vec3::Zero();
    return (dp.cross(f + m * g) + p.cross(df) + dr.cross(g) + dspin) / 1000;
  }
  double measure(const Vec3& F) const {
    if (t.measure == BalanceMeasure::Fx) return std::abs(F.x());
    if (t.measure == BalanceMeasure::Fy) return std::abs(F.y());
    if (t.measure == BalanceMeasure::Fz) return std::abs(F.z());
    return F.norm();
  }
  // d measure / d F: the unit the measure is read along (0 where it has no direction).
  Vec3 along(const Vec3& F) const {
    for (int c = 0; c < 3; ++c)
      if (t.measure == (c == 0   ? BalanceMeasure::Fx
                        : c == 1 ? BalanceMeasure::Fy
                                 : BalanceMeasure::Fz))
        return Vec3::Unit(c) * (F[c] < 0 ? -1 : 1);
    return F.norm() > 0 ? Vec3(F / F.norm()) : Vec3::Zero();
  }
  std::vector<double> gradient(const Kinematics& k, const Sensitivity* sens, Status& status) const;
  std::vector<double> reactionGradient(const Kinematics& k, const Vec3& e, Status& status) const;
};

// A reaction's: a dimension moves the design's reaction and each counterweight's share (fixed
// in its body's drawing at crank 0, turn0), a counterweight's moment its own share.
std::vector<double> Shaker::reactionGradient(const Kinematics& k, const Vec3& e,
                                             Status& status) const {
  auto lift = [](const Vec2& v) { return Vec3(v.x(), v.y(), 0); };
  std::vector<double> out(vars.dim.size(), 0.0);
  JointForceSensitivity f;
  std::vector<CounterweightShareChange> moved;
  if (vars.dimensionCount() > 0) {
    f = jointForceSensitivity(k, joint, vars.dims);
    status = f.status;
    for (size_t c = 0; c < vars.counterweights.size() && status.ok(); ++c) {
      moved.push_back(counterweightShareChange(
          k, joint, placed(c), vars.dims, c < turn0.size() ? turn0[c] : std::vector<double>()));
      status = moved.back().status;
    }
  }
  for (size_t v = 0; v < out.size() && status.ok(); ++v) {
    if (vars.dim[v] >= 0) {
      Vec2 d = part(f.change[vars.dim[v]]);
      for (const CounterweightShareChange& s : moved) d += part(s.change[vars.dim[v]]);
      out[v] = e.dot(lift(d));
      continue;
    }
    const CounterweightShare sh = shares.at(k, placed(vars.cw[v]));
    status = sh.status;
    out[v] = e.dot(lift(part(vars.axis[v] == 0 ? sh.perX : sh.perY)));
  }
  return out;
}

// d measure / d variable at k's pose (sens at k's pose when there are dimensions).
std::vector<double> Shaker::gradient(const Kinematics& k, const Sensitivity* sens,
                                     Status& status) const {
  const Vec3 F = force(k), e = along(F);
  auto lift = [](const Vec2& v) { return Vec3(v.x(), v.y(), 0); };
  std::vector<double> out(vars.dim.size(), 0.0);
  if (joint) return reactionGradient(k, e, status);
  const bool space = isSpatial(k.mechanism());
  for (size_t v = 0; v < out.size(); ++v) {
    Vec3 dF = Vec3::Zero();
    if (vars.dim[v] >= 0 && sens) {
      dF = space && t.moment ? shakingMomentSensitivity3(k, *sens, vars.dim[v])
           : space           ? shakingForceSensitivity3(k, *sens, vars.dim[v])
           : t.moment        ? Vec3(0, 0, shakingMomentSensitivity(k, *sens, vars.dim[v]))
                             : lift(shakingForceSensitivity(k, *sens, vars.dim[v]));
      for (size_t c = 0; c < vars.counterweights.size(); ++c)
        dF += counterweightChange(k, *sens, c, vars.dim[v]);
    } else if (vars.cw[v] >= 0) {
      const size_t c = static_cast<size_t>(vars.cw[v]);
      const Counterweight& cw = vars.counterweights[c];
      const Vec2 unit = vars.axis[v] == 0 ? Vec2(1, 0) : Vec2(0, 1);
      const Vec2 s = vars.moment(x, c);
      Vec3 d = inertia(k, c, unit);
      if (s.norm() > 0) d += s.dot(unit) / (s.norm() * cw.maxRadiusMm) * g;  // d(|s| / R)
      dF = t.moment ? counterweightMomentChange(k, c, s, unit) : d;
    }
    out[v] = e.dot(dF);
  }
  return out;
}

// Each counterweight's body's turn per unit of each dimension at crank angle 0.
Status turnsAtZero(const Kinematics& k, const Variables& vars, Sensitivity& sens,
                   std::vector<std::vector<double>>& out) {
  out.clear();
  if (vars.counterweights.empty()) return Status::success();
  Kinematics zero = k;
  if (Status s = zero.moveTo(0); !s.ok()) return s;
  if (Status s = sens.at(zero); !s.ok()) return s;
  for (const Counterweight& c : vars.counterweights) {
    out.emplace_back();
    for (size_t d = 0; d < vars.dims.size(); ++d)
      out.back().push_back(sens.angle(zero, c.body, static_cast<int>(d)));
  }
  return Status::success();
}

struct RowAt {
  double value = -1, deg = 0;
};

// Each interval's largest measure and where: its ends, then the refined local maxima.
Status intervalMaxima(const Shaker& sh, int n, std::vector<RowAt>& rows) {
  Kinematics k = sh.design;
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) {
    if (Status s = k.moveTo(360.0 * i / n); !s.ok()) return s;
    v[i] = sh.measure(sh.force(k));
  }
  rows.assign(n, {});
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    rows[i] = v[i] >= v[j] ? RowAt{v[i], 360.0 * i / n} : RowAt{v[j], 360.0 * (i + 1) / n};
  }
  const double step = 360.0 / n;
  Status status = Status::success();
  for (int i = 0; i < n; ++i) {
    if (v[i] < v[(i + n - 1) % n] || v[i] < v[(i + 1) % n]) continue;
    auto negative = [&](double deg) {
      if (status = k.moveTo(deg); !status.ok()) return 0.0;
      return -sh.measure(sh.force(k));
    };
    double fmin = -v[i];
    const double deg = brent::minimum(negative, step * i - step, step * i + step, 1e-9, &fmin);
    if (!status.ok()) return status;
    RowAt& in = rows[deg >= step * i ? i : (i + n - 1) % n];
    if (-fmin > in.value) in = {-fmin, deg};
  }
  return Status::success();
}

}  // namespace

Status shakingResiduals(const Kinematics& k, const OptimizeSpec& spec, size_t target,
                        const Variables& vars, const std::vector<double>& x, Sensitivity* sens,
                        Evaluation& e) {
  const OptTarget& t = spec.targets[target];
  const Mechanism& m = k.mechanism();
  const Vec2 gPlane = m.gravity.value_or(Vec2::Zero());
  const Vec3 g = isSpatial(m) ? m.gravityWorld() : Vec3(gPlane.x(), gPlane.y(), 0);
  Shaker sh{k, t, vars, x, g, {}, {}, {}, {}, {}, {}};
  for (const Counterweight& c : vars.counterweights) {
    sh.placings.push_back(placeCounterweight(m, c.body));
    sh.depthFromPivot.push_back(depthFromPivotOf(m, c));
  }
  if (sens && !e.gradient.empty() && vars.dimensionCount() > 0)
    if (Status s = turnsAtZero(k, vars, *sens, sh.turn0); !s.ok()) return s;
  if (t.kind == OptTarget::Kind::Force) {
    sh.joint = k.mechanism().joints.at(t.index).id;
    if (Status s = sh.solver.prepare(k); !s.ok()) return s;
    if (!vars.counterweights.empty())
      if (Status s = sh.shares.prepare(k, sh.joint); !s.ok()) return s;
  }
  std::vector<RowAt> rows;
  if (Status s = intervalMaxima(sh, spec.steps, rows); !s.ok()) return s;
  const auto top = std::max_element(
      rows.begin(), rows.end(), [](const RowAt& a, const RowAt& b) { return a.value < b.value; });
  const double r = std::max(0.0, top->value - t.limitN);
  e.objective += t.weight * r * r;
  e.peakObjective += t.weight * r * r;
  e.measures[target] = {top->value, std::fmod(top->deg + 360, 360)};
  Evaluation::PeakRows pr;
  pr.target = target;
  for (const RowAt& row : rows) pr.value.push_back(row.value - t.limitN);
  if (!e.gradient.empty()) {
    // Each row's gradient where it is reached, the walker visiting the angles in order.
    std::vector<size_t> order(rows.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return rows[a].deg < rows[b].deg; });
    pr.gradient.resize(rows.size());
    Kinematics walker = k;
    for (size_t n = 0; n < order.size(); ++n) {
      const size_t i = order[n];
      if (n > 0 && rows[i].deg == rows[order[n - 1]].deg) {  // an end two intervals share
        pr.gradient[i] = pr.gradient[order[n - 1]];
        continue;
      }
      if (Status s = walker.moveTo(rows[i].deg); !s.ok()) return s;
      if (sens && vars.dimensionCount() > 0)
        if (Status s = sens->at(walker); !s.ok()) return s;
      Status status = Status::success();
      pr.gradient[i] = sh.gradient(walker, sens, status);
      if (!status.ok()) return status;
    }
    const std::vector<double>& g = pr.gradient[top - rows.begin()];
    for (size_t v = 0; v < g.size(); ++v) {
      e.gradient[v] += 2 * t.weight * r * g[v];
      e.peakGradient[v] += 2 * t.weight * r * g[v];
    }
  }
  e.peaks.push_back(std::move(pr));
  return Status::success();
}

}  // namespace linkage::opt
