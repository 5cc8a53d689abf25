#include "elements/block_item.h"

#include <QPainter>
#include <QtMath>

namespace linkage::ui {

namespace {
// Over the bodies (at 0) and the gears, under the pins.
constexpr double kBlockZ = 20;
}  // namespace

BlockItem::BlockItem(const CanvasContext* ctx, JointId joint, BodyId body, int number)
    : JointItem(ctx, joint), body_(body), number_(number) {
  setAcceptHoverEvents(true);
  setZValue(kBlockZ);
}

void BlockItem::setPlacement(const Vec2& at, const Vec2& direction) {
  setPos(at.x(), at.y());
  setRotation(qRadiansToDegrees(std::atan2(direction.y(), direction.x())));
}

QRectF BlockItem::boundingRect() const {
  const double l = (CanvasStyle::blockLength / 2 + 2) * px(),
               w = (CanvasStyle::blockWidth / 2 + 2) * px();
  return QRectF(-l, -w, 2 * l, 2 * w);
}

void BlockItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double l = CanvasStyle::blockLength / 2 * px(), w = CanvasStyle::blockWidth / 2 * px();
  p->setRenderHint(QPainter::Antialiasing);
  const QColor line = flagged() ? st.warning : colour_.isValid() ? colour_ : st.body(number_);
  QColor fill = line;
  fill.setAlphaF(st.dark ? 0.55 : 0.45);
  p->setPen(cosmetic(line, flagged() ? 2.4 : CanvasStyle::outline));
  p->setBrush(fill);
  p->drawRoundedRect(QRectF(-l, -w, 2 * l, 2 * w), 1.5 * px(), 1.5 * px());
}

void BlockItem::setColour(const QColor& c) {
  if (c == colour_) return;
  colour_ = c;
  update();
}

}  // namespace linkage::ui
