// What the tools draw over the mechanism: the selection, the body under the cursor and what a
// click would snap to (each named), the link or slot being drawn, the rubber band.
#pragma once

#include <optional>
#include <vector>

#include "draw/canvas_item.h"
#include "tools/picker.h"

namespace linkage::ui {

class CanvasScene;
class Selection;

// The outline a selected slot is drawn with, in scene coordinates, its body at `pose`: around
// its curve (an arc slot's along the arc, not its chord), `margin` px wider than its channel.
QPolygonF slotOutline(const Slot& s, const Transform& pose, double px, double margin = 3);

class ToolOverlay : public CanvasItem {
 public:
  ToolOverlay(const CanvasContext* ctx, const CanvasScene* scene, const Selection* selection);

  void setHover(const Pick& p);
  void setSnap(const std::optional<Snap>& s);
  // A polyline being drawn (a link), ending at the cursor.
  void setPath(const std::vector<Vec2>& vertices, std::optional<Vec2> cursor);
  void setBand(const std::optional<QRectF>& sceneRect);
  void clearPreview();
  const std::optional<Snap>& snap() const { return snap_; }
  const Pick& hover() const { return hover_; }

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) override;

 private:
  void paintSelection(QPainter* p) const;
  void label(QPainter* p, const QPointF& at, const QString& text, const QColor& ink) const;

  const CanvasScene* scene_;
  const Selection* selection_;
  Pick hover_;
  std::optional<Snap> snap_;
  std::vector<Vec2> path_;
  std::optional<Vec2> cursor_;
  std::optional<QRectF> band_;
};

}  // namespace linkage::ui
