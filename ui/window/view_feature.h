// View: zoom and fit, the grid and the traced paths over the canvas, the dark palette, and
// whether the panels may float out of the window.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class MainWindow;
class WindowLayout;

class ViewFeature : public WindowFeature {
 public:
  ViewFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  QAction* fit;
  QAction* zoomIn;
  QAction* zoomOut;
  QAction* actualSize;
  QAction* showGrid;
  QAction* showTraces;
  QAction* darkPalette;
  QAction* detachablePanels;

 private:
  void makeZoomActions(MainWindow& w);
  // One palette for the whole application: every window follows it.
  static void setDarkPalette(bool on);
};

}  // namespace linkage::ui
