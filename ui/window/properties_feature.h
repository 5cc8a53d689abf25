// The Properties dock: the selection's exact numbers (PropertiesPanel) above, what the
// mechanism is and where it is (InspectorPanel) below. Accelerations are computed only while
// it is seen (its readout is the only view of them).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class Document;
class InspectorPanel;
class MainWindow;
class PropertiesPanel;
class WindowLayout;

class PropertiesFeature : public WindowFeature {
 public:
  PropertiesFeature(MainWindow& w, WindowLayout& layout);

  PropertiesPanel* panel() const { return panel_; }
  InspectorPanel* inspector() const { return inspector_; }

  QDockWidget* dock;

 private:
  QWidget* makeSplit();
  void updateWork();

  Document* doc_;
  PropertiesPanel* panel_;
  InspectorPanel* inspector_;
  bool seen_ = false;
};

}  // namespace linkage::ui
