#include "elements/ball_rod_item.h"

#include <QPainter>

namespace linkage::ui {

namespace {
// Over the bodies, under the pins: a rod runs over what it joins.
constexpr double kRodZ = 25;
}  // namespace

BallRodItem::BallRodItem(const CanvasContext* ctx, JointId joint) : JointItem(ctx, joint) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(kRodZ);
}

void BallRodItem::place(const JointSymbol& s) {
  prepareGeometryChange();
  a_ = s.at;
  b_ = s.at2;
  update();
}

QRectF BallRodItem::boundingRect() const {
  const double m = (CanvasStyle::pinRadius + 6) * px();
  return QRectF(QPointF(std::min(a_.x(), b_.x()), std::min(a_.y(), b_.y())),
                QPointF(std::max(a_.x(), b_.x()), std::max(a_.y(), b_.y())))
      .adjusted(-m, -m, m, m);
}

void BallRodItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  const QColor ink = flagged() ? st.warning : st.ink;
  p->setPen(cosmetic(ink, 3));
  p->drawLine(QPointF(a_.x(), a_.y()), QPointF(b_.x(), b_.y()));
  p->setPen(cosmetic(ink, CanvasStyle::outline));
  p->setBrush(st.paper);
  const double r = CanvasStyle::pinRadius * u;
  for (const Vec2& e : {a_, b_}) p->drawEllipse(QPointF(e.x(), e.y()), r, r);
}

double BallRodItem::distanceToLines(const Vec2& at) const {
  const Vec2 d = b_ - a_;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((at - a_).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a_ + t * d - at).norm();
}

QPainterPath BallRodItem::lines() const {
  QPainterPath path;
  path.moveTo(a_.x(), a_.y());
  path.lineTo(b_.x(), b_.y());
  return path;
}

}  // namespace linkage::ui
