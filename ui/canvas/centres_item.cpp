#include "canvas/centres_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <cmath>

#include "canvas/body_item.h"

namespace linkage::ui {

namespace {

// The point of a homogeneous centre, or nullopt at infinity.
std::optional<QPointF> finite(const Eigen::Vector3d& h) {
  if (h.z() == 0) return std::nullopt;
  return QPointF(h.x() / h.z(), h.y() / h.z());
}

// Where the ray from `from` along `d` leaves the rectangle `r` (from inside it).
QPointF exitPoint(const QRectF& r, const QPointF& from, const QPointF& d) {
  double t = std::numeric_limits<double>::infinity();
  if (d.x() > 0) t = std::min(t, (r.right() - from.x()) / d.x());
  if (d.x() < 0) t = std::min(t, (r.left() - from.x()) / d.x());
  if (d.y() > 0) t = std::min(t, (r.bottom() - from.y()) / d.y());
  if (d.y() < 0) t = std::min(t, (r.top() - from.y()) / d.y());
  return from + t * d;
}

}  // namespace

CentresItem::CentresItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(100);
}

void CentresItem::setCentres(const std::vector<Drawing::Centre>& centres) {
  centres_ = centres;
  update();
}

void CentresItem::setChosen(int i, int j) {
  if (std::make_pair(i, j) == chosen_) return;
  chosen_ = {i, j};
  update();
}

const Drawing::Centre* CentresItem::find(int i, int j) const {
  for (const Drawing::Centre& c : centres_)
    if ((c.i == i && c.j == j) || (c.i == j && c.j == i)) return &c;
  return nullptr;
}

std::pair<int, int> CentresItem::centreNear(const QPointF& at, double radiusPx) const {
  std::pair<int, int> best{0, 0};
  double bestD = radiusPx * px();
  for (const Drawing::Centre& c : centres_) {
    if (!c.determined || c.atInfinity) continue;
    const double d = std::hypot(c.at.x() - at.x(), c.at.y() - at.y());
    if (d <= bestD) {
      bestD = d;
      best = {c.i, c.j};
    }
  }
  return best;
}

QRectF CentresItem::boundingRect() const {
  // Arrows at the view's edge and lines across it: the whole scene.
  return scene() ? scene()->sceneRect() : QRectF();
}

QColor CentresItem::colour(const Drawing::Centre& c) const {
  switch (c.status) {
    case CentreStatus::Primary:
      return style().centre;
    case CentreStatus::Kennedy:
      return style().kennedyCentre;
    case CentreStatus::Velocity:
      return style().velocityCentre;
  }
  return style().ink;
}

void CentresItem::paintLabel(QPainter* p, const QPointF& at, const QString& text,
                             const QColor& ink) {
  // Text upright and of constant size: drawn in device coordinates.
  const QTransform t = p->worldTransform();
  const QPointF d = t.map(at);
  p->save();
  p->resetTransform();
  const QRect box = p->fontMetrics().boundingRect(text);
  QRectF r = QRectF(box).adjusted(-2, 0, 2, 0).translated(d.x() + 6 - box.left(), d.y() - 8);
  for (int tries = 0; tries < 8; ++tries) {
    bool clear = true;
    for (const QRectF& q : placed_) clear = clear && !q.intersects(r);
    if (clear) break;
    r.translate(0, r.height() + 1);
  }
  // Inside the view: a label at the right or bottom edge goes to the other side.
  if (r.right() > device_.right() - 2) r.moveRight(device_.right() - 2);
  if (r.bottom() > device_.bottom() - 2) r.moveBottom(device_.bottom() - 2);
  if (r.left() < device_.left() + 2) r.moveLeft(device_.left() + 2);
  if (r.top() < device_.top() + 2) r.moveTop(device_.top() + 2);
  placed_.push_back(r);
  // A backing of the paper colour keeps it legible over lines (cheaper than a halo).
  QColor back = style().paper;
  back.setAlphaF(0.75);
  p->fillRect(r, back);
  p->setPen(ink);
  p->drawText(r, Qt::AlignCenter, text);
  p->restore();
}

