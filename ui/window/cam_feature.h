// Cams (issue 28): the Cam dock (a cam designed from its follower's motion, cam/cam_panel.h),
// a tab beside the plots, hidden until asked for (Analysis > Cam Design, Shift+K). A cam is
// made from a follower's right-click menu (elements/cam_ui.cpp); the dock then shows it.
#pragma once

#include <cstdint>
#include <set>

#include "linkage/model.h"
#include "window/window_feature.h"

namespace linkage::ui {

class CamPanel;
class MainWindow;
class WindowLayout;

class CamFeature : public WindowFeature {
 public:
  CamFeature(MainWindow& w, WindowLayout& layout);

  CamPanel* panel() const { return panel_; }

  QDockWidget* dock;
  QAction* showPanel;  // the dock's toggle (Shift+K)

 private:
  MainWindow& w_;
  CamPanel* panel_ = nullptr;
  std::set<JointId> known_;  // the cams seen
  bool replaced_ = true;
};

}  // namespace linkage::ui
