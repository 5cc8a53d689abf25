// The instant centres: View > Instant Centres (I) draws every centre on the canvas (hover one
// for its Kennedy lines), the Instant Centres dock lists them and writes out the velocity of a
// point by a chain of centres, whose distances are drawn on the canvas while the centres are.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class CentresPanel;
class MainWindow;
class WindowLayout;

class CentresFeature : public WindowFeature {
 public:
  CentresFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  CentresPanel* panel() const { return panel_; }

  QAction* show;  // the centres on the canvas
  QDockWidget* dock;

 private:
  CentresPanel* panel_;
};

}  // namespace linkage::ui
