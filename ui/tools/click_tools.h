// The one-click tools: Ground pivot (G), Driver (M), Output (O).
#pragma once

#include "tools/tool.h"

namespace linkage::ui {

// Ground (G): a click on a point pins its body to the ground there; on empty canvas it makes
// a ground point to build on.
class GroundTool : public Tool {
  Q_OBJECT
 public:
  using Tool::Tool;
  QString hint() const override;
  void press(const CanvasMouse& e) override;
};

// Driver (M): a click on a pin makes it the driver (the crank).
class DriverTool : public Tool {
  Q_OBJECT
 public:
  using Tool::Tool;
  QString hint() const override;
  bool snaps() const override { return false; }
  void press(const CanvasMouse& e) override;
};

// Output (O): a click on a point traces, plots and exports it (or stops doing so).
class OutputTool : public Tool {
  Q_OBJECT
 public:
  using Tool::Tool;
  QString hint() const override;
  bool snaps() const override { return false; }
  void press(const CanvasMouse& e) override;
};

}  // namespace linkage::ui
