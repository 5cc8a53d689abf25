// When a dock's figure is made again. Asked again and again (an edit dragged with the mouse
// changes the design at every move, between two paints), the work runs once per burst and at
// most 30 times a second: a figure costs a few milliseconds, which a drag's every frame cannot
// spare, and the eye does not follow curves faster. Nothing runs while the owner is hidden.
// The docks' panels use it through their base (docks/dock_panel.h).
#pragma once

#include <QElapsedTimer>
#include <QPointer>
#include <QWidget>
#include <functional>

namespace linkage::ui {

class RedrawThrottle {
 public:
  // `minMs`: the least time between two runs (0: once per turn of the event loop).
  RedrawThrottle(QWidget* owner, std::function<void()> work, int minMs = 33);
  // The work runs soon, unless the owner is hidden or it is already to run.
  void ask();
  // The work ran (or runs now) of itself: what was asked is done.
  void done();
  bool pending() const { return pending_; }

 private:
  QPointer<QWidget> owner_;
  std::function<void()> work_;
  int minMs_;
  bool pending_ = false;
  QElapsedTimer last_;
};

}  // namespace linkage::ui
