// Counterweights balancing the shaking force: see linkage/balance.h.
#include "linkage/balance.h"
#include "linkage/space.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "analysis/brent.h"
#include "analysis/chebyshev_lp.h"
#include "linkage/dynamics.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

// The shaking force at one crank angle in the world, and what each counterweight adds to it:
// F = F0 + sum (A_k s_k + m_k g), A_k = 1e-3 E_k (omega^2 I - alpha perp) R(theta) P_k (N per
// kg mm) for a point mass turning about a fixed pivot with its body, g its weight per kg (the
// shaking force is sum m (g - a): a mass at rest on the frame adds m g). The body turns in its
// plane class's frame: P_k turns its plane's coordinates (where s_k is) into that frame, E_k
// lifts that frame's x and y into the world (3 x 2: its axes); a planar machine's are I and
// the drawing's (x, y, 0), so its A_k is the planar one with a row of zeros.
using Lift = Eigen::Matrix<double, 3, 2>;
struct Sample {
  double deg = 0;
  Vec3 F0 = Vec3::Zero();
  std::vector<Lift> A;
};

// Where a peak is, and the force there.
struct Peak {
  double value = 0, deg = 0;
  Vec3 F = Vec3::Zero();
};

using Placing = CounterweightPlacing;

class Balancer {
 public:
  Balancer(const Kinematics& k, const BalanceOptions& opt) : work_(k), opt_(opt) {
    work_.setAccelerations(true);  // an editor may have them off while no view shows them
  }

  BalanceResult run();

 private:
  bool pivots(BalanceResult& r);
  bool refused(BalanceResult& r) const;
  double forceScale() const;
  void place();
  bool sampleAt(double deg, Sample& s, Status& status);
  Vec3 force(const Sample& s, const std::vector<double>& x) const;
  // The measure of F; with `along`, |F . along| instead.
  double measure(const Vec3& F, const Vec3* along = nullptr) const;
  // Every local maximum of the measure (or of |F . along|) over the cycle for static moments
  // x, refined; the highest first.
  std::vector<Peak> peaks(const std::vector<double>& x, Status& status,
                          const Vec3* along = nullptr);
  void addRows(ChebyshevLP& lp, const Sample& s, const Vec3& F);
  void addTangent(ChebyshevLP& lp, int k, const Vec2& d);
  bool cutsAdded(ChebyshevLP& lp, const std::vector<double>& x);
  bool solve(ChebyshevLP& lp, std::vector<double>& x, BalanceResult& r);
  bool exchange(ChebyshevLP& lp, std::vector<double>& x, BalanceResult& r);
  void finish(std::vector<double>& x, BalanceResult& r);
  void unreached(const std::vector<double>& x, BalanceResult& r);

  Kinematics work_;
  const BalanceOptions& opt_;
  bool space_ = false;             // a machine in space: the force in 3D
  Vec3 g_ = Vec3::Zero();          // N per kg of counterweight: its weight on the frame
  bool weighs_ = false;            // the weight enters the measure (its part that counts)
  std::vector<double> maxRadius_;  // mm, each counterweight's R
  std::vector<Placing> placing_;   // each counterweight's body in the world
  std::vector<Sample> samples_;
};

// Each counterweight's unknowns: its static moment (kg mm) and its mass (kg), then t.
constexpr int kUnknowns = 3;
int sx(int k) {
  return kUnknowns * k;
}
int kgOf(int k) {
  return kUnknowns * k + 2;
}
Vec2 momentOf(const std::vector<double>& x, int k) {
  return Vec2(x[sx(k)], x[sx(k) + 1]);
}

}  // namespace

CounterweightPlacing placeCounterweight(const Mechanism& m, BodyId b) {
  const PlaneClasses pc = planeClasses(m);
  const PlaneInClass& in = pc.of(m.body(b)->plane);
  const Plane& f = pc.frames[in.cls];
  CounterweightPlacing p;
  p.E.col(0) = f.xAxis;
  p.E.col(1) = f.yAxis;
  p.normal = f.normal();
  p.turned = !in.identity;
  if (p.turned) p.P << in.rot.c, -in.rot.s, in.rot.s, in.rot.c;
  return p;
}

