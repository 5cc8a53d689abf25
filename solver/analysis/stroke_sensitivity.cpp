// A stroke's exact derivatives (linkage/stroke_sensitivity.h).
#include "linkage/stroke_sensitivity.h"

#include "linkage/space.h"

namespace linkage {

namespace {

// The limits of `along` and, at each, the point's derivative along u (`along` gives it from the
// Sensitivity at the pose): the envelope theorem's difference.
template <class Along>
StrokeSensitivity strokeOf(const Kinematics& k, const LimitMeasure& what,
                           std::vector<Dimension> dims, Sensitivity::Space space, Along along) {
  StrokeSensitivity out;
  out.limits = findLimits(k, what);
  out.status = out.limits.status;
  if (!out.status.ok()) return out;
  if (!out.limits.periodic) {
    out.status = Status::failure(StatusCode::BadModel,
                                 "the motion does not repeat after a turn: an end of the turn "
                                 "counts among the extremes, where the stroke's derivative is "
                                 "not the limit positions'");
    return out;
  }
  Sensitivity s;
  Kinematics at = k;
  out.status = s.prepare(at, std::move(dims), space);
  if (!out.status.ok()) return out;
  out.dims = s.dims();
  out.derivative.assign(out.dims.size(), 0.0);
  if (!out.limits.moves) return out;
  for (const auto& [deg, sign] : {std::pair{out.limits.maxDeg, 1.0}, {out.limits.minDeg, -1.0}}) {
    if (out.status = at.moveTo(deg); !out.status.ok()) return out;
    if (out.status = s.at(at); !out.status.ok()) return out;
    for (size_t d = 0; d < out.dims.size(); ++d)
      out.derivative[d] += sign * along(s, at, static_cast<int>(d));
  }
  return out;
}

}  // namespace

StrokeSensitivity strokeSensitivity(const Kinematics& k, PointId p, const Vec2& direction,
                                    std::vector<Dimension> dims) {
  const Vec2 u = direction.normalized();
  return strokeOf(
      k, LimitMeasure::along(p, u), std::move(dims), Sensitivity::Space::Refuse,
      [&](const Sensitivity& s, const Kinematics& at, int d) { return u.dot(s.point(at, p, d)); });
}

StrokeSensitivity strokeSensitivity(const Kinematics& k, PointId p, const Vec3& direction,
                                    std::vector<Dimension> dims) {
  if (!k.valid() || !isSpatial(k.mechanism())) {
    if (direction.z() != 0) {
      StrokeSensitivity out;
      out.status = Status::failure(StatusCode::BadModel,
                                   "a direction with a z component is of a machine in space");
      return out;
    }
    return strokeSensitivity(k, p, Vec2(direction.x(), direction.y()), std::move(dims));
  }
  const Vec3 u = direction.normalized();
  return strokeOf(
      k, LimitMeasure::alongInSpace(p, u), std::move(dims), Sensitivity::Space::World,
      [&](const Sensitivity& s, const Kinematics& at, int d) { return u.dot(s.point3(at, p, d)); });
}

Vec3 strokeDirection(const Mechanism& m, PointId p) {
  if (isSpatial(m)) return Vec3(0, 1, 0);
  const Vec2 d = defaultDirection(m, p);
  return Vec3(d.x(), d.y(), 0);
}

}  // namespace linkage
