#include "docks/dock_panel.h"

#include <QDockWidget>

namespace linkage::ui {

DockPanel::DockPanel(Redraw redraw, Behind behind, QWidget* parent)
    : QWidget(parent),
      redraw_(redraw),
      behind_(behind),
      throttle_(
          this,
          [this] {
            // Hidden meanwhile: done when it comes into view again.
            if (shown()) recompute();
          },
          redraw == Redraw::Throttled ? 33 : 0) {}

bool DockPanel::shown() const {
  if (!isVisible()) return false;
  if (!dock_ || dock_->isFloating() || !dock_->parentWidget()) return true;
  // A dock whose tab is behind another's is moved off its window (QDockAreaLayoutInfo).
  return dock_->parentWidget()->rect().intersects(dock_->geometry());
}

void DockPanel::markStale() {
  stale_ = true;
  schedule();
}

void DockPanel::schedule() {
  if (!shown()) return;
  if (redraw_ == Redraw::Now)
    recompute();
  else
    throttle_.ask();
}

void DockPanel::ensureComputed() {
  if (stale_) recompute();
}

void DockPanel::recompute() {
  throttle_.done();
  stale_ = false;
  compute();
}

void DockPanel::showEvent(QShowEvent* e) {
  QWidget::showEvent(e);
  followDock();
  viewChanged();
}

void DockPanel::hideEvent(QHideEvent* e) {
  QWidget::hideEvent(e);
  leftView();
}

void DockPanel::followDock() {
  if (behind_ == Behind::Works) return;
  QDockWidget* dock = nullptr;
  for (QWidget* p = parentWidget(); p && !dock; p = p->parentWidget())
    dock = qobject_cast<QDockWidget*>(p);
  if (dock == dock_) return;
  disconnect(dockSeen_);
  dock_ = dock;
  if (dock)
    dockSeen_ = connect(dock, &QDockWidget::visibilityChanged, this, &DockPanel::viewChanged,
                        Qt::QueuedConnection);
}

void DockPanel::viewChanged() {
  if (shown()) {
    ensureComputed();
    cameIntoView();
  } else {
    leftView();
  }
}

}  // namespace linkage::ui
