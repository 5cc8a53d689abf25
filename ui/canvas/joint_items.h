// The symbols drawn over the bodies, each placed at its world position: the joints as their
// kinds draw them (ui/elements/element_ui.h makes them: pins, a ground pivot with its hatched
// base, slider blocks aligned with their slot, gear pairs and belts), the driver's rotation
// arrow, output points with their labels. Sizes are in screen pixels (CanvasStyle).
#pragma once

#include "draw/canvas_item.h"
#include "linkage/drawing.h"

namespace linkage::ui {

// Stacking of the joints' symbols: over the bodies (at 0), under the driver and outputs.
constexpr double kGearZ = 10, kBlockZ = 20, kPinZ = 30;

// A joint's symbol: placed from its JointSymbol at each pose; flagged (the warning colour) when
// a failure or the structure analysis names it.
class JointItem : public CanvasItem {
 public:
  JointItem(const CanvasContext* ctx, JointId joint) : CanvasItem(ctx), joint_(joint) {}
  JointId joint() const { return joint_; }
  virtual void place(const JointSymbol& s) = 0;
  void setFlagged(bool on);
  bool flagged() const { return flagged_; }

 private:
  JointId joint_;
  bool flagged_ = false;
};

class PinItem : public JointItem {
 public:
  enum class Kind { Pin, GroundPivot, InSlot };
  PinItem(const CanvasContext* ctx, JointId joint, Kind kind);
  void place(const JointSymbol& s) override { setAt(s.at); }
  void setAt(const Vec2& at);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  Kind kind_;
};

class BlockItem : public JointItem {
 public:
  BlockItem(const CanvasContext* ctx, JointId joint, BodyId body, int number);
  BodyId body() const { return body_; }
  void place(const JointSymbol& s) override { setPlacement(s.at, s.direction); }
  void setPlacement(const Vec2& at, const Vec2& direction);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  // Its mechanism's colour (linkage/mechanisms.h); invalid: its body's own.
  void setColour(const QColor& c);
  QColor colour() const { return colour_; }

 private:
  BodyId body_;
  int number_;
  QColor colour_;
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
