// A joint's symbol on the canvas, as its kind draws it (each kind's item is in its own files
// here, made by its ElementUi::item): placed from its JointSymbol at each pose; flagged (the
// warning colour) when a failure or the structure analysis names it. What the canvas and the
// tools ask of a joint's symbol is asked here, so that they never ask which kind it is.
#pragma once

#include <QColor>
#include <QPainterPath>
#include <cmath>
#include <functional>

#include "draw/canvas_item.h"
#include "linkage/drawing.h"

namespace linkage::ui {

class JointItem : public CanvasItem {
 public:
  JointItem(const CanvasContext* ctx, JointId joint) : CanvasItem(ctx), joint_(joint) {}
  JointId joint() const { return joint_; }
  virtual void place(const JointSymbol& s) = 0;
  void setFlagged(bool on);
  bool flagged() const { return flagged_; }

  // The colours of the mechanisms (linkage/mechanisms.h) for the bodies it draws in their
  // colours: `colourOf` a body, invalid for the body's own.
  virtual void setBodyColours(const std::function<QColor(BodyId)>& colourOf) { (void)colourOf; }
  // The body it draws (a slider's block), picked where its shape holds the cursor; invalid:
  // none.
  virtual BodyId drawnBody() const { return {}; }
  // A symbol aimed at by lines of its own, having no point to click (a gear's pitch circles, a
  // belt's runs): what a click finds it by, in scene coordinates (mm): the distance to its
  // lines, and the radius of its smallest circle that holds the point (else infinity); its
  // lines in scene coordinates, to outline it selected or under the cursor.
  virtual bool pickedByLines() const { return false; }
  virtual double distanceToLines(const Vec2&) const { return INFINITY; }
  virtual double radiusHolding(const Vec2&) const { return INFINITY; }
  virtual QPainterPath lines() const { return {}; }

 private:
  JointId joint_;
  bool flagged_ = false;
};

}  // namespace linkage::ui
