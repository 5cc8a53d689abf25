#include "canvas/gear_item.h"

#include <QPainter>
#include <cmath>

namespace linkage::ui {

GearItem::GearItem(const CanvasContext* ctx, const JointSymbol& s, QColor colourA, QColor colourB)
    : JointItem(ctx, s.joint), s_(s), colour_{colourA, colourB}, own_{colourA, colourB} {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(kGearZ);
}

void GearItem::setBodyColour(int k, const QColor& c) {
  const QColor next = c.isValid() ? c : own_[k];
  if (next == colour_[k]) return;
  colour_[k] = next;
  update();
}

void GearItem::place(const JointSymbol& s) {
  prepareGeometryChange();
  s_ = s;
  setPos(s.at.x(), s.at.y());
}

QRectF GearItem::boundingRect() const {
  const Vec2 b = s_.at2 - s_.at;
  const double r = std::max(s_.radius[0], s_.radius[1]) + 4 * px();
  return QRectF(QPointF(std::min(0.0, b.x()) - r, std::min(0.0, b.y()) - r),
                QPointF(std::max(0.0, b.x()) + r, std::max(0.0, b.y()) + r));
}

void GearItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  const QPointF c[2] = {QPointF(0, 0), QPointF(s_.at2.x() - s_.at.x(), s_.at2.y() - s_.at.y())};
  const double base = std::atan2(s_.direction.y(), s_.direction.x());
  for (int k = 0; k < 2; ++k) {
    const double r = s_.radius[k];
    if (!(r > 0)) continue;
    const QColor ink = flagged() ? st.warning : colour_[k];
    p->setPen(cosmetic(ink, 1.6, s_.belt ? Qt::SolidLine : Qt::DashLine));
    p->drawEllipse(c[k], r, r);
    // The tick: the body's rotation from the drawing, from the line of centres as drawn.
    const double a = base + s_.angle[k];
    p->setPen(cosmetic(ink, 1.6));
    p->drawLine(c[k], c[k] + QPointF(r * std::cos(a), r * std::sin(a)));
  }
  if (!s_.belt) return;
  // The belt's straight runs: the outer tangents, n . u = (ra - rb) / d on both sides.
  const Vec2 d = s_.at2 - s_.at;
  const double len = d.norm(), ra = s_.radius[0], rb = s_.radius[1];
  if (!(len > std::abs(ra - rb))) return;
  const Vec2 u = d / len;
  const double along = (ra - rb) / len, across = std::sqrt(1 - along * along);
  p->setPen(cosmetic(flagged() ? st.warning : st.ink, 1.6));
  for (double side : {1.0, -1.0}) {
    const Vec2 n = along * u + side * across * perp(u);
    const Vec2 pa = ra * n, pb = d + rb * n;
    p->drawLine(QPointF(pa.x(), pa.y()), QPointF(pb.x(), pb.y()));
  }
}

}  // namespace linkage::ui
