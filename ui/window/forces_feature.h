// The forces (issue 17): each joint's reaction on the canvas (View > Forces, Shift+F), the
// Forces dock (force curves over a turn, tabbed with the plots), the Balance dialog (Analysis)
// and the force exports (File > Export).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class BalanceDialog;
class ForcesOverlay;
class ForcesPanel;
class MainWindow;
class WindowLayout;

class ForcesFeature : public WindowFeature {
 public:
  ForcesFeature(MainWindow& w, WindowLayout& layout);
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  ForcesPanel* panel() const { return panel_; }
  ForcesOverlay* overlay() const { return overlay_; }

  QAction* show;  // the reactions on the canvas
  QDockWidget* dock;
  QAction* showPanel;  // the dock's toggle (Shift+G)
  QAction* balance;
  QAction* exportTable;
  QAction* exportFigure;

 private:
  void makeDock();
  void makeActions();

  MainWindow& w_;
  ForcesPanel* panel_ = nullptr;
  ForcesOverlay* overlay_ = nullptr;
  BalanceDialog* balance_ = nullptr;
};

}  // namespace linkage::ui
