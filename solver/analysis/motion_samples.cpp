#include "linkage/motion_samples.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace linkage {

const PointSamples* MotionSamples::point(PointId id) const {
  for (const PointSamples& p : points)
    if (p.id == id) return &p;
  return nullptr;
}

const BodySamples* MotionSamples::body(BodyId id) const {
  for (const BodySamples& b : bodies)
    if (b.id == id) return &b;
  return nullptr;
}

namespace {

Status bad(std::string msg) {
  return Status::failure(StatusCode::BadModel, std::move(msg));
}

// Every body's pose. At a regular position of a mechanism the driver moves, velocities and
// accelerations follow from the pose (the linear solves have one solution), so equal poses
// mean equal motion: the periodicity test needs nothing more.
std::vector<Transform> poses(const Kinematics& k) {
  std::vector<Transform> out;
  for (const Body& b : k.mechanism().bodies) out.push_back(k.bodyTransform(b.id));
  return out;
}

bool samePoses(const std::vector<Transform>& a, const std::vector<Transform>& b, double L) {
  if (a.size() != b.size()) return false;
  const double tol = 1e-9;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::abs(a[i].R.c - b[i].R.c) > tol || std::abs(a[i].R.s - b[i].R.s) > tol) return false;
    if ((a[i].t - b[i].t).norm() > tol * L) return false;
  }
  return true;
}

double component(const Vec3& v, const Quantity& q, const Vec3& u) {
  switch (q.component) {
    case Quantity::Component::X:
      return v.x();
    case Quantity::Component::Y:
      return v.y();
    case Quantity::Component::Z:
      return v.z();
    case Quantity::Component::Magnitude:
      return v.norm();
    case Quantity::Component::Along:
      return v.dot(u);
    case Quantity::Component::Distance:
      break;  // of two points: distanceRates
  }
  return NAN;
}

// The unit direction of an Along quantity (or +x for the others); false when it has none.
bool unitDirection(const Quantity& q, Vec3& u) {
  u = Vec3(1, 0, 0);
  if (q.component != Quantity::Component::Along) return true;
  const double n = q.direction.norm();
  if (!(n > 0) || !std::isfinite(n)) return false;
  u = q.direction / n;
  return true;
}

// The distance d = |D| between two points and its first two rates, from their relative
// position D, velocity D' and acceleration D'' (Quantity::Component::Distance). Where the
// points meet (d = 0) the rates have no value: false.
bool distanceRates(const Vec3& D, const Vec3& V, const Vec3& A, double out[3]) {
  const double d = D.norm();
  out[0] = d;
  if (!(d > 0)) return false;
  out[1] = D.dot(V) / d;
  out[2] = (V.squaredNorm() + D.dot(A) - out[1] * out[1]) / d;
  return true;
}

Vec3 lift(const Vec2& v) {
  return Vec3(v.x(), v.y(), 0);
}

// Why jerk (or harmonics) cannot be had from these samples, or "" when they can.
std::string periodicProblem(const MotionSamples& s, bool accelerations) {
  if (accelerations && !s.accelerations) return "accelerations were not sampled";
  if (s.size() <= s.steps) return "the crank did not complete a revolution";
  if (!s.periodic) return "the motion does not repeat after one revolution of the crank";
  return "";
}

// One revolution of a periodic curve repeated over all the samples (the sample at 360 * r
// is the one at 0).
std::vector<double> tiled(const std::vector<double>& period, long long rows) {
  std::vector<double> v(rows);
  const long long n = static_cast<long long>(period.size());
  for (long long i = 0; i < rows; ++i) v[i] = period[i % n];
  return v;
}

// The point's motion where k is, in its plane class's frame and (spec.world) in the world.
void addSample(const Kinematics& k, const SampleSpec& spec, PointSamples& p) {
  const Kinematics::PointMotion m = k.motion(p.id);
  p.p.push_back(m.position);
  p.v.push_back(m.velocity);
  if (spec.accelerations) p.a.push_back(m.acceleration);
  if (!spec.world) return;
  const Kinematics::PointMotion3 w = k.motionInSpace(p.id);
  p.p3.push_back(w.position);
  p.v3.push_back(w.velocity);
  if (spec.accelerations) p.a3.push_back(w.acceleration);
}

}  // namespace

