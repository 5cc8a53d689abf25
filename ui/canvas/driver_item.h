// The driver's rotation arrow about its pin: a 270 degree arc whose head shows the driving
// direction, its speed in the tooltip. Sizes in screen pixels (CanvasStyle).
#pragma once

#include "draw/canvas_item.h"

namespace linkage::ui {

class DriverItem : public CanvasItem {
 public:
  DriverItem(const CanvasContext* ctx, bool ccw, const QString& tip);
  void setAt(const Vec2& at) { setPos(at.x(), at.y()); }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  bool ccw_;
};

}  // namespace linkage::ui
