// What every dock's panel shares (the plots, the forces, the cycle, the instant centres, the
// design checks): work only for what is seen. An edit or a new pose marks what a panel shows
// stale; a stale panel that is seen computes again (at once, at the next turn of the event loop
// or at most 30 times a second: Redraw), one that is not seen computes nothing and does its
// work when it comes into view.
//
// Seen: shown, and, for a panel that rests behind a tab (Behind::Rests), its dock not a tab
// behind another. Qt moves a dock whose tab is behind another off the window and leaves it
// "visible"; such a panel follows its dock's visibilityChanged by itself (queued: the dock
// tells before its contents know).
//
// A panel derives from it, does its work in compute(), and calls markStale() when what it
// shows is no longer of the document.
#pragma once

#include <QPointer>
#include <QWidget>

#include "figures/redraw_throttle.h"

class QDockWidget;

namespace linkage::ui {

class DockPanel : public QWidget {
  Q_OBJECT

 public:
  // How soon a stale panel that is seen computes again.
  enum class Redraw {
    Now,        // at once: tables a user reads after each edit, cheap to fill
    NextTurn,   // once per turn of the event loop, however often asked
    Throttled,  // at most 30 times a second: figures of a whole turn, a few ms each
  };

  // Whether a panel whose dock is a tab behind another works on.
  enum class Behind {
    Works,  // as long as it is shown, in front or not (the plots', forces' and cycle docks,
            // tabs of one another; the cycle's clearances stay on the canvas)
    Rests,  // read in the dock only: nothing computed until its tab is in front
  };

  DockPanel(Redraw redraw, Behind behind, QWidget* parent = nullptr);

  // Seen: shown, and, if it rests behind a tab, its dock's tab in front.
  bool shown() const;
  // A throttled computation is yet to run.
  bool redrawPending() const { return throttle_.pending(); }

 protected:
  // What is shown is of a design or pose before: computed again soon while seen, otherwise
  // when the panel comes into view.
  void markStale();
  // Computed again as markStale() does, what is shown still of the document meanwhile (a
  // preview following the mouse).
  void schedule();
  bool stale() const { return stale_; }
  // Computes now if stale (the panel comes into view; an export asks while it is hidden).
  void ensureComputed();
  // Computes now: the pending request done, the results fresh.
  void recompute();

  // The panel's work, from the document as it is now.
  virtual void compute() = 0;
  // The panel came into view, its results fresh: what follows the pose (a cursor) follows it.
  virtual void cameIntoView() {}
  // It left the view (hidden, or its tab behind another): what it shows elsewhere (the
  // canvas) is taken back.
  virtual void leftView() {}

  void showEvent(QShowEvent* e) override;
  void hideEvent(QHideEvent* e) override;

 private:
  void followDock();
  void viewChanged();

  Redraw redraw_;
  Behind behind_;
  bool stale_ = true;
  QPointer<QDockWidget> dock_;
  QMetaObject::Connection dockSeen_;
  RedrawThrottle throttle_;
};

}  // namespace linkage::ui
