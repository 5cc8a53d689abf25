#include "tools/pick_point_tool.h"

#include "canvas/canvas_scene.h"

namespace linkage::ui {

void PickPointTool::start(const QString& purpose, std::function<void(PointId)> picked,
                          std::function<void()> cancelled) {
  purpose_ = purpose;
  picked_ = std::move(picked);
  cancelled_ = std::move(cancelled);
  emit hintChanged();
}

QString PickPointTool::hint() const {
  return tr("Pick %1: click a point on the canvas (Esc cancels)").arg(purpose_);
}

// Left without a point (Esc, another tool, a new document): the one who asked is told.
void PickPointTool::deactivate() {
  auto cancelled = std::move(cancelled_);
  picked_ = nullptr;
  cancelled_ = nullptr;
  if (cancelled) cancelled();
}

void PickPointTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  if (!e.pick.point) {
    say(tr("No point there: click on a point to pick %1 (Esc cancels)").arg(purpose_), true);
    return;
  }
  // Handed over before the tool is left, so that leaving it does not cancel.
  auto picked = std::move(picked_);
  picked_ = nullptr;
  cancelled_ = nullptr;
  emit finished();
  if (picked) picked(e.pick.point);
}

bool PickPointTool::key(QKeyEvent* e) {
  if (e->key() != Qt::Key_Escape) return false;
  emit finished();  // the select tool again; deactivate() cancels
  return true;
}

}  // namespace linkage::ui
