#include "elements/cam_item.h"

#include <QPainter>
#include <algorithm>
#include <cmath>

namespace linkage::ui {

namespace {
// Over the bodies (at 0), under the blocks and pins: the follower's block sits on the cam.
constexpr double kCamZ = 5;
}  // namespace

CamItem::CamItem(const CanvasContext* ctx, const JointSymbol& s, QColor colour)
    : JointItem(ctx, s.joint), s_(s), colour_(colour), own_(colour) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(kCamZ);
}

void CamItem::setBodyColours(const std::function<QColor(BodyId)>& colourOf) {
  const QColor c = colourOf(s_.bodies[0]);
  const QColor next = c.isValid() ? c : own_;
  if (next == colour_) return;
  colour_ = next;
  update();
}

void CamItem::place(const JointSymbol& s) {
  prepareGeometryChange();
  s_ = s;
  setPos(s.at.x(), s.at.y());
}

QPolygonF CamItem::surface() const {
  QPolygonF poly;
  const Rot R = Rot::of(s_.angle[0]);
  for (const Vec2& p : s_.curve) poly << toQt(R * p);
  return poly;
}

QRectF CamItem::boundingRect() const {
  double r = s_.radius[0];
  for (const Vec2& p : s_.curve) r = std::max(r, p.norm());
  for (const Vec2& p : s_.curve2) r = std::max(r, p.norm());
  const Vec2 b = s_.at2 - s_.at;
  const double reach = std::max(r, b.norm() + s_.radius[1] + r / 2) + 4 * px();
  return QRectF(-reach, -reach, 2 * reach, 2 * reach);
}

double CamItem::distanceToLines(const Vec2& at) const {
  const Vec2 p = at - s_.at;
  const QPolygonF poly = surface();
  if (poly.size() < 2) return std::abs(p.norm() - s_.radius[0]);
  double best = INFINITY;
  for (qsizetype i = 0; i < poly.size(); ++i) {
    const QPointF a = poly[i], b = poly[(i + 1) % poly.size()];
    const Vec2 u(a.x(), a.y()), v(b.x(), b.y()), d = v - u;
    const double t =
        d.squaredNorm() > 0 ? std::clamp((p - u).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (u + t * d - p).norm());
  }
  return best;
}

QPainterPath CamItem::lines() const {
  QPainterPath path;
  const QPolygonF poly = surface();
  if (poly.size() < 2) {
    path.addEllipse(toQt(s_.at), s_.radius[0], s_.radius[0]);
    return path;
  }
  path.addPolygon(poly.translated(toQt(s_.at)));
  path.closeSubpath();
  return path;
}

void CamItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  p->setRenderHint(QPainter::Antialiasing);
  const QColor ink = flagged() ? st.warning : colour_;
  QColor fill = ink;
  fill.setAlphaF(0.18);
  p->setPen(cosmetic(ink, 1.6));
  p->setBrush(fill);
  const QPolygonF poly = surface();
  if (poly.size() >= 3)
    p->drawPolygon(poly);
  else
    p->drawEllipse(QPointF(0, 0), s_.radius[0], s_.radius[0]);
  // The base circle, dashed: the profile's dwells lie on it.
  p->setBrush(Qt::NoBrush);
  p->setPen(cosmetic(ink, 1, Qt::DashLine));
  p->drawEllipse(QPointF(0, 0), s_.radius[0], s_.radius[0]);
  // The pitch curve (a roller's centre's path on the cam), dotted: the roller runs on it.
  if (s_.curve2.size() >= 3) {
    QPolygonF pitch;
    const Rot R = Rot::of(s_.angle[0]);
    for (const Vec2& v : s_.curve2) pitch << toQt(R * v);
    p->setPen(cosmetic(ink, 1, Qt::DotLine));
    p->drawPolygon(pitch);
  }
  // The follower's end: its roller, or its flat face.
  const QPointF b = toQt(s_.at2 - s_.at);
  p->setPen(cosmetic(flagged() ? st.warning : st.ink, 1.6));
  if (s_.face) {
    const Vec2 n = Rot::of(s_.angle[1]) * s_.direction, t = perp(n);
    const double half = 0.6 * s_.radius[0];
    p->drawLine(b - toQt(half * t), b + toQt(half * t));
  } else if (s_.radius[1] > 0) {
    p->setBrush(st.paper);
    p->drawEllipse(b, s_.radius[1], s_.radius[1]);
  }
}

}  // namespace linkage::ui
