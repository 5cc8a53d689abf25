// Limit positions: see linkage/limits.h.
#include "linkage/limits.h"
#include "linkage/space.h"

#include <algorithm>
#include <cmath>

#include "analysis/measure_track.h"
#include "analysis/slot_frame.h"
#include "analysis/space_distance.h"
#include "linkage/elements.h"

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

// |g| at or below this everywhere is no motion: rounding of a velocity that is zero.
double noiseOf(const Kinematics& k, const LimitMeasure& w) {
  return w.body ? 1e-12 : 1e-12 * k.size() * kDeg;
}

}  // namespace

CycleReading readMeasure(const Kinematics& k, const LimitMeasure& w) {
  const double rate = kDeg / k.omega();  // seconds per degree of crank
  if (w.body) {
    return {k.bodyAngle(w.body) / kDeg, k.bodyOmega(w.body) * rate / kDeg,
            k.bodyAlpha(w.body) * rate * rate / kDeg};
  }
  const bool space = isSpatial(k.mechanism());
  if (w.other && space) return spaceDistance(k, w.point, w.other);
  if (w.other) {
    const Kinematics::PointMotion p = k.motion(w.point), q = k.motion(w.other);
    return lengthOf(Vec2(p.position - q.position), Vec2((p.velocity - q.velocity) * rate),
                    Vec2((p.acceleration - q.acceleration) * (rate * rate)));
  }
  if (space) {
    // In the world: a point's plane class frame is not the world's.
    const SpaceMotion p = spaceMotion(k, w.point);
    const Vec3 d = w.direction3();
    return {p.r.dot(d), p.dr.dot(d), p.ddr.dot(d)};
  }
  const Kinematics::PointMotion p = k.motion(w.point);
  return {p.position.dot(w.direction), p.velocity.dot(w.direction) * rate,
          p.acceleration.dot(w.direction) * rate * rate};
}

Vec2 defaultDirection(const Mechanism& m, PointId p) {
  const Point* pt = m.point(p);
  const Body* g = m.ground();
  if (!pt || !g) return Vec2(0, 1);
  for (const Joint& j : m.joints) {
    const Role role = kindOf(j).role;
    if (role != Role::Prismatic && role != Role::PointOnCurve) continue;
    const Slot* s = m.slot(j.slot);
    const Point* a = m.point(j.a);
    if (!s || !a) continue;
    // The point itself in a ground slot, or its body carried along one by a slider (the block
    // in a ground slot, or the ground's point in the body's slot).
    const bool own = j.a == p && s->body == g->id;
    const bool carried = role == Role::Prismatic && ((a->body == pt->body && s->body == g->id) ||
                                                     (s->body == pt->body && a->body == g->id));
    if (!own && !carried) continue;
    Vec2 d = (s->p1 - s->p0).normalized();
    if (std::abs(d.y()) >= std::abs(d.x()) ? d.y() < 0 : d.x() < 0) d = -d;
    return d;
  }
  return Vec2(0, 1);
}

Status checkMeasure(const Kinematics& k, const LimitMeasure& w) {
  if (!k.valid()) return Status::failure(StatusCode::BadModel, "no mechanism is loaded");
  if (!(k.omega() > 0) || !std::isfinite(k.omega()))
    return Status::failure(StatusCode::BadModel, "the driver's speed is not a positive number");
  if (w.body) {
    if (!k.contains(w.body))
      return Status::failure(StatusCode::BadModel, "the body is not in the mechanism");
    return Status::success();
  }
  if (!k.contains(w.point))
    return Status::failure(StatusCode::BadModel, "the point is not in the mechanism");
  if (w.other) {
    if (!k.contains(w.other) || w.other == w.point)
      return Status::failure(StatusCode::BadModel,
                             "the other point is not in the mechanism, or is the point itself");
    return k.checkDetermined({w.point, w.other});
  }
  if (!w.direction3().allFinite() || w.direction3().norm() == 0)
    return Status::failure(StatusCode::BadModel, "the direction is not a finite non-zero vector");
  if (w.dz != 0 && !isSpatial(k.mechanism()))
    return Status::failure(StatusCode::BadModel,
                           "a direction with a z component is of a machine in space");
  return k.checkDetermined({w.point});
}

