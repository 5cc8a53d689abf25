// The machine's cycle (issue 18): the Cycle dock (the timing diagram, its windows, conflicts
// and clearances, tabbed with the plots; Analysis > Cycle Diagram, Shift+C), Analysis > Watch
// Clearance (Shift+W: the two things selected on the canvas), the closest approaches drawn on
// the canvas while the dock is seen, and the exports (File > Export > Cycle Diagram, Timing
// Table).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class ClearanceMarksItem;
class CyclePanel;
class MainWindow;
class WindowLayout;

class CycleFeature : public WindowFeature {
 public:
  CycleFeature(MainWindow& w, WindowLayout& layout);

  CyclePanel* panel() const { return panel_; }
  ClearanceMarksItem* marks() const { return marks_; }

  QDockWidget* dock;
  QAction* showPanel;  // the dock's toggle (Shift+C)
  QAction* watchClearance;
  QAction* exportFigure;
  QAction* exportTable;

 private:
  void makeDock();
  void makeActions();

  MainWindow& w_;
  CyclePanel* panel_ = nullptr;
  ClearanceMarksItem* marks_ = nullptr;
};

}  // namespace linkage::ui