MotionSamples sampleMotion(const Kinematics& k, const SampleSpec& spec) {
  MotionSamples s;
  s.kinematics = k;
  s.steps = spec.steps;
  s.revs = spec.revs;
  if (!k.valid()) {
    s.status = bad("no mechanism is solved");
    return s;
  }
  const double total = static_cast<double>(spec.steps) * spec.revs;
  if (!(spec.steps > 0 && spec.revs > 0 && std::isfinite(total)) ||
      std::abs(total - std::round(total)) > 1e-9 * std::max(1.0, total)) {
    s.status = bad("steps per revolution times revolutions must be a positive whole number");
    return s;
  }
  for (PointId p : spec.points)
    if (!k.contains(p)) {
      s.status = bad("a point the mechanism does not hold");
      return s;
    }
  for (BodyId b : spec.bodies)
    if (!k.contains(b)) {
      s.status = bad("a body the mechanism does not hold");
      return s;
    }
  if (Status d = k.checkDetermined(spec.points); !d.ok()) {
    s.status = d;
    return s;
  }

  Kinematics& kk = s.kinematics;
  if (spec.rpm > 0) kk.setRpm(spec.rpm);
  kk.setAccelerations(spec.accelerations);
  s.rpm = kk.rpm();
  s.omega = kk.omega();
  s.accelerations = spec.accelerations;
  s.world = spec.world;
  const long long rows = static_cast<long long>(std::round(total)) + 1;
  for (PointId p : spec.points) s.points.push_back({p, {}, {}, {}, {}, {}, {}});
  for (BodyId b : spec.bodies) s.bodies.push_back({b, {}, {}, {}});
  auto reserve = [rows](auto& v) { v.reserve(rows); };
  reserve(s.crankDeg);
  for (PointSamples& p : s.points) {
    reserve(p.p);
    reserve(p.v);
    if (spec.accelerations) reserve(p.a);
  }

  std::vector<Transform> start;
  for (long long i = 0; i < rows; ++i) {
    // Angles from the index, as the motion table's, so the last is exactly 360 * revs.
    const double deg = static_cast<double>(i) * 360.0 / static_cast<double>(spec.steps);
    // A singular position comes back as Singular: velocities are not determined there.
    const Status st = kk.moveTo(deg);
    if (!st.ok()) {
      s.status = st;
      break;
    }
    s.crankDeg.push_back(deg);
    for (PointSamples& p : s.points) addSample(kk, spec, p);
    for (BodySamples& b : s.bodies) {
      b.angle.push_back(kk.bodyAngle(b.id));
      b.omega.push_back(kk.bodyOmega(b.id));
      if (spec.accelerations) b.alpha.push_back(kk.bodyAlpha(b.id));
    }
    if (i == 0) start = poses(kk);
    if (i == spec.steps) s.periodic = samePoses(start, poses(kk), kk.size());
  }
  return s;
}

