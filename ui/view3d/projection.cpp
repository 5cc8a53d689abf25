#include "view3d/projection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace linkage::ui {

Eigen::Matrix3d Projection::fromAzimuthElevation(double az, double el) {
  const Vec3 eye(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  const Vec3 right(std::cos(az), 0, -std::sin(az));
  const Vec3 up = eye.cross(right);
  Eigen::Matrix3d r;
  r.row(0) = right;
  r.row(1) = up;
  r.row(2) = eye;
  return r;
}

Eigen::Matrix3d Projection::rotationOf(View v) {
  switch (v) {
    case View::Front:
      return fromAzimuthElevation(0, 0);
    case View::Top:
      return fromAzimuthElevation(0, M_PI / 2);
    case View::Side:
      return fromAzimuthElevation(M_PI / 2, 0);
    case View::Isometric:
      break;
  }
  return fromAzimuthElevation(M_PI / 4, std::atan(1 / std::sqrt(2.0)));
}

Eigen::Matrix3d Projection::along(const Plane& p) {
  Eigen::Matrix3d r;
  r.row(0) = p.xAxis.normalized();
  r.row(1) = p.yAxis.normalized();
  r.row(2) = p.normal().normalized();
  return r;
}

QPointF Projection::toScreen(const Vec3& w) const {
  const Vec3 v = rot_ * (w - target_);
  return centre_ + QPointF(scale_ * v.x(), -scale_ * v.y());
}

void Projection::orbit(double dxPx, double dyPx) {
  constexpr double kRadPerPx = 0.008;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(dxPx * kRadPerPx, Vec3::UnitY()).matrix();
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(dyPx * kRadPerPx, Vec3::UnitX()).matrix();
  rot_ = tilt * rot_ * turn;
  // Rounding must not shear the view over many drags: orthonormal again.
  const Vec3 right = rot_.row(0).normalized();
  const Vec3 up = (rot_.row(1) - rot_.row(1).dot(right) * right.transpose()).normalized();
  rot_.row(0) = right;
  rot_.row(1) = up;
  rot_.row(2) = right.cross(up);
}

void Projection::zoomAbout(const QPointF& atPx, double factor) {
  if (!(factor > 0) || !std::isfinite(factor)) return;
  const double next = std::clamp(scale_ * factor, 1e-4, 1e5);
  factor = next / scale_;
  centre_ = atPx + (centre_ - atPx) * factor;
  scale_ = next;
}

void Projection::fit(const std::vector<Vec3>& points, const QSize& size) {
  if (points.empty()) return;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  target_ = 0.5 * (lo + hi);
  // The extent on the screen of the points themselves (a box's corners would leave the
  // picture half empty in an oblique view).
  Eigen::Vector2d slo(INFINITY, INFINITY), shi(-INFINITY, -INFINITY);
  for (const Vec3& p : points) {
    const Vec3 v = rot_ * (p - target_);
    slo = slo.cwiseMin(Eigen::Vector2d(v.x(), v.y()));
    shi = shi.cwiseMax(Eigen::Vector2d(v.x(), v.y()));
  }
  const Eigen::Vector2d span = shi - slo, mid = 0.5 * (slo + shi);
  const double room = 0.85;
  const double sx = span.x() > 1e-9 ? room * size.width() / span.x() : 1e9;
  const double sy = span.y() > 1e-9 ? room * size.height() / span.y() : 1e9;
  scale_ = std::min(sx, sy);
  if (!(scale_ < 1e8)) scale_ = 1;  // a single point: any scale shows it
  centre_ = QPointF(size.width() / 2.0 - scale_ * mid.x(), size.height() / 2.0 + scale_ * mid.y());
}

}  // namespace linkage::ui
