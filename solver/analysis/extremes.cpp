#include "linkage/extremes.h"

#include <algorithm>
#include <cmath>

#include "analysis/brent.h"

namespace linkage {

namespace {

// The solver moved to any crank angle near the samples: the exact value of the quantity and of
// its derivative there.
class Probe {
 public:
  Probe(const Kinematics& k, const Quantity& q, Order o) : k_(k), q_(q), o_(o) {
    k_.setAccelerations(true);
  }
  bool ok() const { return ok_; }
  double crankDeg() const { return k_.crankDeg(); }
  // A failed move leaves the solver where it got to; the next extreme may still be reachable.
  void reset() { ok_ = true; }
  double value(double deg) { return moveTo(deg) ? valueAt(k_, q_, o_) : NAN; }
  // d(value)/d(crank angle) up to a positive factor: the next order's component, or for a
  // magnitude |w|, w . w' (a zero of it is a zero of d|w|).
  double slope(double deg) {
    if (!moveTo(deg)) return NAN;
    const Order next = static_cast<Order>(static_cast<int>(o_) + 1);
    if (q_.isBody() || q_.component != Quantity::Component::Magnitude) return valueAt(k_, q_, next);
    if (q_.inWorld()) {
      const Kinematics::PointMotion3 m = k_.motionInSpace(q_.point);
      return o_ == Order::Position ? m.position.dot(m.velocity) : m.velocity.dot(m.acceleration);
    }
    const Kinematics::PointMotion m = k_.motion(q_.point);
    return o_ == Order::Position ? m.position.dot(m.velocity) : m.velocity.dot(m.acceleration);
  }

 private:
  bool moveTo(double deg) {
    ok_ = ok_ && k_.moveTo(deg).ok() && k_.derivativesValid();
    return ok_;
  }
  Kinematics k_;
  const Quantity& q_;
  Order o_;
  bool ok_ = true;
};

// Places the extreme (sign +1: a maximum, -1: a minimum) found at sample i between its
// neighbours, a step of h degrees either side.
Extreme refine(Probe& probe, Order o, double sign, double at, double sampled, double h) {
  Extreme e{at, sampled, Extreme::Method::Sample};
  if (o == Order::Jerk) return e;
  probe.reset();
  if (o == Order::Acceleration) {
    double f = 0;
    const double t =
        brent::minimum([&](double t) { return -sign * probe.value(at + t); }, -h, h, 1e-9 * h, &f);
    if (probe.ok() && std::isfinite(f) && -sign * f >= sign * sampled)
      e = {at + t, -sign * f, Extreme::Method::Minimised};
    return e;
  }
  // The derivative vanishes on the side of the sample where the curve still rises (for a
  // maximum): between the sample and its neighbour there.
  const double g0 = probe.slope(at);
  if (!probe.ok() || g0 == 0) return e;
  const double side = sign * g0 > 0 ? h : -h;
  const double g1 = probe.slope(at + side);
  if (!probe.ok() || !((g0 > 0 && g1 <= 0) || (g0 < 0 && g1 >= 0))) return e;
  const double t =
      brent::zero([&](double t) { return probe.slope(at + t); }, 0, side, g0, g1, 1e-10);
  const double v = probe.value(at + t);
  if (probe.ok() && sign * v >= sign * sampled) e = {at + t, v, Extreme::Method::Root};
  return e;
}

}  // namespace

Extremes extremesOf(const MotionSamples& s, const Quantity& q, Order order) {
  Extremes x;
  const Curve c = curveOf(s, q, order);
  x.status = c.status;
  if (!c.status.ok() || c.values.empty()) {
    if (x.status.ok()) x.status = Status::failure(StatusCode::BadModel, "no samples");
    return x;
  }
  const long long n = s.periodic ? s.steps : s.size();
  const auto first = c.values.begin();
  const long long iMax = std::max_element(first, first + n) - first;
  const long long iMin = std::min_element(first, first + n) - first;
  const double h = 360.0 / static_cast<double>(s.steps);
  Probe probe(s.kinematics, q, order);
  auto place = [&](long long i, double sign) {
    // A sample at an end of a curve that does not go round has one neighbour: it stays.
    const bool interior = s.periodic || (i > 0 && i + 1 < n);
    // A periodic curve has the same extreme a whole turn on: refine it at the turn nearest to
    // where the solver copy is (at most half a turn to track, not up to R turns back). Not a
    // body's angle, which gains its whole turns every revolution.
    double at = c.crankDeg[i];
    if (s.periodic && !(q.isBody() && order == Order::Position))
      at += 360.0 * std::round((probe.crankDeg() - at) / 360.0);
    Extreme e = interior ? refine(probe, order, sign, at, c.values[i], h)
                         : Extreme{at, c.values[i], Extreme::Method::Sample};
    if (s.periodic) {
      e.crankDeg -= 360.0 * std::floor(e.crankDeg / 360.0);
      if (e.crankDeg > 360.0 - 1e-9) e.crankDeg = 0;  // a root a hair before 0 is at 0
    }
    return e;
  };
  x.max = place(iMax, 1);
  x.min = place(iMin, -1);
  return x;
}

}  // namespace linkage
