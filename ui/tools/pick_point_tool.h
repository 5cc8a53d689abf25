// Picking a point on the canvas for another part of the editor (the Cycle dock's window is of a
// point picked so): a tool with no button of its own, made current by Toolbox::pickPoint. The
// next click on a point gives it and goes back to the select tool; a click elsewhere says what
// to click; Esc, or another tool chosen, gives up.
#pragma once

#include <functional>

#include "tools/tool.h"

namespace linkage::ui {

class PickPointTool : public Tool {
  Q_OBJECT

 public:
  using Tool::Tool;
  // What the point is for ("the window's point"); `picked` or `cancelled` is called once.
  void start(const QString& purpose, std::function<void(PointId)> picked,
             std::function<void()> cancelled);
  bool picking() const { return static_cast<bool>(picked_); }

  QString hint() const override;
  bool snaps() const override { return false; }
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;

 private:
  QString purpose_;
  std::function<void(PointId)> picked_;
  std::function<void()> cancelled_;
};

}  // namespace linkage::ui