void CentresItem::paintLines(QPainter* p, const Drawing::Centre& c, const QRectF& view) const {
  const double u = px();
  const QPointF centre = toQt(c.at);
  const QPen pen = cosmetic(colour(c), 1.0, Qt::DashLine);
  for (const Drawing::KennedyLine& l : c.lines) {
    // A line through two homogeneous points; drawn across the view.
    const Eigen::Vector3d a = l.through[0], b = l.through[1];
    QPointF o, d;
    if (auto fa = finite(a)) {
      o = *fa;
      if (auto fb = finite(b))
        d = *fb - o;
      else
        d = QPointF(b.x(), b.y());
    } else if (auto fb = finite(b)) {
      o = *fb;
      d = QPointF(a.x(), a.y());
    } else {
      continue;  // the line at infinity
    }
    const double n = std::hypot(d.x(), d.y());
    if (n == 0) continue;
    d /= n;
    const double reach = 2 * (std::hypot(view.width(), view.height()) +
                              std::hypot(o.x() - view.center().x(), o.y() - view.center().y()));
    p->setPen(pen);
    p->drawLine(o - reach * d, o + reach * d);
    // The centres that define the line, ringed, with their labels.
    p->setPen(cosmetic(colour(c), 1.0));
    p->setBrush(Qt::NoBrush);
    for (int e = 0; e < 2; ++e)
      if (auto f = finite(l.through[e])) p->drawEllipse(*f, 7 * u, 7 * u);
  }
  p->setPen(cosmetic(colour(c), 2));
  if (!c.atInfinity) p->drawEllipse(centre, 9 * u, 9 * u);
}

void CentresItem::paintEdgeArrow(QPainter* p, const Drawing::Centre& c, const QRectF& view) {
  const double u = px();
  const QRectF inner = view.adjusted(24 * u, 24 * u, -24 * u, -24 * u);
  const QPointF mid = view.center();
  QPointF d = c.atInfinity ? toQt(c.at) : toQt(c.at) - mid;
  const double n = std::hypot(d.x(), d.y());
  if (n == 0 || inner.width() <= 0 || inner.height() <= 0) return;
  d /= n;
  const QPointF tip = exitPoint(inner, mid, d);
  const QPointF nrm(-d.y(), d.x());
  const QColor ink = colour(c);
  p->setPen(cosmetic(ink, 1.0));
  p->drawLine(tip - 16 * u * d, tip);
  QPolygonF head;
  head << tip + 6 * u * d << tip - 2 * u * d + 5 * u * nrm << tip - 2 * u * d - 5 * u * nrm;
  p->setBrush(ink);
  p->drawPolygon(head);
  const QString dist = c.atInfinity
                           ? QStringLiteral("\u221e")
                           : QStringLiteral("%1 mm").arg(std::hypot(c.at.x(), c.at.y()), 0, 'f', 0);
  paintLabel(p, tip - 22 * u * d, QStringLiteral("%1,%2 %3").arg(c.i).arg(c.j).arg(dist), ink);
}

void CentresItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) {
  if (centres_.empty()) return;
  placed_.clear();
  device_ = widget ? QRectF(widget->rect()) : p->worldTransform().mapRect(boundingRect());
  p->setRenderHint(QPainter::Antialiasing);
  const QRectF view =
      widget ? p->worldTransform().inverted().mapRect(QRectF(widget->rect())) : boundingRect();
  if (const Drawing::Centre* c = find(chosen_.first, chosen_.second); c && c->determined)
    paintLines(p, *c, view);
  const double r = CanvasStyle::centreRadius * px();
  for (const Drawing::Centre& c : centres_) {
    if (!c.determined) continue;
    const QPointF at = toQt(c.at);
    if (c.atInfinity || !view.contains(at)) {
      paintEdgeArrow(p, c, view);
      continue;
    }
    const QColor ink = colour(c);
    p->setPen(cosmetic(style().paper, 1));
    p->setBrush(ink);
    if (c.status == CentreStatus::Primary)
      p->drawEllipse(at, r, r);
    else  // found, not given: a diamond
      p->drawPolygon(QPolygonF() << at + QPointF(r * 1.3, 0) << at + QPointF(0, r * 1.3)
                                 << at - QPointF(r * 1.3, 0) << at - QPointF(0, r * 1.3));
    paintLabel(p, at, QStringLiteral("%1,%2").arg(c.i).arg(c.j), ink);
  }
}

}  // namespace linkage::ui
