#include "canvas/centres_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <algorithm>
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

QStaticText& CentresItem::staticText(const QString& text, const QFont& font) {
  auto it = texts_.find(text);
  if (it == texts_.end() || it->second.second != font) {
    QStaticText t(text);
    t.setPerformanceHint(QStaticText::AggressiveCaching);
    t.prepare(QTransform(), font);  // laid out once, not at every paint
    it = texts_.insert_or_assign(text, std::pair{t, font}).first;
  }
  return it->second.first;
}

bool CentresItem::paintLabel(QPainter* p, const QPointF& d, const QString& text,
                             const QColor& ink) {
  QStaticText& t = staticText(text, p->font());
  const QSizeF size = t.size() + QSizeF(4, 0);
  // Right of the centre, then left, above, below, then further down: the first free place.
  const QPointF right(d.x() + 5, d.y() - size.height() - 1),
      left(d.x() - 5 - size.width(), right.y());
  const QPointF under(right.x(), d.y() + 3);
  std::vector<QRectF> tries;
  for (const QPointF& c : {right, left, QPointF(d.x() - size.width() / 2, right.y() - 6), under})
    tries.push_back(QRectF(c, size));
  for (int k = 1; k <= 3; ++k)
    tries.push_back(QRectF(under + QPointF(0, k * (size.height() + 1)), size));
  const std::optional<QRectF> r = ctx().labels.place(tries, device_.adjusted(2, 2, -2, -2));
  if (!r) return false;
  // A backing of the paper colour keeps it legible over lines (cheaper than a halo).
  QColor back = style().paper;
  back.setAlphaF(0.75);
  p->fillRect(*r, back);
  p->setPen(ink);
  p->drawStaticText(r->topLeft() + QPointF(2, 0), t);
  return true;
}

const QPixmap& CentresItem::dot(const QColor& ink, bool primary, qreal dpr) {
  const auto key = std::make_tuple(ink.rgba(), primary, qRound(dpr * 100));
  auto it = dots_.find(key);
  if (it != dots_.end()) return it->second;
  const double r = CanvasStyle::centreRadius, side = 2 * std::ceil(r * 1.3) + 4;
  QPixmap pm(QSize(qCeil(side * dpr), qCeil(side * dpr)));
  pm.setDevicePixelRatio(dpr);
  pm.fill(Qt::transparent);
  QPainter q(&pm);
  q.setRenderHint(QPainter::Antialiasing);
  q.setPen(QPen(style().paper, 1));
  q.setBrush(ink);
  const QPointF c(side / 2, side / 2);
  if (primary)
    q.drawEllipse(c, r, r);
  else  // found, not given: a diamond
    q.drawPolygon(QPolygonF() << c + QPointF(r * 1.3, 0) << c + QPointF(0, r * 1.3)
                              << c - QPointF(r * 1.3, 0) << c - QPointF(0, r * 1.3));
  return dots_.emplace(key, pm).first->second;
}

