// A ball rod as drawn in a plane: a rod between two balls at its ends, where the ends are now
// in the drawing (the canvas shows one plane; the 3D view shows the rod in space). Picked by its
// line. Sizes in screen pixels (CanvasStyle).
#pragma once

#include "elements/joint_item.h"

namespace linkage::ui {

class BallRodItem : public JointItem {
 public:
  BallRodItem(const CanvasContext* ctx, JointId joint);
  void place(const JointSymbol& s) override;
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  bool pickedByLines() const override { return true; }
  double distanceToLines(const Vec2& at) const override;
  QPainterPath lines() const override;

 private:
  Vec2 a_ = Vec2::Zero(), b_ = Vec2::Zero();
};

}  // namespace linkage::ui
