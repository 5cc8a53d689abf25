// A gear or belt coupling (the gear element, solver/elements/gear.cpp): an external gear pair as
// its two pitch circles touching at the pitch point, a belt as two pulleys and the belt's two
// straight runs; a radial tick on each circle turns with its body, so that the ratio shows as
// the animation runs.
#pragma once

#include <utility>
#include <vector>

#include "elements/joint_item.h"

namespace linkage::ui {

class GearItem : public JointItem {
 public:
  GearItem(const CanvasContext* ctx, const JointSymbol& s, QColor colourA, QColor colourB);
  void place(const JointSymbol& s) override;
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  // The body on side k (0: of point a, 1: of b), and its mechanism's colour (invalid: the
  // body's own), so that a coloured mechanism's pulley or gear is in its colour too.
  BodyId body(int k) const { return s_.bodies[k]; }
  void setBodyColour(int k, const QColor& c);
  QColor bodyColour(int k) const { return colour_[k]; }
  void setBodyColours(const std::function<QColor(BodyId)>& colourOf) override;

  // What a click finds it by, in scene coordinates (mm): the distance to its drawn lines (the
  // pitch circles, which touch at a gear pair's pitch point, and a belt's runs), and the
  // radius of its smallest pitch circle that holds the point (its centre area; else infinity).
  bool pickedByLines() const override { return true; }
  double distanceToLines(const Vec2& at) const override;
  double radiusHolding(const Vec2& at) const override;
  // Its drawn lines in scene coordinates, to outline it selected or under the cursor.
  QPainterPath lines() const override;

 private:
  // A belt's two straight runs (item coordinates), from pulley a to pulley b; none for gears
  // or pulleys that overlap.
  std::vector<std::pair<Vec2, Vec2>> beltRuns() const;
  Vec2 centre(int k) const { return k == 0 ? Vec2::Zero() : Vec2(s_.at2 - s_.at); }

  JointSymbol s_;
  QColor colour_[2], own_[2];
};

}  // namespace linkage::ui
