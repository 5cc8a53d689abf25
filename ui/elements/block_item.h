// A slider's block: a rounded rectangle aligned with its slot, in its body's colour (or its
// mechanism's), made by the slider's kind (slider_ui.cpp). The block is a body of its own: a
// click on it picks that body. Sizes in screen pixels (CanvasStyle).
#pragma once

#include "elements/joint_item.h"

namespace linkage::ui {

class BlockItem : public JointItem {
 public:
  BlockItem(const CanvasContext* ctx, JointId joint, BodyId body, int number);
  BodyId body() const { return body_; }
  void place(const JointSymbol& s) override { setPlacement(s.at, s.direction); }
  void setPlacement(const Vec2& at, const Vec2& direction);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;
  // Its mechanism's colour (linkage/mechanisms.h); invalid: its body's own.
  void setColour(const QColor& c);
  QColor colour() const { return colour_; }
  void setBodyColours(const std::function<QColor(BodyId)>& colourOf) override {
    setColour(colourOf(body_));
  }
  BodyId drawnBody() const override { return body_; }

 private:
  BodyId body_;
  int number_;
  QColor colour_;
};

}  // namespace linkage::ui
