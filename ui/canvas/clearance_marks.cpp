#include "canvas/clearance_marks.h"

#include <QPainter>

namespace linkage::ui {

namespace {
constexpr double kRingPx = 5;  // the rings' radius on screen
}

ClearanceMarksItem::ClearanceMarksItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setZValue(60);  // over the mechanism, under the tools' overlays
}

void ClearanceMarksItem::setMarks(std::vector<ClearanceMark> marks) {
  prepareGeometryChange();
  marks_ = std::move(marks);
  rebuild();
  update();
}

void ClearanceMarksItem::rebuild() {
  for (LabelItem* l : labels_) delete l;
  labels_.clear();
  for (const ClearanceMark& m : marks_) {
    auto* l = new LabelItem(m.text, this);
    const Vec2 mid = 0.5 * (m.a + m.b);
    l->setPos(mid.x(), mid.y());
    l->setOffset(QPointF(0, -14));
    l->setColours(m.tooClose ? style().warning : style().ink, style().paper);
    l->setBold(m.tooClose);
    labels_.push_back(l);
  }
}

QRectF ClearanceMarksItem::boundingRect() const {
  QRectF r;
  const double pad = 2 * kRingPx * px();
  for (const ClearanceMark& m : marks_)
    r |= QRectF(QPointF(std::min(m.a.x(), m.b.x()), std::min(m.a.y(), m.b.y())),
                QPointF(std::max(m.a.x(), m.b.x()), std::max(m.a.y(), m.b.y())))
             .adjusted(-pad, -pad, pad, pad);
  return r;
}

void ClearanceMarksItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  const double r = kRingPx * px();
  for (const ClearanceMark& m : marks_) {
    const QColor c = m.tooClose ? style().warning : style().ink;
    p->setPen(cosmetic(c, 1.2, Qt::DashLine));
    p->drawLine(QPointF(m.a.x(), m.a.y()), QPointF(m.b.x(), m.b.y()));
    p->setPen(cosmetic(c, 1.5));
    p->drawEllipse(QPointF(m.a.x(), m.a.y()), r, r);
    p->drawEllipse(QPointF(m.b.x(), m.b.y()), r, r);
  }
}

}  // namespace linkage::ui
