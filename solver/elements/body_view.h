// A body's pose and velocity as the row equations see them (coincident.h, on_line.h,
// on_circle.h, angles.h), and where a point sits on a body.
#pragma once

#include "linkage/geometry.h"

namespace linkage {

// Ground has x = y = theta = 0 and no coordinates.
struct BodyView {
  int col = -1;  // first of its three columns (x, y, theta) in q, or -1 for ground
  Vec2 r = Vec2::Zero();
  double theta = 0;
  Rot R;
  Vec2 v = Vec2::Zero();  // velocity of the frame origin (or d/dphi of it)
  double w = 0;           // angular velocity (or d/dphi)
};

// A point in the frame of a moving body (its centroid frame, system/system.h), or on the
// ground (body -1, s in sketch coordinates).
struct PointLocation {
  int body = -1;
  Vec2 s = Vec2::Zero();
};

}  // namespace linkage
