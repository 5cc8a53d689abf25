// A stroke's exact derivatives (linkage/stroke_sensitivity.h).
#include "linkage/stroke_sensitivity.h"

namespace linkage {

StrokeSensitivity strokeSensitivity(const Kinematics& k, PointId p, const Vec2& direction,
                                    std::vector<Dimension> dims) {
  StrokeSensitivity out;
  const Vec2 u = direction.normalized();
  out.limits = findLimits(k, LimitMeasure::along(p, u));
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
  out.status = s.prepare(at, std::move(dims));
  if (!out.status.ok()) return out;
  out.dims = s.dims();
  out.derivative.assign(out.dims.size(), 0.0);
  if (!out.limits.moves) return out;
  for (const auto& [deg, sign] : {std::pair{out.limits.maxDeg, 1.0}, {out.limits.minDeg, -1.0}}) {
    if (out.status = at.moveTo(deg); !out.status.ok()) return out;
    if (out.status = s.at(at); !out.status.ok()) return out;
    for (size_t d = 0; d < out.dims.size(); ++d)
      out.derivative[d] += sign * u.dot(s.point(at, p, static_cast<int>(d)));
  }
  return out;
}

}  // namespace linkage
