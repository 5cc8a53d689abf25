// Sensitivities (issue 29): the Sensitivity dock (design/sensitivity_panel.h), a tab beside the
// plots, hidden until asked for (Analysis > Sensitivities, Shift+S); Analysis > Find
// Dimensions (Ctrl+Shift+F: design/optimize_dialog.h), its dialog made on first use.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class OptimizeDialog;
class SensitivityPanel;
class WindowLayout;

class SensitivityFeature : public WindowFeature {
 public:
  SensitivityFeature(MainWindow& w, WindowLayout& layout);

  SensitivityPanel* panel() const { return panel_; }

  QDockWidget* dock;
  QAction* showPanel;  // the dock's toggle (Shift+S)
  QAction* findDimensions;
  OptimizeDialog* optimizeDialog();

 private:
  MainWindow& w_;
  SensitivityPanel* panel_ = nullptr;
  OptimizeDialog* optimize_ = nullptr;
};

}  // namespace linkage::ui
