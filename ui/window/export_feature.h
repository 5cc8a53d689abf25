// File > Export: the motion table, the plots' figure and the animation (the force exports are
// the forces feature's).
#pragma once

#include <QImage>
#include <QSize>
#include <memory>

#include "window/window_feature.h"

namespace linkage::ui {

class CanvasScene;
class CanvasView;
class ForcesOverlay;
class MainWindow;
class WindowLayout;

class ExportFeature : public WindowFeature {
 public:
  ExportFeature(MainWindow& w, WindowLayout& layout);
  ~ExportFeature() override;

  // One frame of the animation as File > Export > Animation writes it: the mechanism at a crank
  // angle, fitted to its motion, at `size`; endFrames() when done.
  QImage renderFrame(double deg, QSize size);
  void endFrames();

  QAction* table;
  QAction* figure;
  QAction* animation;

 private:
  void exportMotionTable();
  void exportFigure();
  void exportAnimation();

  MainWindow& w_;
  std::unique_ptr<CanvasScene> frameScene_;
  std::unique_ptr<ForcesOverlay> frameForces_;  // the masses and loads, as the window draws them
  std::unique_ptr<CanvasView> frameView_;
};

}  // namespace linkage::ui
