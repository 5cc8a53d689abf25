// A dyad's transmission angle's exact derivatives (linkage/transmission_sensitivity.h).
#include "linkage/transmission_sensitivity.h"

#include <cmath>

namespace linkage {

namespace {

constexpr double kDeg = M_PI / 180;

}  // namespace

Status dyadDifferentiable(const Mechanism& m, const TransmissionJoint& j) {
  if (j.kind != TransmissionKind::Dyad)
    return Status::failure(StatusCode::BadModel,
                           j.label + " is a " + toString(j.kind) +
                               " angle: its derivatives are not computed yet (a dyad's "
                               "between points are)");
  for (const Anchor* a : {&j.linkOuter, &j.linkAt, &j.otherAt, &j.otherOuter})
    if (a->arc)
      return Status::failure(StatusCode::BadModel,
                             j.label + " is a dyad with " + m.slotLabel(a->arc) +
                                 "'s centre (an arc slot): its derivatives are not computed "
                                 "yet (a dyad's between points are)");
  return Status::success();
}

double dyadAngleSensitivity(const Kinematics& k, const TransmissionJoint& j,
                            const Sensitivity* sens, int dim, double* d) {
  const Vec2 u = j.linkOuter.at(k) - j.linkAt.at(k), w = j.otherOuter.at(k) - j.otherAt.at(k);
  const double turn = std::atan2(cross(u, w), u.dot(w));
  if (sens && d) {
    auto dp = [&](const Anchor& a) { return sens->point(k, a.point, dim); };
    const Vec2 du = dp(j.linkOuter) - dp(j.linkAt), dw = dp(j.otherOuter) - dp(j.otherAt);
    const double dturn = cross(w, dw) / w.squaredNorm() - cross(u, du) / u.squaredNorm();
    *d = (turn < 0 ? -dturn : dturn) / kDeg;
  }
  return std::abs(turn) / kDeg;
}

std::vector<double> dyadAngleDerivatives(const Kinematics& k, const TransmissionJoint& j,
                                         const Sensitivity& s) {
  std::vector<double> out(s.dims().size());
  for (size_t v = 0; v < out.size(); ++v)
    dyadAngleSensitivity(k, j, &s, static_cast<int>(v), &out[v]);
  return out;
}

}  // namespace linkage
