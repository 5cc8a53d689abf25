// The Properties dock: the selection's exact numbers (PropertiesPanel) above, what the
// mechanism is and where it is (InspectorPanel) below. Accelerations are computed only while
// it is seen (its readout is the only view of them).
#pragma once

#include "window/window_feature.h"

class QScrollArea;
class QSplitter;

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

 protected:
  bool eventFilter(QObject* o, QEvent* e) override;

 private:
  QWidget* makeSplit();
  void fitForm();
  void updateWork();

  Document* doc_;
  PropertiesPanel* panel_;
  InspectorPanel* inspector_;
  QSplitter* split_ = nullptr;
  QScrollArea* scroll_ = nullptr;
  bool seen_ = false;
  bool formPending_ = true;  // the form's rows wait for the dock to have a height
};

}  // namespace linkage::ui
