// An output point (traced, plotted, exported): a cross in a circle with its label beside it.
// Sizes in screen pixels (CanvasStyle).
#pragma once

#include "draw/canvas_item.h"
#include "linkage/model.h"

namespace linkage::ui {

class OutputItem : public CanvasItem {
 public:
  OutputItem(const CanvasContext* ctx, PointId point, const QString& label);
  PointId point() const { return point_; }
  void setAt(const Vec2& at) { setPos(at.x(), at.y()); }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 protected:
  void rebuild() override;

 private:
  PointId point_;
  LabelItem* label_;
};

}  // namespace linkage::ui
