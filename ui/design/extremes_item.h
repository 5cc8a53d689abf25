// The mechanism drawn faintly at the extreme positions of a point (or of a body's angle), as
// the paper of seed 001 draws its figure 2b: every moving body's outline, its pins and blocks,
// thin and light, at each crank angle findLimits reports, with the point marked there; for a
// point, the stroke as a dimension beside it with every extreme at its height ("max 131.20 mm
// (crank 87.3°)"); for a body, each extreme's label at the body's mark. The poses are computed once
// per design (on a copy of the document's solver); the item only paints them.
#pragma once

#include <vector>

#include <memory>

#include "canvas/canvas_item.h"
#include "design/overlay_labels.h"
#include "linkage/drawing.h"
#include "linkage/limits.h"

namespace linkage::ui {

struct ExtremePose {
  Extreme extreme;
  Drawing drawing;         // the mechanism at the extreme's crank angle
  Vec2 at = Vec2::Zero();  // the point there (a body's subject: its first point)
};

struct ExtremePoses {
  LimitMeasure measure;
  Limits limits;                   // findLimits's answer; status says why there are no poses
  std::vector<ExtremePose> poses;  // one per extreme, crank order
  QString label;                   // the point's "body.point", or the body's name
};

// findLimits on k, then a copy of k turned to each extreme (from crank angle 0 forwards, as
// findLimits turns its own).
ExtremePoses findExtremePoses(const Kinematics& k, const LimitMeasure& what);

class ExtremesItem : public CanvasItem {
 public:
  ExtremesItem(const CanvasContext* ctx, std::shared_ptr<LabelBoard> board);
  void setPoses(ExtremePoses poses);
  void clear();
  const ExtremePoses& poses() const { return poses_; }

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 protected:
  void rebuild() override;

 private:
  struct Ghost {
    std::vector<std::pair<QPolygonF, int>> outlines;  // world polygons with the body's number
    std::vector<QPointF> pins;
  };
  std::shared_ptr<LabelBoard> board_;
  ExtremePoses poses_;
  std::vector<Ghost> ghosts_;  // [pose]
};

}  // namespace linkage::ui
