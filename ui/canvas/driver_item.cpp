#include "canvas/driver_item.h"

#include <QPainter>
#include <QtMath>

namespace linkage::ui {

DriverItem::DriverItem(const CanvasContext* ctx, bool ccw, const QString& tip)
    : CanvasItem(ctx), ccw_(ccw) {
  setToolTip(tip);
}

QRectF DriverItem::boundingRect() const {
  const double r = (CanvasStyle::driverRadius + 8) * px();
  return QRectF(-r, -r, 2 * r, 2 * r);
}

void DriverItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double r = CanvasStyle::driverRadius * px();
  p->setRenderHint(QPainter::Antialiasing);
  QPen pen = cosmetic(st.ink, 1.0);
  pen.setCapStyle(Qt::RoundCap);
  p->setPen(pen);
  p->setBrush(Qt::NoBrush);
  // A 270 degree arc from the right; the head at its end shows the driving direction. The scene
  // has y up: angles count counter-clockwise as seen.
  const double start = 20, span = 270;
  QPainterPath arc;
  arc.arcMoveTo(QRectF(-r, -r, 2 * r, 2 * r), start);
  arc.arcTo(QRectF(-r, -r, 2 * r, 2 * r), start, span);
  p->drawPath(arc);
  // arcTo measures angles with y down: in this y-up scene the point at angle a is
  // (cos a, -sin a), which turns clockwise as seen when a grows. The head is at the end the
  // driving direction reaches, pointing along it.
  const double a = qDegreesToRadians(ccw_ ? start : start + span);
  const QPointF tip(r * std::cos(a), -r * std::sin(a));
  const QPointF t = ccw_ ? QPointF(std::sin(a), std::cos(a)) : QPointF(-std::sin(a), -std::cos(a));
  const QPointF n(-t.y(), t.x());
  const double h = 7 * px();
  QPolygonF head;
  head << tip + t * h << tip - t * 0.2 * h + n * 0.6 * h << tip - t * 0.2 * h - n * 0.6 * h;
  p->setBrush(st.ink);
  p->drawPolygon(head);
}

}  // namespace linkage::ui
