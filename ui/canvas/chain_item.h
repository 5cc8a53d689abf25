// The distances of a velocity chain (instant centres) drawn as dimension lines, as a hand
// solution measures them with a ruler: |IC(1,from) P| and |IC(1,to) P| at each step and the
// arm of the point about its body's centre, each with its length.
#pragma once

#include <optional>

#include "draw/canvas_item.h"
#include "linkage/velocity_chain.h"

namespace linkage::ui {

class ChainItem : public CanvasItem {
 public:
  explicit ChainItem(const CanvasContext* ctx);
  struct Dimension {
    Vec2 a, b;
    QString label;
  };
  void setChain(const std::optional<VelocityChain>& chain);
  const std::vector<Dimension>& dimensions() const { return dims_; }
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  std::vector<Dimension> dims_;
};

}  // namespace linkage::ui
