// The mechanism drawn faintly at the extreme positions of a point (or of a body's angle), as
// the paper of seed 001 draws its figure 2b: every moving body's outline, its pins and blocks,
// thin and light, at each crank angle findLimits reports, under the mechanism. Their marks,
// values and the stroke are drawn over it by ExtremesNotes (extremes_notes.h). The poses are
// computed once per design (on a copy of the document's solver); the items only paint them.
#pragma once

#include <vector>

#include "draw/canvas_item.h"
#include "linkage/drawing.h"
#include "linkage/limits.h"

namespace linkage::ui {

struct ExtremePose {
  LocalExtreme extreme;
  Drawing drawing;         // the mechanism at the extreme's crank angle
  Vec2 at = Vec2::Zero();  // the point there (a body's subject: its first point)
};

struct ExtremePoses {
  LimitMeasure measure;
  Limits limits;                   // findLimits's answer; status says why there are no poses
  std::vector<ExtremePose> poses;  // one per extreme, crank order
  Status status;                   // the copy's turn to the extremes: why poses stop short
};

// findLimits on k, then a copy of k turned to each extreme (from crank angle 0 forwards, as
// findLimits turns its own).
ExtremePoses findExtremePoses(const Kinematics& k, const LimitMeasure& what);

class ExtremesItem : public CanvasItem {
 public:
  explicit ExtremesItem(const CanvasContext* ctx);
  void setPoses(ExtremePoses poses);
  void clear();
  const ExtremePoses& poses() const { return poses_; }
  // The item that marks the positions and labels them (above the mechanism), repainted with it.
  void setNotes(QGraphicsItem* notes) { notes_ = notes; }

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 protected:
  void rebuild() override;

 private:
  struct Ghost {
    std::vector<std::pair<QPolygonF, int>> outlines;  // world polygons with the body's number
    std::vector<QPointF> pins;
  };
  QGraphicsItem* notes_ = nullptr;
  ExtremePoses poses_;
  std::vector<Ghost> ghosts_;  // [pose]
};

}  // namespace linkage::ui
