// A cam and its follower (the cam element, solver/elements/cam.cpp): the cam's working surface
// (its profile, linkage/cam_geometry.h) turning with the cam's body about its centre, filled in
// the body's colour, its pitch curve dotted (a roller's), and the follower's roller (a circle
// at b) or flat face (a line through b normal to its motion); a knife edge is its point on the
// surface. Picked by the surface.
#pragma once

#include "elements/joint_item.h"

namespace linkage::ui {

class CamItem : public JointItem {
 public:
  CamItem(const CanvasContext* ctx, const JointSymbol& s, QColor colour);
  void place(const JointSymbol& s) override;
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  void setBodyColours(const std::function<QColor(BodyId)>& colourOf) override;
  bool pickedByLines() const override { return true; }
  double distanceToLines(const Vec2& at) const override;
  QPainterPath lines() const override;

 private:
  // The surface at the current pose, about the cam's centre (item coordinates).
  QPolygonF surface() const;

  JointSymbol s_;
  QColor colour_, own_;
};

}  // namespace linkage::ui
