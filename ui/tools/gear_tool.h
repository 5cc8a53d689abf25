// Gear or belt (E): click a body that turns about a pivot, then another pivoted on the same
// body (the frame, or an arm): a gear pair couples them, b turning as fast as a the other way
// (ratio -1); with Shift held at the second click, a belt (ratio +1). The ratio is edited in
// the properties panel, where the new coupling is selected.
#pragma once

#include "tools/tool.h"

namespace linkage::ui {

class GearTool : public Tool {
  Q_OBJECT
 public:
  using Tool::Tool;
  QString hint() const override;
  bool snaps() const override { return false; }
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;
  // The first body is chosen (the body's menu: "Couple to..."): the next click picks the second.
  void startAt(BodyId first);
  void start(const ToolStart& s) override { startAt(s.body); }

 private:
  BodyId first_;
};

}  // namespace linkage::ui
