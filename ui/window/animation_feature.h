// Animation: play and pause, step, back to the start, slower and faster; the crank scrubber in
// the Animation toolbar.
#pragma once

#include "window/window_feature.h"

namespace linkage::ui {

class CrankBar;
class MainWindow;
class WindowLayout;

class AnimationFeature : public WindowFeature {
 public:
  AnimationFeature(MainWindow& w, WindowLayout& layout);
  void applyIcons(const QPalette& p) override;
  void readSettings(const QSettings& s) override;
  void writeSettings(QSettings& s) const override;

  CrankBar* crankBar() const { return crankBar_; }

  QAction* play;  // "&Pause" while playing
  QAction* stepForward;
  QAction* stepBack;
  QAction* toStart;
  QAction* slower;
  QAction* faster;

 private:
  void makeActions();
  void showPlaying(bool on);

  MainWindow& w_;
  CrankBar* crankBar_;
};

}  // namespace linkage::ui
