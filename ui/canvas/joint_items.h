// The symbols drawn over the bodies, each placed at its world position: pins (a ground pivot
// with its hatched base), slider blocks aligned with their slot, the driver's rotation arrow,
// output points with their labels. Sizes are in screen pixels (CanvasStyle).
#pragma once

#include "canvas/canvas_item.h"
#include "linkage/drawing.h"

namespace linkage::ui {

class PinItem : public CanvasItem {
 public:
  enum class Kind { Pin, GroundPivot, InSlot };
  PinItem(const CanvasContext* ctx, JointId joint, Kind kind);
  JointId joint() const { return joint_; }
  void setAt(const Vec2& at);
  void setFlagged(bool on);
  bool flagged() const { return flagged_; }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  JointId joint_;
  Kind kind_;
  bool flagged_ = false;
};

class BlockItem : public CanvasItem {
 public:
  BlockItem(const CanvasContext* ctx, JointId joint, BodyId body, int number);
  JointId joint() const { return joint_; }
  BodyId body() const { return body_; }
  void setPlacement(const Vec2& at, const Vec2& direction);
  void setFlagged(bool on);
  bool flagged() const { return flagged_; }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  JointId joint_;
  BodyId body_;
  int number_;
  bool flagged_ = false;
};

class DriverItem : public CanvasItem {
 public:
  DriverItem(const CanvasContext* ctx, bool ccw, const QString& tip);
  void setAt(const Vec2& at) { setPos(at.x(), at.y()); }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  bool ccw_;
};

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
