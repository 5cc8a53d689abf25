// A window's ends' exact derivatives (linkage/window_sensitivity.h).
#include "linkage/window_sensitivity.h"

#include <cmath>

namespace linkage {

namespace {

Status refused(std::string why) {
  return Status::failure(StatusCode::BadModel, std::move(why));
}

// d(phi_e)/dp at the pose of `at` for every dimension; false where the output does not cross
// (its crank rate along u is 0 there).
bool endDerivatives(Kinematics& at, Sensitivity& s, const LimitMeasure& w, double deg,
                    std::vector<double>& out, Status& status) {
  if (!(status = at.moveTo(deg)).ok() || !(status = s.at(at)).ok()) return false;
  const Vec2 u = w.direction.normalized();
  // The velocity at the driver's speed, per degree of crank.
  const double rate = u.dot(at.motion(w.point).velocity) / at.omega() * M_PI / 180;
  if (!(std::abs(rate) > 1e-12)) {
    status = refused(
        "the output stands still where it crosses the level (a dead centre on "
        "it): the end has no derivative");
    return false;
  }
  out.clear();
  for (size_t d = 0; d < s.dims().size(); ++d)
    out.push_back(-u.dot(s.point(at, w.point, static_cast<int>(d))) / rate);
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
  if (w->output.body || w->output.other || w->output.dz != 0)
    return out.status = refused("window \"" + name +
                                "\" follows a body's angle or a distance: "
                                "its ends have no derivatives yet (a point's position has)"),
           out;
  const CycleDiagram d = cycleDiagram(k, t);
  if (!(out.status = d.status).ok()) return out;
  Kinematics at = k;
  Sensitivity s;
  if (!(out.status = s.prepare(at, std::move(dims))).ok()) return out;
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
