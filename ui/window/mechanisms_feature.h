// Mechanisms (issue 18): the machine's mechanisms, each named, shown or hidden and coloured
// (ui/mechanisms/mechanisms_panel.h), in a dock tabbed with the history on the left.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class MechanismsPanel;
class WindowLayout;

class MechanismsFeature : public WindowFeature {
 public:
  MechanismsFeature(MainWindow& w, WindowLayout& layout);

  MechanismsPanel* panel;
  QDockWidget* dock;
  QAction* show;  // the dock's toggle (View > Mechanisms, Shift+M)
};

}  // namespace linkage::ui
