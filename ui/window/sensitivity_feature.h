// Sensitivities (issue 29): the Sensitivity dock (design/sensitivity_panel.h), a tab beside the
// plots, hidden until asked for (Analysis > Sensitivities, Shift+S).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class SensitivityPanel;
class WindowLayout;

class SensitivityFeature : public WindowFeature {
 public:
  SensitivityFeature(MainWindow& w, WindowLayout& layout);

  SensitivityPanel* panel() const { return panel_; }

  QDockWidget* dock;
  QAction* showPanel;  // the dock's toggle (Shift+S)

 private:
  SensitivityPanel* panel_ = nullptr;
};

}  // namespace linkage::ui
