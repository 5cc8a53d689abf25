// The Plots dock under the canvas: position, velocity and acceleration of a point against the
// crank angle, linked both ways to the animation, compared with the other windows' documents.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class PlotsPanel;
class WindowLayout;

class PlotsFeature : public WindowFeature {
 public:
  PlotsFeature(MainWindow& w, WindowLayout& layout);

  PlotsPanel* panel() const { return panel_; }

  QDockWidget* dock;
  QAction* show;  // the dock's toggle

 private:
  PlotsPanel* panel_;
};

}  // namespace linkage::ui