namespace {

// omega^2 I - alpha perp, and R(theta) as a matrix.
Eigen::Matrix2d spin(double w, double al) {
  Eigen::Matrix2d M;
  M << w * w, al, -al, w * w;
  return M;
}
Eigen::Matrix2d turn(double theta) {
  const Rot R = Rot::of(theta);
  Eigen::Matrix2d Rm;
  Rm << R.c, -R.s, R.s, R.c;
  return Rm;
}
Eigen::Matrix<double, 3, 2> lifted(const CounterweightPlacing& p, const Eigen::Matrix2d& A) {
  return p.E * (p.turned ? Eigen::Matrix2d(1e-3 * A * p.P) : Eigen::Matrix2d(1e-3 * A));
}

}  // namespace

Eigen::Matrix<double, 3, 2> counterweightForcePerMoment(const Kinematics& k, BodyId b,
                                                        const CounterweightPlacing& p) {
  return lifted(p, spin(k.bodyOmega(b), k.bodyAlpha(b)) * turn(k.bodyAngle(b)));
}

Eigen::Matrix<double, 3, 2> counterweightForcePerMomentChange(const Kinematics& k, BodyId b,
                                                              const CounterweightPlacing& p,
                                                              double dTheta, double dOmega,
                                                              double dAlpha) {
  const double w = k.bodyOmega(b);
  Eigen::Matrix2d dM;
  dM << 2 * w * dOmega, dAlpha, -dAlpha, 2 * w * dOmega;
  Eigen::Matrix2d perp;
  perp << 0, -1, 1, 0;
  const Eigen::Matrix2d R = turn(k.bodyAngle(b));
  return lifted(p, dM * R + spin(w, k.bodyAlpha(b)) * R * perp * dTheta);
}

Status counterweightOn(const Mechanism& m, BodyId b, Counterweight& c) {
  const Body* g = m.ground();
  const Body* body = m.body(b);
  if (!body || body->ground) return Status::badModel("a counterweight goes on a moving body");
  c = Counterweight{};
  c.body = b;
  for (const Joint& j : m.joints) {
    if (kindOf(j).role != Role::Revolute) continue;
    const Point *a = m.point(j.a), *o = m.point(j.b);
    if (a->body == b && o->body == g->id) c.pivot = j.a;
    if (o->body == b && a->body == g->id) c.pivot = j.b;
    if (c.pivot) break;
  }
  if (!c.pivot)
    return Status::badModel("body '" + body->name +
                            "' is not pinned to the ground: a counterweight's static moment is "
                            "measured from that pivot");
  const Vec2 at = m.point(c.pivot)->pos;
  auto reach = [&](const Vec2& p) { c.maxRadiusMm = std::max(c.maxRadiusMm, (p - at).norm()); };
  for (const Point& p : m.points)
    if (p.body == b) reach(p.pos);
  for (const Slot& sl : m.slots)
    if (sl.body == b) {
      reach(sl.p0);
      reach(sl.p1);
      if (sl.mid) reach(*sl.mid);
    }
  if (!(c.maxRadiusMm > 1e-9)) c.maxRadiusMm = 20;
  return Status::success();
}

