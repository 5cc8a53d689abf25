// A dimension's move of the drawing in the solver's terms on a machine in space (linkage/space.h,
// analysis/sensitivity.cpp): the drawing gives a moving body's points and slots in its plane and
// the ground's in the world; the rows hold them in their plane class's frame (a rotation of a
// plane into its class, the ground projected along the class's normal). The class frames are
// coordinates here, held as the dimension changes: a move of the world is the same move in them.
// On a planar model every conversion is the identity, skipped.
#pragma once

#include "linkage/sensitivity.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage::internal {

class SpaceMoves {
 public:
  SpaceMoves(const Mechanism& m, const System& sys);
  bool spatial() const { return spatial_; }
  // A point's move as Sensitivity keeps it (sensitivity.h, pointMove_) from the dimension's move
  // in its body's plane (the ground's: the world's x, y) and of its depth (the ground's: z).
  Vec3 kept(const Point& p, const Vec2& move, double depth) const;
  // A kept move of point p in class `cls`'s frame (the ground's projected) and along its normal.
  Vec2 inClass(PointId p, const Vec3& kept, int cls) const;
  double depthIn(PointId p, const Vec3& kept, int cls) const;
  // A slot (and its ends' moves) as class `cls`'s frame sees it.
  Slot slot(const Slot& s, int cls) const;
  void slotMove(const Slot& s, const Dimension::SlotMove& mv, int cls, Vec2& d0, Vec2& d1) const;
  // An arc's point on the way: its move, as slotMove's ends (zero where the move has none).
  Vec2 midMove(const Slot& s, const Dimension::SlotMove& mv, int cls) const;
  // An arc slot's centre's move and its radius's for the dimension, in class `cls`'s frame
  // (linkage/slot_sensitivity.h, arcChange).
  void arcMove(const Slot& s, const Dimension& d, int cls, Vec2& dc, double& drho) const;
  // The class a slot is seen in: its body's plane's, the ground's its block's (groundSlotClass;
  // 0 where none runs in it).
  int slotClass(const Slot& s) const;
  // A point's drawn position in class `cls`'s frame.
  Vec2 drawn(const Point& p, int cls) const;
  // The class a planar row is written in: its first moving body's (0 with none).
  int rowClass(const Row& r) const;
  // A class-frame vector and depth in the world.
  Vec3 lift(int cls, const Vec2& v, double depth = 0) const;

 private:
  const Mechanism& m_;
  const System& sys_;
  bool spatial_ = false;
  PlaneClasses pc_;
  bool ground(const Body* b) const { return !b || b->ground; }
};

// The class a ground slot is written in: that of the first joint whose slot it is (its block's
// plane), -1 when no joint runs in it.
int groundSlotClass(const Mechanism& m, const PlaneClasses& pc, const Slot& s);

}  // namespace linkage::internal
