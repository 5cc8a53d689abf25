// How the 3D view puts the world on the screen: an orthographic projection (a machine's
// drawings are orthographic, and parallel shafts stay parallel on the screen) by a rotation of
// the view, a scale and a pan. Kept apart from the widget so that where a world point lands is
// plain arithmetic a test checks against the standard views' definitions.
//
// World axes as the file has them: x to the right and y up in the drawing plane, z out of it
// towards the viewer of the drawing. The view's rotation has as rows the screen's right, the
// screen's up and the direction towards the eye, all in world axes.
#pragma once

#include <Eigen/Core>
#include <QPointF>
#include <QSize>
#include <vector>

#include "linkage/model.h"

namespace linkage::ui {

class Projection {
 public:
  // The standard views (third-angle, as a machine's drawings are laid out).
  enum class View { Front, Top, Side, Isometric };
  // Front: seen from +z (the drawing as drawn); Top: from +y, z down the screen; Side: from +x,
  // z to the left; Isometric: from (1, 1, 1).
  static Eigen::Matrix3d rotationOf(View v);
  // Seen from azimuth `az` about y (from +z towards +x) and elevation `el` above the x-z plane
  // (radians), with no roll: the world's y stays up on the screen.
  static Eigen::Matrix3d fromAzimuthElevation(double az, double el);
  // Looking along a plane's normal from its tip: its x to the right, its y up (as the canvas
  // draws it).
  static Eigen::Matrix3d along(const Plane& p);

  const Eigen::Matrix3d& rotation() const { return rot_; }
  void setRotation(const Eigen::Matrix3d& r) { rot_ = r; }
  double scale() const { return scale_; }  // pixels per mm
  // The pixel where the world point `target` lands.
  QPointF centre() const { return centre_; }
  Vec3 target() const { return target_; }

  QPointF toScreen(const Vec3& w) const;
  // Along the line of sight: larger is nearer the eye (what the painter draws last).
  double depth(const Vec3& w) const { return rot_.row(2).dot(w - target_); }

  // Left-drag by (dx, dy) pixels: a turntable about the world's y through the target (the
  // machine's up stays up) and a tilt about the screen's horizontal.
  void orbit(double dxPx, double dyPx);
  void pan(const QPointF& byPx) { centre_ += byPx; }
  // The wheel: the world point under `atPx` stays under it.
  void zoomAbout(const QPointF& atPx, double factor);
  // The points (world) fill `size` less a margin, in its middle; the turns of orbit() are
  // about their middle.
  void fit(const std::vector<Vec3>& points, const QSize& size);

 private:
  Eigen::Matrix3d rot_ = Eigen::Matrix3d::Identity();
  double scale_ = 1;
  QPointF centre_;
  Vec3 target_ = Vec3::Zero();
};

}  // namespace linkage::ui
