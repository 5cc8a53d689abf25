// A body's pose and velocity as the joint equations see them (joints/*.h).
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

}  // namespace linkage