void CentresItem::rebuild() {
  dots_.clear();  // the paper's colour rings them
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

std::optional<CentresItem::EdgeTip> CentresItem::edgeTip(const Drawing::Centre& c,
                                                         const QRectF& view,
                                                         const QTransform& toDevice) const {
  const double u = px();
  const QRectF inner = view.adjusted(24 * u, 24 * u, -24 * u, -24 * u);
  const QPointF mid = view.center();
  QPointF d = c.atInfinity ? toQt(c.at) : toQt(c.at) - mid;
  const double n = std::hypot(d.x(), d.y());
  if (n == 0 || inner.width() <= 0 || inner.height() <= 0) return std::nullopt;
  d /= n;
  const QPointF tip = exitPoint(inner, mid, d);
  const QPointF at = toDevice.map(tip), way = toDevice.map(tip + 10 * u * d) - at;
  const double w = std::hypot(way.x(), way.y());
  if (w == 0) return std::nullopt;
  return EdgeTip{at, way / w, &c};
}

QString CentresItem::edgeText(const Drawing::Centre& c) {
  const QString dist = c.atInfinity
                           ? QStringLiteral("\u221e")
                           : QStringLiteral("%1 mm").arg(std::hypot(c.at.x(), c.at.y()), 0, 'f', 0);
  return QStringLiteral("%1,%2 %3").arg(c.i).arg(c.j).arg(dist);
}

// One arrow for the centres in `group` (they leave the view at one place), with each one's
// label when they are few, else the first's and how many more.
// One arrow for the centres in `group` (they leave the view at one place), with each one's
// label when they are few, else the first's and how many more.
void CentresItem::paintEdgeArrow(QPainter* p, const std::vector<EdgeTip>& group) {
  const EdgeTip& e = group.front();
  const QPointF tip = e.tip, d = e.direction, nrm(-d.y(), d.x());
  const QColor ink = colour(*e.centre);
  p->setPen(QPen(ink, 1.0));
  p->drawLine(tip - 16 * d, tip);
  p->setBrush(ink);
  p->drawPolygon(QPolygonF() << tip + 6 * d << tip - 2 * d + 5 * nrm << tip - 2 * d - 5 * nrm);
  constexpr size_t kFew = 3;
  if (group.size() <= kFew) {
    for (const EdgeTip& g : group)
      paintLabel(p, tip - 22 * d, edgeText(*g.centre), colour(*g.centre));
    return;
  }
  paintLabel(p, tip - 22 * d, edgeText(*e.centre) + QStringLiteral(" +%1").arg(group.size() - 1),
             ink);
}

// The arrows of the centres outside the view, one for those that leave it at one place (within
// a few pixels).
void CentresItem::paintEdgeArrows(QPainter* p, const std::vector<EdgeTip>& tips) {
  std::vector<std::vector<EdgeTip>> groups;
  constexpr double kTogetherPx = 14;
  for (const EdgeTip& e : tips) {
    auto same = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      const QPointF o = g.front().tip;
      return std::abs(o.x() - e.tip.x()) < kTogetherPx && std::abs(o.y() - e.tip.y()) < kTogetherPx;
    });
    if (same != groups.end())
      same->push_back(e);
    else
      groups.push_back({e});
  }
  for (const std::vector<EdgeTip>& g : groups) paintEdgeArrow(p, g);
}

void CentresItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) {
  if (centres_.empty()) return;
  device_ = widget ? QRectF(widget->rect()) : p->worldTransform().mapRect(boundingRect());
  p->setRenderHint(QPainter::Antialiasing);
  const QRectF view =
      widget ? p->worldTransform().inverted().mapRect(QRectF(widget->rect())) : boundingRect();
  if (const Drawing::Centre* c = find(chosen_.first, chosen_.second); c && c->determined)
    paintLines(p, *c, view);
  // The rest in device pixels, the transform reset once: dots as pixmaps made once, labels
  // upright, arrows of one size at any zoom.
  const QTransform toDevice = p->worldTransform();
  p->save();
  p->resetTransform();
  const qreal dpr = p->device()->devicePixelRatioF();
  std::vector<EdgeTip> tips;
  for (const Drawing::Centre& c : centres_) {
    if (!c.determined) continue;
    const QPointF at = toQt(c.at);
    if (c.atInfinity || !view.contains(at)) {
      if (std::optional<EdgeTip> e = edgeTip(c, view, toDevice)) tips.push_back(*e);
      continue;
    }
    const QColor ink = colour(c);
    const QPointF d = toDevice.map(at);
    const QPixmap& pm = dot(ink, c.status == CentreStatus::Primary, dpr);
    const QSizeF half = QSizeF(pm.size()) / dpr / 2;
    p->drawPixmap(d - QPointF(half.width(), half.height()), pm);
    paintLabel(p, d, QStringLiteral("%1,%2").arg(c.i).arg(c.j), ink);
  }
  paintEdgeArrows(p, tips);
  p->restore();
}

}  // namespace linkage::ui
