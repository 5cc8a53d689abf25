#include "canvas/output_item.h"

#include <QPainter>

namespace linkage::ui {

OutputItem::OutputItem(const CanvasContext* ctx, PointId point, const QString& label)
    : CanvasItem(ctx), point_(point), label_(new LabelItem(label, this)) {
  setToolTip(QStringLiteral("output point %1").arg(label));
  setAcceptedMouseButtons(Qt::NoButton);
  rebuild();
}

void OutputItem::rebuild() {
  const QRectF r = label_->boundingRect();
  // Right of the point and a little below, clear of the centres' labels (above right).
  label_->setOffset(QPointF(r.width() / 2 + 10, 12));
  label_->setColours(style().trace, style().paper);
}

QRectF OutputItem::boundingRect() const {
  const double r = (CanvasStyle::outputRadius + 5) * px();
  return QRectF(-r, -r, 2 * r, 2 * r);
}

void OutputItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const double r = CanvasStyle::outputRadius * px();
  p->setRenderHint(QPainter::Antialiasing);
  p->setPen(cosmetic(style().trace, 1.0));
  p->setBrush(Qt::NoBrush);
  p->drawEllipse(QPointF(0, 0), r, r);
  p->drawLine(QPointF(-r - 3 * px(), 0), QPointF(r + 3 * px(), 0));
  p->drawLine(QPointF(0, -r - 3 * px()), QPointF(0, r + 3 * px()));
}

}  // namespace linkage::ui
