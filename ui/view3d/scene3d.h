// What the 3D view draws of a mechanism at a pose, in world millimetres: each moving body as a
// plate in its plane (the convex hull of its points there, a bar for two, a dot for one), studs
// to the points at a depth along its plane's normal, the ball rods, the slots, the ground's
// points and the shaft axes through the ground's pivots. Geometry only: the widget projects and
// paints it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage::ui {

struct Scene3d {
  struct Plate {
    BodyId body;
    int number = 0;     // the body's colour (textbook number: ground 1)
    std::string plane;  // "" the drawing plane
    // In the plane, counter-clockwise seen from its normal's tip: a dot, a bar's two ends, or
    // the hull.
    std::vector<Vec3> outline;
    std::vector<std::pair<Vec3, Vec3>> studs;  // from the plane to a point at a depth
  };
  struct Mark {
    PointId point;
    BodyId body;
    Vec3 at = Vec3::Zero();
    bool ground = false;
  };
  struct Rod {
    JointId joint;
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  };
  // A slot: the groove its block or pin runs in, as a path in the world (an arc sampled every 5
  // degrees or less), on its body at the pose (the ground's where the file writes it, z too).
  struct Groove {
    SlotId slot;
    BodyId body;
    int number = 0;  // its body's colour
    bool ground = false;
    std::vector<Vec3> path;
  };
  // A shaft: a ground pivot and the normal of the plane of what turns on it.
  struct Axis {
    Vec3 at = Vec3::Zero(), direction = Vec3::UnitZ();
  };
  std::vector<Plate> plates;  // file order
  std::vector<Mark> points;
  std::vector<Rod> rods;
  std::vector<Groove> grooves;  // file order
  std::vector<Axis> axes;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the extent of all of it
  bool empty() const { return points.empty(); }
  // Every point, plate corner and shaft end: what fitting the view keeps in sight.
  std::vector<Vec3> extent() const;
};

// Where things are in the world now (the solver's pose, or the drawing's): a point, and a
// point fixed in a body given in its sketch coordinates (a slot's end).
struct WorldPose {
  std::function<Vec3(PointId)> point;
  std::function<Vec3(BodyId, const Vec2&)> body;
};
Scene3d describeScene3d(const Mechanism& m, const WorldPose& at);

}  // namespace linkage::ui