namespace {

// Sample i of a point's position (order 0), velocity (1) or acceleration (2), in the world or
// in its plane class's frame.
Vec3 sampled(const PointSamples& p, bool world, int order, long long i) {
  if (world) {
    const std::vector<Vec3>* v[] = {&p.p3, &p.v3, &p.a3};
    return (*v[order])[i];
  }
  const std::vector<Vec2>* v[] = {&p.p, &p.v, &p.a};
  return lift((*v[order])[i]);
}

// The distance between q's two points, order by order (the jerk: the spectral derivative of
// its exact acceleration over one revolution).
void distanceCurve(const MotionSamples& s, const Quantity& q, Order order, Curve& c) {
  const PointSamples *a = s.point(q.point), *b = s.point(q.other);
  if (!a || !b) {
    c.status = bad("the second point of the distance was not sampled");
    return;
  }
  const bool world = q.inWorld();
  const int o = std::min(static_cast<int>(order), 2);
  std::vector<double> values;
  values.reserve(s.size());
  for (long long i = 0; i < s.size(); ++i) {
    Vec3 rel[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    for (int k = 0; k <= o; ++k) rel[k] = sampled(*a, world, k, i) - sampled(*b, world, k, i);
    double d[3];
    if (!distanceRates(rel[0], rel[1], rel[2], d) && o > 0) {
      c.status = bad("the points meet at " + std::to_string(s.crankDeg[i]) +
                     " degrees: the distance has no rate there");
      return;
    }
    values.push_back(d[o]);
  }
  if (order != Order::Jerk) {
    c.values = std::move(values);
    return;
  }
  const long long n = s.steps;
  Derivative j = periodicDerivative({values.begin(), values.begin() + n});
  for (double& x : j.values) x *= s.omega;
  c.values = tiled(j.values, s.size());
  c.errorEstimate = j.errorEstimate * s.omega;
}

// A point's position, velocity and acceleration where k is, in the world or in its plane
// class's frame.
std::array<Vec3, 3> motionOf(const Kinematics& k, PointId p, bool world) {
  if (world) {
    const Kinematics::PointMotion3 m = k.motionInSpace(p);
    return {m.position, m.velocity, m.acceleration};
  }
  const Kinematics::PointMotion m = k.motion(p);
  return {lift(m.position), lift(m.velocity), lift(m.acceleration)};
}

}  // namespace

Curve curveOf(const MotionSamples& s, const Quantity& q, Order order) {
  Curve c;
  c.crankDeg = s.crankDeg;
  Vec3 u;
  if (!unitDirection(q, u)) {
    c.status = bad("the direction of the component has no length");
    return c;
  }
  const int o = static_cast<int>(order);
  if (o >= 2 && !s.accelerations) {
    c.status = bad("accelerations were not sampled");
    return c;
  }
  std::string problem = order == Order::Jerk ? periodicProblem(s, true) : "";
  if (!problem.empty()) {
    c.status = bad("no jerk: " + problem);
    return c;
  }
  const long long n = s.steps;
  if (q.isBody()) {
    const BodySamples* b = s.body(q.body);
    if (!b) {
      c.status = bad("the body was not sampled");
      return c;
    }
    const std::vector<double>* v[] = {&b->angle, &b->omega, &b->alpha};
    if (order != Order::Jerk) {
      c.values = *v[o];
      return c;
    }
    Derivative d = periodicDerivative({b->alpha.begin(), b->alpha.begin() + n});
    for (double& x : d.values) x *= s.omega;
    c.values = tiled(d.values, s.size());
    c.errorEstimate = d.errorEstimate * s.omega;
    return c;
  }
  const PointSamples* p = s.point(q.point);
  if (!p) {
    c.status = bad("the point was not sampled");
    return c;
  }
  if (q.inWorld() && !s.world) {
    c.status = bad("the point's motion in the world was not sampled");
    return c;
  }
  if (q.component == Quantity::Component::Distance) {
    distanceCurve(s, q, order, c);
    return c;
  }
  std::vector<Vec3> vectors;
  if (order != Order::Jerk && q.inWorld()) {
    const std::vector<Vec3>* v[] = {&p->p3, &p->v3, &p->a3};
    vectors = *v[o];
  } else if (order != Order::Jerk) {
    const std::vector<Vec2>* v[] = {&p->p, &p->v, &p->a};
    for (const Vec2& x : *v[o]) vectors.emplace_back(x.x(), x.y(), 0);
  } else {
    // The jerk vector: the spectral derivative of each component of the acceleration.
    std::vector<double> a[3] = {std::vector<double>(n), std::vector<double>(n),
                                std::vector<double>(n, 0.0)};
    for (long long i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k)
        if (q.inWorld())
          a[k][i] = p->a3[i][k];
        else if (k < 2)
          a[k][i] = p->a[i][k];
    const Derivative j[3] = {periodicDerivative(a[0]), periodicDerivative(a[1]),
                             periodicDerivative(a[2])};
    vectors.resize(s.size());
    for (long long i = 0; i < s.size(); ++i)
      vectors[i] = s.omega * Vec3(j[0].values[i % n], j[1].values[i % n], j[2].values[i % n]);
    // Every component is a combination of the three with weights of at most 1 in size.
    c.errorEstimate = s.omega * (j[0].errorEstimate + j[1].errorEstimate + j[2].errorEstimate);
  }
  c.values.reserve(vectors.size());
  for (const Vec3& v : vectors) c.values.push_back(component(v, q, u));
  return c;
}

double valueAt(const Kinematics& k, const Quantity& q, Order order) {
  Vec3 u;
  if (!unitDirection(q, u) || order == Order::Jerk) return NAN;
  if (q.isBody()) {
    switch (order) {
      case Order::Position:
        return k.bodyAngle(q.body);
      case Order::Velocity:
        return k.bodyOmega(q.body);
      default:
        return k.bodyAlpha(q.body);
    }
  }
  const std::array<Vec3, 3> v = motionOf(k, q.point, q.inWorld());
  if (q.component != Quantity::Component::Distance)
    return component(v[static_cast<int>(order)], q, u);
  if (!k.contains(q.other)) return NAN;
  const std::array<Vec3, 3> w = motionOf(k, q.other, q.inWorld());
  double d[3];
  const bool rates = distanceRates(v[0] - w[0], v[1] - w[1], v[2] - w[2], d);
  return order == Order::Position || rates ? d[static_cast<int>(order)] : NAN;
}

Spectrum harmonicsOf(const MotionSamples& s, const Quantity& q, Order order, int maxK,
                     Status* why) {
  auto fail = [&](std::string msg) {
    if (why) *why = bad("no harmonics: " + msg);
    return Spectrum{};
  };
  const std::string problem = periodicProblem(s, order >= Order::Acceleration);
  if (!problem.empty()) return fail(problem);
  Curve c = curveOf(s, q, order);
  if (!c.status.ok()) return fail(c.status.message);
  const long long n = s.steps;
  std::vector<double> period(c.values.begin(), c.values.begin() + n);
  if (q.isBody() && order == Order::Position) {
    // Whole turns per revolution, spread evenly: the steady part of the angle.
    const double drift = c.values[n] - c.values[0];
    for (long long i = 0; i < n; ++i)
      period[i] -= drift * static_cast<double>(i) / static_cast<double>(n);
  }
  if (why) *why = Status::success();
  return harmonics(period, maxK);
}

}  // namespace linkage
