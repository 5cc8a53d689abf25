// One body as a textbook draws it, in its own sketch coordinates and moved by its pose: a bar
// with rounded ends, a rigid plate, a small disc, or (the ground) its fixed slots with hatching.
// Slots are channels cut into their body and turn with it. Slider blocks, pins and pivots are
// items of their own (joint_items.h), drawn over the bodies.
#pragma once

#include <QString>
#include <vector>

#include "draw/canvas_item.h"
#include "linkage/drawing.h"
#include "linkage/guide.h"

namespace linkage::ui {

struct BodyGeometry {
  Drawing::Body body;
  std::vector<Guide> slots;     // sketch coordinates: straight, or arcs
  std::vector<SlotId> slotIds;  // of each slot
  std::vector<Vec2> points;     // sketch coordinates
};

class BodyItem : public CanvasItem {
 public:
  BodyItem(const CanvasContext* ctx, BodyGeometry g);
  BodyId id() const { return g_.body.id; }
  int number() const { return g_.body.number; }
  const BodyGeometry& geometry() const { return g_; }
  void setPose(const Transform& pose);
  // Drawn in the warning colour (a body the solver names: free, or at a joint that fails).
  void setFlagged(bool on);
  bool flagged() const { return flagged_; }
  // Slots drawn in the warning colour (a block or pin runs out of them).
  void setFlaggedSlots(std::vector<SlotId> slots);
  bool slotFlagged(SlotId s) const;
  // The ground's slots of other planes than the canvas shows (only bodies of those planes
  // run in them): drawn faint, as those bodies are.
  void setFaintSlots(std::vector<SlotId> slots);
  bool slotFaint(SlotId s) const;
  // Its mechanism's colour (linkage/mechanisms.h); invalid: the body's own, by its number.
  void setColour(const QColor& c);
  QColor colour() const;

  QRectF boundingRect() const override;
  QPainterPath shape() const override { return shape_; }
  const QPolygonF& outline() const { return body_; }  // as drawn, in the body's frame
  void paint(QPainter* p, const QStyleOptionGraphicsItem* o, QWidget*) override;

 protected:
  void rebuild() override;
  QColor fill() const;
  void hoverEnterEvent(QGraphicsSceneHoverEvent*) override;
  void hoverLeaveEvent(QGraphicsSceneHoverEvent*) override;

 private:
  BodyGeometry g_;
  QPolygonF body_;
  QPainterPath shape_;
  std::vector<QPolygonF> channels_;
  std::vector<QVector<QLineF>> hatch_;  // a ground slot's strokes, by channel
  LabelItem* label_ = nullptr;
  bool hovered_ = false, flagged_ = false;
  std::vector<SlotId> flaggedSlots_, faintSlots_;
  QColor colour_;
};

// The outline with rounded ends around the segment a-b at distance r (a disc when a = b), as a
// polygon fine enough for `px` millimetres per pixel.
QPolygonF capsule(const Vec2& a, const Vec2& b, double r, double px);
// The outline around a slot's curve at distance r (a capsule for a straight slot; for an arc,
// the band between radii R - r and R + r with round ends).
QPolygonF channel(const Guide& g, double r, double px);
// A counter-clockwise convex polygon grown by r, its corners rounded.
QPolygonF roundedHull(const std::vector<Vec2>& hull, double r, double px);
// A body's outline as BodyItem draws it (sketch coordinates); empty for the ground and blocks.
QPolygonF bodyOutline(const Drawing::Body& b, double px);

}  // namespace linkage::ui
