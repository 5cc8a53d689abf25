// A window's ends' exact derivatives (linkage/window_sensitivity.h).
#include "linkage/window_sensitivity.h"

#include <cmath>

#include "analysis/measure_track.h"
#include "linkage/space.h"

namespace linkage {

namespace {

Status refused(std::string why) {
  return Status::failure(StatusCode::BadModel, std::move(why));
}

// The output's rate per degree of crank and its derivative in dimension d at the pose: a point
// along u, a body's angle (radians), or the distance between two points. On a machine in space
// the point and the distance are the world's (readMeasure's rate, Sensitivity's point3).
double outputRate(const Kinematics& at, const LimitMeasure& w) {
  const double perDeg = M_PI / 180 / at.omega();
  if (w.body) return at.bodyOmega(w.body) * perDeg;
  if (isSpatial(at.mechanism())) return readMeasure(at, w).d1;
  if (w.other) {
    const Vec2 e = (at.position(w.point) - at.position(w.other)).normalized();
    return e.dot(at.velocity(w.point) - at.velocity(w.other)) * perDeg;
  }
  return w.direction.normalized().dot(at.velocity(w.point)) * perDeg;
}

double outputChange(const Kinematics& at, const Sensitivity& s, const LimitMeasure& w, int d) {
  if (w.body) return s.angle(at, w.body, d);
  if (isSpatial(at.mechanism())) {
    if (!w.other) return w.direction3().dot(s.point3(at, w.point, d));
    const Vec3 e =
        (at.motionInSpace(w.point).position - at.motionInSpace(w.other).position).normalized();
    return e.dot(s.point3(at, w.point, d) - s.point3(at, w.other, d));
  }
  if (w.other) {
    const Vec2 e = (at.position(w.point) - at.position(w.other)).normalized();
    return e.dot(s.point(at, w.point, d) - s.point(at, w.other, d));
  }
  return w.direction.normalized().dot(s.point(at, w.point, d));
}

// d(phi_e)/dp at the pose of `at` for every dimension; false where the output does not cross
// (its crank rate is 0 there).
bool endDerivatives(Kinematics& at, Sensitivity& s, const LimitMeasure& w, double deg,
                    std::vector<double>& out, Status& status) {
  if (!(status = at.moveTo(deg)).ok() || !(status = s.at(at)).ok()) return false;
  const double rate = outputRate(at, w);
  if (!(std::abs(rate) > 1e-12)) {
    status = refused(
        "the output stands still where it crosses the level (a dead centre on "
        "it): the end has no derivative");
    return false;
  }
  out.clear();
  for (size_t d = 0; d < s.dims().size(); ++d)
    out.push_back(-outputChange(at, s, w, static_cast<int>(d)) / rate);
  return true;
}

}  // namespace

WindowSensitivity windowSensitivity(const Kinematics& k, const std::string& name,
                                    std::vector<Dimension> dims) {
  WindowSensitivity out;
  const Timing& t = k.mechanism().timing;
  const TimingWindow* w = nullptr;
  for (const TimingWindow& x : t.windows)
    if (x.name == name) w = &x;
  if (!w) return out.status = refused("no window named \"" + name + "\" in the timing"), out;
  const CycleDiagram d = cycleDiagram(k, t);
  if (!(out.status = d.status).ok()) return out;
  Kinematics at = k;
  Sensitivity s;
  const Sensitivity::Space world =
      isSpatial(k.mechanism()) ? Sensitivity::Space::World : Sensitivity::Space::Refuse;
  if (!(out.status = s.prepare(at, std::move(dims), world)).ok()) return out;
  out.dims = s.dims();
  for (const WindowIntervals& wi : d.windows) {
    if (wi.name != name) continue;
    for (const AngleInterval& i : wi.intervals) {
      WindowEndSensitivity e{i.fromDeg, i.toDeg, {}, {}};
      if (!endDerivatives(at, s, w->output, i.fromDeg, e.dFrom, out.status) ||
          !endDerivatives(at, s, w->output, i.toDeg, e.dTo, out.status))
        return out;
      out.intervals.push_back(std::move(e));
    }
  }
  return out;
}

}  // namespace linkage
