// The clearances a machine's Cycle dock watches, on the canvas: for each, where its two things
// are at their closest approach over the cycle (a ring at each, a dashed line between them) with
// the distance and the crank angle, in the warning colour when it is under the least allowed.
// The closest pose is usually not the pose shown: the marks say where the parts will meet, and
// a segment or slot measured to is drawn where it is then (a needle lower than drawn: the ring
// on it, not below its point as drawn).
#pragma once

#include <QString>
#include <vector>

#include "draw/canvas_item.h"
#include "linkage/geometry.h"
#include "linkage/model.h"

namespace linkage::ui {

class LabelItem;

// As the solver gives them (world, mm; a machine in space: a in its body's plane class frame,
// b and part in the other body's); the item draws them in the canvas's plane
// (CanvasContext::view).
struct ClearanceMark {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();  // world, mm
  QString text;                             // "hook.K – needlebar.N: closest 0.42 mm at 201.3°"
  bool tooClose = false;
  std::vector<Vec2> part;  // the segment or slot at that pose (world, mm); empty for a point
  BodyId bodyA, bodyB;     // whose frames a, and b and part, are in
};

class ClearanceMarksItem : public CanvasItem {
 public:
  explicit ClearanceMarksItem(const CanvasContext* ctx);
  void setMarks(std::vector<ClearanceMark> marks);
  const std::vector<ClearanceMark>& marks() const { return marks_; }
  // As drawn: in the canvas's plane.
  const std::vector<ClearanceMark>& shownMarks() const { return shown_; }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 protected:
  void rebuild() override;

 private:
  std::vector<ClearanceMark> marks_, shown_;
  std::vector<LabelItem*> labels_;
};

}  // namespace linkage::ui
