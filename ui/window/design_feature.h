// The design checks (issue 13): the extreme positions and transmission arcs on the canvas
// (View, Analysis), the Design Checks dock (Grashof, transmission angles, limit positions and
// stroke) and the parameter study (Analysis).
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class ChecksPanel;
class DesignChoices;
class DesignOverlays;
class MainWindow;
class StudyDialog;
class WindowLayout;

class DesignFeature : public WindowFeature {
 public:
  DesignFeature(MainWindow& w, WindowLayout& layout);
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  DesignChoices* choices() const { return choices_; }
  DesignOverlays* overlays() const { return overlays_; }
  ChecksPanel* panel() const { return panel_; }
  // The parameter-study dialog, made on first use.
  StudyDialog* studyDialog();

  QAction* showExtremes;
  QAction* showTransmission;
  QAction* parameterStudy;
  QDockWidget* dock;
  QAction* show;  // the dock's toggle (Shift+D)

 private:
  void makeActions();
  void makeDock();

  MainWindow& w_;
  DesignChoices* choices_;
  DesignOverlays* overlays_;
  ChecksPanel* panel_ = nullptr;
  StudyDialog* study_ = nullptr;
};

}  // namespace linkage::ui
