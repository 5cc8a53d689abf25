#include "plots/curve_set.h"

#include "linkage/space.h"

#include <algorithm>
#include <cmath>

#include "document/shown_numbers.h"
#include "figures/units.h"

namespace linkage::ui {

namespace {

// The scale next to which a value of this order is rounding (shown_numbers.h).
double scaleOf(const Kinematics& k, bool body, int order) {
  return (body ? M_PI : k.size()) * std::pow(std::abs(k.omega()), order);
}

// A curve whose whole swing is rounding (a fixed pivot's velocity computed through a turning
// link: +-2.5e-14 mm/s) is the constant it rounds, plotted flat (exactly 0 when it is zero).
// Its largest and smallest value are that constant, reached nowhere in particular: the angles
// where the rounding peaked are no extremes of the motion, and none is marked.
void flattenRounding(Curve& c, Extremes& e, double scale) {
  if (c.values.empty()) return;
  const auto [lo, hi] = std::minmax_element(c.values.begin(), c.values.end());
  if (!(*hi - *lo <= kRoundingFraction * scale)) return;
  const double v = cleaned((*lo + *hi) / 2, scale);
  std::fill(c.values.begin(), c.values.end(), v);
  e.max.value = e.min.value = v;
  e.max.crankDeg = e.min.crankDeg = NAN;
}

}  // namespace

CurveSet::CurveSet(const Kinematics& k, const CurveRequest& r, const QString& title,
                   const Status& solve)
    : title_(title), request_(r) {
  const std::string target = r.target.toStdString();
  crankLabel_ = crankAxisLabel(k.mechanism());
  if (!solve.ok()) {
    status_ = solve;
    return;
  }
  if (!k.valid()) {
    status_ = Status::failure(StatusCode::BadModel, "the mechanism is not solved");
    return;
  }
  SampleSpec spec;
  if (r.body) {
    const Body* b = k.mechanism().bodyNamed(target);
    if (!b) {
      status_ = Status::failure(StatusCode::BadModel, "no body \"" + target + "\"");
      return;
    }
    // A body free with the crank held has no rotation the driver determines.
    const std::vector<BodyId> free = k.structure().freeBodies;
    if (std::find(free.begin(), free.end(), b->id) != free.end()) {
      status_ = Status::failure(StatusCode::Underconstrained,
                                "the rotation of " + target +
                                    " is not determined by the driver (it turns with the crank "
                                    "held)");
      return;
    }
    quantity_ = Quantity::ofBody(b->id);
    spec.bodies = {b->id};
  } else {
    const std::optional<PointId> p = k.mechanism().findPoint(target);
    if (!p) {
      status_ = Status::failure(StatusCode::BadModel, "no point \"" + target + "\"");
      return;
    }
    const double a = r.directionDeg * M_PI / 180, e = r.elevationDeg * M_PI / 180;
    quantity_ = Quantity::ofPoint(
        *p, r.component,
        Vec3(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), e == 0 ? 0 : std::sin(e)));
    spec.points = {*p};
    if (r.component == Quantity::Component::Distance) {
      const std::string to = r.other.toStdString();
      const std::optional<PointId> o = k.mechanism().findPoint(to);
      if (!o) {
        status_ = Status::failure(StatusCode::BadModel, "no point \"" + to + "\" to measure to");
        return;
      }
      quantity_.other = *o;
      spec.points.push_back(*o);
    }
    // A machine in space: the world's x, y, z (the solver's planar motion of a point is in its
    // plane class's frame); the labels say so.
    quantity_.world = isSpatial(k.mechanism());
    if (quantity_.world) frame_ = QStringLiteral("world");
    spec.world = quantity_.inWorld();
  }
  spec.steps = r.steps;
  spec.revs = r.revs;
  spec.accelerations = r.orders[2] || r.orders[3];
  samples_ = std::make_shared<MotionSamples>(sampleMotion(k, spec));
  status_ = samples_->status;
  for (int o = 0; o < kOrders; ++o) {
    if (!r.orders[o]) continue;
    curves_[o] = curveOf(*samples_, quantity_, static_cast<Order>(o));
    if (curves_[o].status.ok())
      extremes_[o] = extremesOf(*samples_, quantity_, static_cast<Order>(o));
    scales_[o] = scaleOf(k, r.body, o);
    flattenRounding(curves_[o], extremes_[o], scales_[o]);
  }
  const Curve& j = curves_[3];
  if (r.orders[3] && j.status.ok())
    jerk_ = PeriodicInterpolant({j.values.begin(), j.values.begin() + samples_->steps});
  probe_ = std::make_unique<Kinematics>(samples_->kinematics);
  probe_->setAccelerations(true);
}

double CurveSet::lastDeg() const {
  return empty() ? NAN : samples_->crankDeg.back();
}

std::array<double, kOrders> CurveSet::valuesAt(double deg) {
  std::array<double, kOrders> v{NAN, NAN, NAN, NAN};
  if (empty() || !(deg >= 0 && deg <= lastDeg())) return v;
  const bool moved = probe_->moveTo(deg).ok() && probe_->derivativesValid();
  for (int o = 0; o < 3; ++o)
    if (request_.orders[o] && moved)
      v[o] = cleaned(valueAt(*probe_, quantity_, static_cast<Order>(o)), scales_[o]);
  if (!jerk_.empty()) v[3] = cleaned(jerk_(deg * M_PI / 180), scales_[3]);
  return v;
}

Spectrum CurveSet::harmonics(Order o, int maxK, Status* why) const {
  if (empty()) {
    if (why) *why = status_;
    return {};
  }
  return harmonicsOf(*samples_, quantity_, o, maxK, why);
}

}  // namespace linkage::ui
