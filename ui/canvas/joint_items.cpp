#include "canvas/joint_items.h"

#include <QPainter>
#include <QtMath>

namespace linkage::ui {

void JointItem::setFlagged(bool on) {
  if (on == flagged_) return;
  flagged_ = on;
  update();
}

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