namespace {

bool Balancer::pivots(BalanceResult& r) {
  for (BodyId b : opt_.bodies) {
    for (const Counterweight& c : r.counterweights)
      if (c.body == b) {
        r.status =
            Status::badModel("body '" + work_.mechanism().body(b)->name + "' is given twice");
        return false;
      }
    Counterweight c;
    if (r.status = counterweightOn(work_.mechanism(), b, c); !r.status.ok()) return false;
    r.counterweights.push_back(c);
  }
  return true;
}

// Each counterweight's body's plane class in the world (a planar machine: the drawing's).
void Balancer::place() {
  for (BodyId b : opt_.bodies) placing_.push_back(placeCounterweight(work_.mechanism(), b));
}

bool Balancer::sampleAt(double deg, Sample& s, Status& status) {
  if (status = work_.moveTo(deg); !status.ok()) return false;
  Vec3 moment;
  shaking(work_, s.F0, moment);
  s.deg = deg;
  s.A.clear();
  for (size_t k = 0; k < opt_.bodies.size(); ++k)
    s.A.push_back(counterweightForcePerMoment(work_, opt_.bodies[k], placing_[k]));
  return s.F0.allFinite();
}

Vec3 Balancer::force(const Sample& s, const std::vector<double>& x) const {
  Vec3 F = s.F0;
  for (size_t k = 0; k < s.A.size(); ++k)
    F += s.A[k] * momentOf(x, static_cast<int>(k)) + x[kgOf(static_cast<int>(k))] * g_;
  return F;
}

double Balancer::measure(const Vec3& F, const Vec3* along) const {
  if (along) return std::abs(F.dot(*along));
  switch (opt_.measure) {
    case BalanceMeasure::Fx:
      return std::abs(F.x());
    case BalanceMeasure::Fy:
      return std::abs(F.y());
    case BalanceMeasure::Fz:
      return std::abs(F.z());
    case BalanceMeasure::Force:
      break;
  }
  // A planar machine's force in its plane (a gz's weight is along the normal, constant).
  return space_ ? F.norm() : F.head<2>().norm();
}

// The samples' local maxima, each refined by Brent's method between its neighbours on the exact
// motion.
std::vector<Peak> Balancer::peaks(const std::vector<double>& x, Status& status, const Vec3* along) {
  const int n = static_cast<int>(samples_.size());
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = measure(force(samples_[i], x), along);
  std::vector<Peak> out;
  const double step = 360.0 / n;
  Sample s;
  for (int i = 0; i < n; ++i) {
    const double prev = v[(i + n - 1) % n], next = v[(i + 1) % n];
    if (v[i] < prev || v[i] < next) continue;
    auto negative = [&](double deg) {
      return sampleAt(deg, s, status) ? -measure(force(s, x), along) : 0.0;
    };
    double fmin = -v[i];
    const double deg =
        brent::minimum(negative, samples_[i].deg - step, samples_[i].deg + step, 1e-9, &fmin);
    if (!status.ok() || !sampleAt(deg, s, status)) return out;
    out.push_back({measure(force(s, x), along), deg, force(s, x)});
  }
  std::sort(out.begin(), out.end(), [](const Peak& a, const Peak& b) { return a.value > b.value; });
  return out;
}

// Unit directions e with e . F <= |F|: for |F| <= t, rows e . F <= t that contain the ball (the
// programme stays a relaxation). In the plane 8 evenly; in space the 6 axes' and the 8 cube
// corners' (the exchange adds F's own direction at each peak: a tangent of the ball there).
std::vector<Vec3> startDirections(bool space) {
  std::vector<Vec3> dirs;
  if (!space) {
    for (int j = 0; j < 8; ++j)
      dirs.push_back(Vec3(std::cos(j * M_PI / 4), std::sin(j * M_PI / 4), 0));
    return dirs;
  }
  for (int a = 0; a < 3; ++a)
    for (double sign : {1.0, -1.0}) dirs.push_back(sign * Vec3::Unit(a));
  for (int c = 0; c < 8; ++c)
    dirs.push_back(Vec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1) / std::sqrt(3.0));
  return dirs;
}

