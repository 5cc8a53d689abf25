// Paints a Scene3d through a Projection: far things first (the painter's algorithm: each plate,
// rod, shaft and point sorted by its depth along the line of sight), plates paler the farther
// they are, outlined in their body's colour; the plane the canvas edits shaded behind its
// bodies; a triad of the world's axes in a corner. Sizes in pixels, as the canvas's.
#pragma once

#include <QPainter>
#include <string>
#include <vector>

#include "draw/style.h"
#include "linkage/model.h"
#include "view3d/projection.h"
#include "view3d/scene3d.h"

namespace linkage::ui {

struct Scene3dLook {
  CanvasStyle style;
  const Plane* plane = nullptr;  // the plane the canvas edits (shaded), or none
  std::string planeName;         // its name ("" the drawing plane)
  std::vector<BodyId> bodies;    // selected
  std::vector<PointId> points;
  std::vector<JointId> joints;
};

void paintScene3d(QPainter& p, const Scene3d& s, const Projection& proj, const Scene3dLook& look);

}  // namespace linkage::ui
