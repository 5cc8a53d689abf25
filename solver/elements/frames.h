// What an element's compile() asks of the compiler (system/compile.cpp): where bodies and
// points are in the system, and slots by id. Lookups by id are constant time.
//
// Positions are in the frame of the plane class of the joint being compiled (linkage/space.h):
// a moving body's drawing mapped from its plane, the ground's projected along the normal; with
// no planes, the drawing's own numbers.
#pragma once

#include "elements/body_view.h"
#include "linkage/model.h"

namespace linkage {

class Frames {
 public:
  virtual ~Frames() = default;
  // The system index of a body: -1 for the ground, -2 when unknown.
  virtual int body(BodyId b) const = 0;
  // A point's body and its place in that body's frame; nullptr when unknown.
  virtual const PointLocation* point(PointId p) const = 0;
  // A sketch position in the frame of body index k (-1: the ground, sketch coordinates).
  virtual Vec2 local(int k, const Vec2& sketch) const = 0;
  virtual const Slot* slot(SlotId s) const = 0;
  // A point's drawn position (in the joint's class frame, as the slots and locations are).
  virtual Vec2 position(PointId p) const = 0;
  // Where a point is in space, for the rows that join plane classes (distance3.h): its body, its
  // place in that body's frame, the class whose frame that is and its depth along the normal.
  struct InSpace {
    int body = -1;
    Vec2 s = Vec2::Zero();
    int frame = 0;
    double depth = 0;
  };
  virtual InSpace inSpace(PointId p) const = 0;
  // L: the diagonal of the drawing's bounding box (mm).
  virtual double size() const = 0;
};

}  // namespace linkage
