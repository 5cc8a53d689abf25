#include "elements/gear_item.h"

#include <QPainter>
#include <algorithm>
#include <cmath>

namespace linkage::ui {

namespace {
// Over the bodies (at 0), under the blocks and pins.
constexpr double kGearZ = 10;
}  // namespace

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

void GearItem::setBodyColours(const std::function<QColor(BodyId)>& colourOf) {
  for (int side : {0, 1}) setBodyColour(side, colourOf(body(side)));
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

std::vector<std::pair<Vec2, Vec2>> GearItem::beltRuns() const {
  // The outer tangents: n . u = (ra - rb) / d on both sides.
  std::vector<std::pair<Vec2, Vec2>> runs;
  const Vec2 d = centre(1);
  const double len = d.norm(), ra = s_.radius[0], rb = s_.radius[1];
  if (!s_.belt || !(len > std::abs(ra - rb))) return runs;
  const Vec2 u = d / len;
  const double along = (ra - rb) / len, across = std::sqrt(1 - along * along);
  for (double side : {1.0, -1.0}) {
    const Vec2 n = along * u + side * across * perp(u);
    runs.emplace_back(ra * n, d + rb * n);
  }
  return runs;
}

double GearItem::distanceToLines(const Vec2& at) const {
  const Vec2 p = at - s_.at;
  double best = INFINITY;
  for (int k = 0; k < 2; ++k)
    if (s_.radius[k] > 0) best = std::min(best, std::abs((p - centre(k)).norm() - s_.radius[k]));
  for (const auto& [a, b] : beltRuns()) {
    const Vec2 run = b - a;
    const double t = std::clamp((p - a).dot(run) / run.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - a - t * run).norm());
  }
  return best;
}

double GearItem::radiusHolding(const Vec2& at) const {
  const Vec2 p = at - s_.at;
  double r = INFINITY;
  for (int k = 0; k < 2; ++k)
    if ((p - centre(k)).norm() < s_.radius[k]) r = std::min(r, s_.radius[k]);
  return r;
}

QPainterPath GearItem::lines() const {
  QPainterPath path;
  for (int k = 0; k < 2; ++k)
    if (s_.radius[k] > 0) path.addEllipse(toQt(s_.at + centre(k)), s_.radius[k], s_.radius[k]);
  for (const auto& [a, b] : beltRuns()) {
    path.moveTo(toQt(s_.at + a));
    path.lineTo(toQt(s_.at + b));
  }
  return path;
}

void GearItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  p->setRenderHint(QPainter::Antialiasing);
  p->setBrush(Qt::NoBrush);
  const double base = std::atan2(s_.direction.y(), s_.direction.x());
  for (int k = 0; k < 2; ++k) {
    const double r = s_.radius[k];
    if (!(r > 0)) continue;
    const QColor ink = flagged() ? st.warning : colour_[k];
    const QPointF c = toQt(centre(k));
    p->setPen(cosmetic(ink, 1.6, s_.belt ? Qt::SolidLine : Qt::DashLine));
    p->drawEllipse(c, r, r);
    // The tick: the body's rotation from the drawing, from the line of centres as drawn.
    const double a = base + s_.angle[k];
    p->setPen(cosmetic(ink, 1.6));
    p->drawLine(c, c + QPointF(r * std::cos(a), r * std::sin(a)));
  }
  p->setPen(cosmetic(flagged() ? st.warning : st.ink, 1.6));
  for (const auto& [a, b] : beltRuns()) p->drawLine(toQt(a), toQt(b));
}

}  // namespace linkage::ui
