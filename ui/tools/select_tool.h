// Select (S, Esc): a click selects a point, a joint, a slot or a body (Shift adds or removes);
// a drag over empty canvas selects what the rubber band holds. Dragging a point moves the
// mechanism along its freedom, the crank turning so that the point follows the mouse as a hand
// pushing it would; with Ctrl held it changes the design instead (the point, and the points
// pinned to it, move in their bodies; everything re-solves as the mouse moves). A drag starts
// after a few pixels, solves at most once per painted frame, and a design drag is one undo
// step.
#pragma once

#include <QTimer>
#include <optional>

#include "document/document.h"
#include "tools/tool.h"

namespace linkage::ui {

class SelectTool : public Tool {
  Q_OBJECT

 public:
  explicit SelectTool(ToolContext* ctx);
  QString hint() const override;
  bool snaps() const override { return false; }
  void deactivate() override;
  void press(const CanvasMouse& e) override;
  void move(const CanvasMouse& e) override;
  void release(const CanvasMouse& e) override;
  bool key(QKeyEvent* e) override;
  bool dragging() const { return mode_ == Mode::Turn || mode_ == Mode::Reshape; }

 private:
  enum class Mode { Idle, Pressed, Band, Turn, Reshape };
  void select(const Pick& p, bool toggle);
  void selectBand(const QRectF& r, bool add);
  void beginDrag(const CanvasMouse& e);
  void solvePending();
  void endDrag(bool keep);

  Mode mode_ = Mode::Idle;
  CanvasMouse pressed_;
  PointId dragPoint_;
  Vec2 target_ = Vec2::Zero();
  bool pending_ = false;
  QTimer frame_;  // one solve per painted frame: the latest target wins
  std::optional<DocumentState> before_;
  std::vector<std::pair<PointId, Transform>> moving_;  // points moved and their bodies' poses
  double gridStep_ = 0;
};

}  // namespace linkage::ui