MeasureTrack::MeasureTrack(const Kinematics& k, LimitMeasure what)
    : what_(std::move(what)), size_(k.size()), noise_(noiseOf(k, what_)) {
  what_ = what_.unit();
  const LimitMeasure w = what_;
  channel.f = [w](const Kinematics& at) {
    const CycleReading r = readMeasure(at, w);
    return RootSample{r.d1, r.d2};
  };
  channel.value = [w](const Kinematics& at) { return readMeasure(at, w).value; };
}

void MeasureTrack::sample(const Kinematics& k) {
  const CycleReading r = readMeasure(k, what_);
  values.push_back(r.value);
  channel.samples.push_back({r.d1, r.d2});
}

bool MeasureTrack::moves() const {
  for (const RootSample& s : channel.samples)
    if (std::abs(s.g) > noise_) return true;
  return false;
}

std::vector<RootChannel*> MeasureTrack::channels() {
  if (!moves()) return {};
  return {&channel};
}

bool MeasureTrack::repeats() const {
  if (values.size() < 2) return false;
  double change = values.back() - values.front();
  if (what_.body) change -= 360 * std::round(change / 360);
  double gmax = 0;
  for (const RootSample& s : channel.samples) gmax = std::max(gmax, std::abs(s.g));
  const double tol = what_.body ? 1e-9 : 1e-9 * size_;
  return std::abs(change) <= tol &&
         std::abs(channel.samples.back().g - channel.samples.front().g) <= 1e-9 * gmax + tol;
}

Limits MeasureTrack::result(bool periodic) const {
  Limits out;
  out.periodic = periodic;
  out.moves = moves();
  auto consider = [&](double deg, double v) {
    if (v < out.min) {
      out.min = v;
      out.minDeg = deg;
    }
    if (v > out.max) {
      out.max = v;
      out.maxDeg = deg;
    }
  };
  out.min = out.max = values.front();
  // The end counts where the motion does not repeat, and for a body that turns fully (its
  // angle comes back whole turns on).
  const bool turns = what_.body && std::abs(values.back() - values.front()) > 180;
  if (!periodic || turns) consider(360, values.back());
  for (const Root& r : channel.roots) {
    // A root at the end of a periodic turn is the one at its start.
    const double deg = periodic && r.crankDeg >= 360 ? r.crankDeg - 360 : r.crankDeg;
    out.extremes.push_back({!r.rising, deg, r.value});
    consider(deg, r.value);
  }
  std::sort(out.extremes.begin(), out.extremes.end(),
            [](const LocalExtreme& a, const LocalExtreme& b) { return a.crankDeg < b.crankDeg; });
  out.stroke = out.max - out.min;
  return out;
}

Limits findLimits(const Kinematics& k0, const LimitMeasure& what, const LimitOptions& opt) {
  Limits out;
  if (opt.steps < 4 || !(opt.toleranceDeg > 0)) {
    out.status = Status::failure(StatusCode::BadModel,
                                 "limits need at least 4 steps and a positive tolerance");
    return out;
  }
  if (out.status = checkMeasure(k0, what); !out.status.ok()) return out;
  Kinematics k = k0;
  k.setAccelerations(true);
  if (out.status = k.moveTo(0); !out.status.ok()) return out;
  Kinematics probe = k;
  MeasureTrack track(k, what);
  std::vector<double> crank;
  for (int i = 0; i <= opt.steps; ++i) {
    crank.push_back(i * 360.0 / opt.steps);
    if (out.status = k.moveTo(crank.back()); !out.status.ok()) return out;
    track.sample(k);
  }
  const bool periodic = track.repeats();
  if (periodic) track.closePeriod();
  if (out.status = findRoots(probe, crank, track.channels(), periodic, opt.toleranceDeg);
      !out.status.ok())
    return out;
  return track.result(periodic);
}

}  // namespace linkage
