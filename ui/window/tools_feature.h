// Tools: the canvas's drawing tools (Tools menu and toolbar, each with its key), the selection
// they work on, and the commands on it in the Edit menu (Delete, Flip assembly).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class Selection;
class ToolOverlay;
class Toolbox;
class WindowLayout;

class ToolsFeature : public WindowFeature {
 public:
  ToolsFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;

  Toolbox* toolbox() const { return toolbox_; }
  Selection* selection() const { return selection_; }

 private:
  Selection* selection_;
  ToolOverlay* overlay_;
  Toolbox* toolbox_;
};

}  // namespace linkage::ui
