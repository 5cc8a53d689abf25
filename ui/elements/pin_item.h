// A pin as a textbook draws it: a small circle over the bodies it joins; a ground pivot (a pin
// to the ground) standing on a hatched base; a pin in a slot filled. The pin's and the pin in a
// slot's kinds make it (pin_ui.cpp, pin_in_slot_ui.cpp). Sizes in screen pixels (CanvasStyle).
#pragma once

#include "elements/joint_item.h"

namespace linkage::ui {

class PinItem : public JointItem {
 public:
  enum class Kind { Pin, GroundPivot, InSlot };
  PinItem(const CanvasContext* ctx, JointId joint, Kind kind);
  void place(const JointSymbol& s) override { setAt(s.at); }
  void setAt(const Vec2& at);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  Kind kind_;
};

}  // namespace linkage::ui
