#include "elements/pin_item.h"

#include <QPainter>

namespace linkage::ui {

namespace {
// Over the bodies (at 0), the gears and the blocks; under the driver and outputs.
constexpr double kPinZ = 30;
}  // namespace

PinItem::PinItem(const CanvasContext* ctx, JointId joint, Kind kind)
    : JointItem(ctx, joint), kind_(kind) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(kPinZ);
}

void PinItem::setAt(const Vec2& at) {
  setPos(at.x(), at.y());
}

QRectF PinItem::boundingRect() const {
  const double s =
      (kind_ == Kind::GroundPivot ? CanvasStyle::pivotSize * 1.6 + 4 : CanvasStyle::pinRadius + 6) *
      px();
  return QRectF(-s, -s, 2 * s, 2 * s);
}

void PinItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  const QColor ink = flagged() ? st.warning : st.ink;
  if (kind_ == Kind::GroundPivot) {
    // A triangle under the pin standing on a hatched base (y is up in the scene).
    const double h = CanvasStyle::pivotSize * u, b = 0.75 * h;
    QPolygonF tri;
    tri << QPointF(0, 0) << QPointF(-b, -h) << QPointF(b, -h);
    p->setPen(cosmetic(ink, CanvasStyle::outline));
    p->setBrush(st.paper);
    p->drawPolygon(tri);
    p->drawLine(QPointF(-1.5 * b, -h), QPointF(1.5 * b, -h));
    p->setPen(cosmetic(st.faint, 1));
    for (double x = -1.4 * b; x <= 1.5 * b; x += 4.5 * u)
      p->drawLine(QPointF(x, -h), QPointF(x - 4.5 * u, -h - 5 * u));
  }
  const double r = CanvasStyle::pinRadius * u;
  p->setPen(cosmetic(ink, flagged() ? 2.4 : CanvasStyle::outline));
  p->setBrush(kind_ == Kind::InSlot ? st.ink : st.paper);
  p->drawEllipse(QPointF(0, 0), r, r);
  if (flagged()) {
    p->setPen(cosmetic(st.warning, 2));
    p->setBrush(Qt::NoBrush);
    p->drawEllipse(QPointF(0, 0), 2.6 * r, 2.6 * r);
  }
}

}  // namespace linkage::ui
