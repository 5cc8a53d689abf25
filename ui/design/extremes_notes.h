// What the extreme positions say, drawn over the mechanism (the ghosts are under it): each
// position of the point marked; for a point, the stroke as a dimension beside it, on the side
// away from the mechanism, with every extreme's value and crank angle ("max 131.20 mm (crank
// 87.3°)") at its place along it, in the order of the values; for a body's angle, each
// extreme's value at the body's mark. Labels go on the overlays' board, off the others.
#pragma once

#include <memory>
#include <vector>

#include "design/overlay_labels.h"
#include "draw/canvas_item.h"

namespace linkage::ui {

class ExtremesItem;

class ExtremesNotes : public CanvasItem {
 public:
  ExtremesNotes(const CanvasContext* ctx, const ExtremesItem* extremes);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  // Where the last paint put the labels, device pixels (for tests).
  const std::vector<QRectF>& labelRects() const { return rects_; }

 private:
  const ExtremesItem* extremes_;
  std::vector<QRectF> rects_;
};

}  // namespace linkage::ui