// The rows a sample gives: its component either way, or |F| <= t along directions (the start's,
// or F's own when given: in the plane, its part in the plane).
void Balancer::addRows(ChebyshevLP& lp, const Sample& s, const Vec3& F) {
  std::vector<Vec3> dirs;
  if (opt_.measure == BalanceMeasure::Fx) dirs = {Vec3(1, 0, 0), Vec3(-1, 0, 0)};
  if (opt_.measure == BalanceMeasure::Fy) dirs = {Vec3(0, 1, 0), Vec3(0, -1, 0)};
  if (opt_.measure == BalanceMeasure::Fz) dirs = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
  if (opt_.measure == BalanceMeasure::Force) {
    const Vec3 own = space_ ? F : Vec3(F.x(), F.y(), 0);
    dirs = own.norm() > 0 ? std::vector<Vec3>{own.normalized()} : startDirections(space_);
  }
  std::vector<double> c(kUnknowns * s.A.size());
  for (const Vec3& e : dirs) {
    for (size_t k = 0; k < s.A.size(); ++k) {
      const Vec2 a = s.A[k].transpose() * e;
      const int i = static_cast<int>(k);
      c[sx(i)] = a.x();
      c[sx(i) + 1] = a.y();
      c[kgOf(i)] = e.dot(g_);
    }
    lp.addRow(c.data(), -e.dot(s.F0));
  }
}

// d . s_k <= R_k m_k: a tangent of the cone |s_k| <= R_k m_k, which contains it (so the
// programme stays a relaxation, its optimum a lower bound).
void Balancer::addTangent(ChebyshevLP& lp, int k, const Vec2& d) {
  lp.addLimit({{sx(k), d.x()}, {sx(k) + 1, d.y()}, {kgOf(k), -maxRadius_[k]}}, 0);
}

// The cone's and the bound's tangents where the solution leaves them by more than the programme
// can resolve (CLP keeps rows to its primal tolerance, 1e-11 absolute: asking for less added
// the same tangent again at every round until the round limit). True when one was added.
bool Balancer::cutsAdded(ChebyshevLP& lp, const std::vector<double>& x) {
  bool added = false;
  for (int k = 0; k < static_cast<int>(opt_.bodies.size()); ++k) {
    const Vec2 s = momentOf(x, k);
    const double slack = std::max(opt_.tolerance * s.norm(), 1e-10);
    if (opt_.maxKgMm && s.norm() - *opt_.maxKgMm > slack) {
      lp.addLimit({{sx(k), s.normalized().x()}, {sx(k) + 1, s.normalized().y()}}, *opt_.maxKgMm);
      added = true;
    }
    // Without gravity the mass is set from the moment at the end: only the moment counts.
    if (weighs_ && s.norm() - maxRadius_[k] * x[kgOf(k)] > slack) {
      addTangent(lp, k, s.normalized());
      added = true;
    }
  }
  return added;
}

// The programme's optimum, and of its solutions the lightest where the mass is free (the weight
// across the measured component): a vertex's mass would be arbitrary. So in space, where a
// counterweight may not reach the measured part at all (fx, and a counterweight turning in a
// plane of normal x): its static moment would be arbitrary, and the lightest is none.
bool Balancer::solve(ChebyshevLP& lp, std::vector<double>& x, BalanceResult& r) {
  double t = 0;
  if (!lp.solve(x, t)) {
    r.status = Status::failure(StatusCode::NotConverged, "the linear programme has no optimum");
    return false;
  }
  r.lowerBound = t;
  if (weighs_ || space_) {
    std::vector<double> w(x.size(), 0.0);
    for (int k = 0; k < static_cast<int>(opt_.bodies.size()); ++k) w[kgOf(k)] = 1;
    lp.solveLeast(w, t, x);
  }
  return true;
}

// Solves, finds the true peak and the cone's and bounds' violations, adds them; true when they
// agree.
bool Balancer::exchange(ChebyshevLP& lp, std::vector<double>& x, BalanceResult& r) {
  if (!solve(lp, x, r)) return true;
  bool done = !cutsAdded(lp, x);
  const std::vector<Peak> found = peaks(x, r.status);
  if (!r.status.ok() || found.empty()) return true;
  // Every peak above the programme's optimum joins it (its exact angle, and direction for |F|).
  const double tol = opt_.tolerance * std::max(r.peakBefore, 1e-300);
  for (const Peak& p : found) {
    if (p.value - r.lowerBound <= tol) break;
    Sample s;
    if (!sampleAt(p.deg, s, r.status)) return true;
    addRows(lp, s, p.F);
    done = false;
  }
  return done;
}

}  // namespace

