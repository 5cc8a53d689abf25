// Slot (T): two clicks, or a press and drag, draw a straight slot on the body under the first
// click (on the ground over empty canvas); with Shift held at the second click (or the drag's
// release), that is the arc's end and a third click the point it passes through on the way.
// Block (B) and Pin in slot (P): a point, then the slot it runs in.
#pragma once

#include <optional>

#include "tools/tool.h"

namespace linkage::ui {

class SlotTool : public Tool {
  Q_OBJECT
 public:
  using Tool::Tool;
  QString hint() const override;
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  void move(const CanvasMouse& e) override;
  void release(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;
  // Starts a slot at a place on a body (the context menu's "add a slot from here").
  void startAt(const Vec2& at, BodyId body);
  void start(const ToolStart& s) override { startAt(s.at, s.body); }

 private:
  // The end is given: a straight slot, or with `arc` wait for the point on the way.
  void end(const Vec2& at, bool arc);
  void finish(const Vec2& end, const std::optional<Vec2>& mid = std::nullopt);
  void preview(const Vec2& cursor);
  void cancel();
  std::optional<Vec2> start_, end_;
  BodyId body_;
  QPoint pressAt_;
  bool dragged_ = false;
};

class SlotJointTool : public Tool {
  Q_OBJECT
 public:
  // Slider: a block (a body of its own) at the point; PinInSlot: the point itself in the slot.
  SlotJointTool(ToolContext* ctx, JointType type) : Tool(ctx), type_(type) {}
  QString hint() const override;
  bool snaps() const override { return false; }
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;
  // The point is chosen (the context menu): the next click picks the slot.
  void startAt(PointId p);
  void start(const ToolStart& s) override { startAt(s.point); }

 private:
  JointType type_;
  PointId point_;
};

}  // namespace linkage::ui
