// What is under the cursor, and where a click there would put a point: the nearest point
// within a few pixels (and the joint it makes), a slot, the body; snapping to points, onto a
// slot's line, or to the grid, with a name for what was snapped to, so that a connection
// never only looks made.
#pragma once

#include <QString>

#include "linkage/model.h"

namespace linkage::ui {

class CanvasScene;

struct Pick {
  PointId point;  // the nearest point within reach (of the shown mechanism)
  Vec2 pointAt = Vec2::Zero();
  JointId joint;  // the pin at that point, or the block or slot pin under the cursor
  SlotId slot;    // a slot under the cursor
  BodyId body;    // the top body under the cursor (the ground when nothing else)
  bool onGround = false;
  bool onBlock = false;  // the body is a slider block under the cursor
  // A gear or belt: the one whose drawn lines (pitch circles, pitch point, belt) are nearest
  // within reach (`onCouplingLines`), else the smallest pitch circle holding the cursor.
  JointId coupling;
  bool onCouplingLines = false;
  bool empty() const { return !point && !joint && !slot && !coupling && (!body || onGround); }
};

// Reach in screen pixels: of a point, and of a gear's or belt's drawn lines.
constexpr double kPickPixels = 8, kCouplingPixels = 5;

Pick pickAt(const CanvasScene& s, const Vec2& world, double px);

struct Snap {
  enum class Kind { Free, Point, Slot, Grid };
  Kind kind = Kind::Free;
  Vec2 at = Vec2::Zero();
  PointId point;
  SlotId slot;
  QString label;  // "coupler.B", "on slot disk.B", "grid 10, 20"
};

// Where a click puts a point: on the picked point, else on a slot's line under the cursor,
// else on the grid (`gridStep` mm, 0 for off), else where the cursor is.
Snap snapAt(const CanvasScene& s, const Pick& pick, const Vec2& world, double px, double gridStep);

// "coupler.B", "slot disk.B", "pin coupler.A - rocker.A", "body coupler": for status messages.
QString describePick(const Mechanism& m, const Pick& p);

}  // namespace linkage::ui
