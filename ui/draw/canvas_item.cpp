#include "draw/canvas_item.h"

#include <QFontMetricsF>
#include <QPainter>

namespace linkage::ui {

QPointF toQt(const Vec2& v) {
  return QPointF(v.x(), v.y());
}

QTransform toQt(const Transform& t) {
  // world = R sketch + t; QTransform maps (x, y) to (m11 x + m21 y + dx, m12 x + m22 y + dy).
  return QTransform(t.R.c, t.R.s, -t.R.s, t.R.c, t.t.x(), t.t.y());
}

QPolygonF cutToDevice(const QPolygonF& poly, const QPainter* p) {
  const QRectF device(0, 0, p->device()->width(), p->device()->height());
  const QRectF b = p->worldTransform().mapRect(poly.boundingRect());
  if (b.width() <= 4 * device.width() && b.height() <= 4 * device.height()) return poly;
  const QRectF around =
      device.adjusted(-device.width(), -device.height(), device.width(), device.height());
  return poly.intersected(p->worldTransform().inverted().map(QPolygonF(around)));
}

LabelItem::LabelItem(const QString& text, QGraphicsItem* parent)
    : QGraphicsItem(parent), text_(text) {
  setFlag(ItemIgnoresTransformations);
  setAcceptedMouseButtons(Qt::NoButton);
}

void LabelItem::setText(const QString& text) {
  if (text == text_) return;
  prepareGeometryChange();
  text_ = text;
}

void LabelItem::setColours(const QColor& ink, const QColor& halo) {
  ink_ = ink;
  halo_ = halo;
  update();
}

void LabelItem::setOffset(const QPointF& offset) {
  prepareGeometryChange();
  offset_ = offset;
}

void LabelItem::setBold(bool bold) {
  prepareGeometryChange();
  bold_ = bold;
}

QRectF LabelItem::textRect() const {
  QFont f;
  f.setBold(bold_);
  const QRectF r = QFontMetricsF(f).boundingRect(text_);
  return QRectF(offset_.x() - r.width() / 2, offset_.y() - r.height() / 2, r.width(), r.height());
}

QRectF LabelItem::boundingRect() const {
  return textRect().adjusted(-3, -3, 3, 3);
}

void LabelItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  QFont f = p->font();
  f.setBold(bold_);
  p->setFont(f);
  const QRectF r = textRect();
  // A backing of the paper colour keeps it legible over lines (cheaper than a halo).
  QColor back = halo_;
  back.setAlphaF(0.7);
  p->fillRect(r.adjusted(-2, 0, 2, 0), back);
  p->setPen(ink_);
  p->drawText(r, Qt::AlignCenter, text_);
}

}  // namespace linkage::ui