double Counterweight::angleDeg() const {
  return std::atan2(staticMoment.y(), staticMoment.x()) / kDeg;
}

BalanceResult Balancer::run() {
  BalanceResult r;
  if (!work_.valid()) {
    r.status = Status::badModel("no mechanism is loaded");
    return r;
  }
  if (opt_.bodies.empty() || opt_.steps < 8 || (opt_.maxKgMm && !(*opt_.maxKgMm >= 0))) {
    r.status = Status::badModel(opt_.bodies.empty() ? "no counterweight to place"
                                : opt_.steps < 8    ? "at least 8 steps a turn"
                                                    : "the bound must be a number >= 0");
    return r;
  }
  space_ = isSpatial(work_.mechanism());
  if (refused(r) || !pivots(r)) return r;
  for (const Counterweight& c : r.counterweights) maxRadius_.push_back(c.maxRadiusMm);
  place();
  g_ = work_.mechanism().gravityWorld();
  // A planar machine's measures are in its plane: the weight along its normal (a gz) is not.
  weighs_ = (space_ ? g_ : Vec3(g_.x(), g_.y(), 0)).norm() > 0;
  samples_.resize(opt_.steps);
  for (int i = 0; i < opt_.steps; ++i)
    if (!sampleAt(360.0 * i / opt_.steps, samples_[i], r.status)) return r;
  const int n = static_cast<int>(opt_.bodies.size());
  std::vector<double> x(kUnknowns * n, 0.0);
  const std::vector<Peak> before = peaks(x, r.status);
  if (!r.status.ok() || before.empty()) return r;
  r.peakBefore = before[0].value;
  r.peakBeforeDeg = before[0].deg;
  if (!(r.peakBefore > 1e-12 * forceScale())) {
    // Nothing shakes (no mass, or none whose centre moves: rounding next to what the masses
    // could do): no counterweight is the answer, and no gap relative to nothing would close.
    r.peakBefore = r.peakAfter = 0;
    unreached(x, r);
    return r;
  }
  ChebyshevLP lp(kUnknowns * n);
  // The first programme on at most 360 of the samples: the exchange adds every peak above its
  // optimum (the samples' local maxima, refined on the exact motion) until none is left, so the
  // answer and its certificate are the same, and the simplex works on hundreds of rows, not
  // thousands (3,600 samples: 7,200 rows for fx, most of the time).
  const int stride = std::max(1, opt_.steps / 360);
  for (int i = 0; i < opt_.steps; i += stride)
    addRows(lp, samples_[i], opt_.measure == BalanceMeasure::Force ? Vec3::Zero() : samples_[i].F0);
  for (int k = 0; k < n; ++k) {
    lp.setLowerBound(kgOf(k), 0);
    for (int j = 0; j < 16; ++j) {
      const Vec2 d(std::cos(j * M_PI / 8), std::sin(j * M_PI / 8));
      addTangent(lp, k, d);
      if (opt_.maxKgMm) lp.addLimit({{sx(k), d.x()}, {sx(k) + 1, d.y()}}, *opt_.maxKgMm);
    }
  }
  for (r.exchanges = 1; r.exchanges <= 200; ++r.exchanges)
    if (exchange(lp, x, r)) break;
  r.angles = lp.rows();
  if (r.status.ok()) finish(x, r);
  return r;
}

// The counterweights put exactly inside their bounds (the tangent rows let them out by the
// programme's tolerance), and the peak they leave found for them as they will be applied.
void Balancer::finish(std::vector<double>& x, BalanceResult& r) {
  for (int k = 0; k < static_cast<int>(r.counterweights.size()); ++k) {
    Vec2 s = momentOf(x, k);
    if (opt_.maxKgMm && s.norm() > *opt_.maxKgMm) s *= *opt_.maxKgMm / s.norm();
    // Without gravity the mass does not enter: the lightest, at the farthest radius.
    const double least = s.norm() / maxRadius_[k];
    double kg = weighs_ ? std::max(x[kgOf(k)], least) : least;
    x[sx(k)] = s.x();
    x[sx(k) + 1] = s.y();
    x[kgOf(k)] = kg;
    r.counterweights[k].staticMoment = s;
    r.counterweights[k].kg = kg;
  }
  const std::vector<Peak> found = peaks(x, r.status);
  if (!r.status.ok() || found.empty()) return;
  r.peakAfter = found[0].value;
  r.peakAfterDeg = found[0].deg;
  unreached(x, r);
}

// What the masses and loads could shake the frame with (N): each moving mass's weight and its
// inertia turning at the driver's speed at the mechanism's size, and the loads' forces.
double Balancer::forceScale() const {
  const Mechanism& m = work_.mechanism();
  const double w = work_.omega(), reach = g_.norm() + w * w * work_.size() / 1000;
  double scale = 0;
  for (const Body& b : m.bodies)
    if (!b.ground && b.mass) scale += b.mass->kg * reach;
  for (const Load& l : m.loads) scale += l.forceN.norm();
  return scale;
}

// A planar machine's fz: the weight along the drawing's normal, constant, which no counterweight
// turning in the plane changes but by its own weight: nothing to balance.
bool Balancer::refused(BalanceResult& r) const {
  if (space_ || opt_.measure != BalanceMeasure::Fz) return false;
  r.status = Status::badModel(
      "fz is the shaking force along the drawing's normal: a planar machine has none but the "
      "weight along it (gravity's z), constant, which no counterweight turning in the plane "
      "lowers");
  return true;
}

// Every counterweight turns in its body's plane: where those planes are all parallel, the
// shaking force along their normal is beyond the counterweights' turning (only their weight
// reaches it, one way). Its peak before and as the counterweights leave it.
void Balancer::unreached(const std::vector<double>& x, BalanceResult& r) {
  const Vec3 n = placing_[0].normal;
  for (const Placing& p : placing_)
    if (p.normal.cross(n).norm() > 1e-9) return;  // planes that span space: all within reach
  r.unreached = n;
  // A constant |F . n| (a planar machine's weight along its normal, or none) is read off the
  // samples: every one of them would be a local maximum to refine.
  auto peakAlong = [&](const std::vector<double>& at, Peak& out) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Sample& s : samples_) {
      const double v = measure(force(s, at), &n);
      lo = std::min(lo, v);
      if (v > hi) hi = v, out = {v, s.deg, force(s, at)};
    }
    if (hi - lo <= 1e-12 * std::max(hi, r.peakBefore)) return true;
    const std::vector<Peak> found = peaks(at, r.status, &n);
    if (!r.status.ok() || found.empty()) return false;
    out = found[0];
    return true;
  };
  Peak after, before;
  if (!peakAlong(x, after) || !peakAlong(std::vector<double>(x.size(), 0.0), before)) return;
  r.unreachedPeak = after.value;
  r.unreachedPeakDeg = after.deg;
  r.unreachedPeakBefore = before.value;
}

BalanceResult balanceShaking(const Kinematics& k, const BalanceOptions& opt) {
  return Balancer(k, opt).run();
}

void addCounterweights(Mechanism& m, const std::vector<Counterweight>& cws) {
  for (const Counterweight& c : cws) {
    Body* b = m.body(c.body);
    const Point* pivot = m.point(c.pivot);
    if (!b || !pivot || !(c.kg > 0)) continue;
    const double mc = c.kg;
    const Vec2 at = pivot->pos + c.staticMoment / mc;
    Mass mass = b->mass.value_or(Mass{});
    const double total = mass.kg + mc;
    const Vec2 com = (mass.kg * mass.com + mc * at) / total;
    mass.jKgMm2 += mass.kg * (mass.com - com).squaredNorm() + mc * (at - com).squaredNorm();
    mass.kg = total;
    mass.com = com;
    mass.counterweights.push_back({mc, at});
    b->mass = mass;
  }
}

}  // namespace linkage
