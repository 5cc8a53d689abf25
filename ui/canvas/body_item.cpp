#include "canvas/body_item.h"

#include <QPainter>
#include <QPainterPathStroker>
#include <QStyleOptionGraphicsItem>
#include <QtMath>
#include <algorithm>
#include <cmath>

namespace linkage::ui {

namespace {

// Arc points about c from angle a0 through a positive sweep (radians, y up), close enough that
// the polygon is never more than a quarter pixel inside the circle at the current zoom (px mm
// per pixel): smooth at any size, and a polygon fills and strokes far faster than curves.
void arc(QPolygonF& out, const Vec2& c, double r, double a0, double sweep, double px) {
  const double rPx = std::max(r / px, 1.0);
  const double step = std::clamp(2 * std::acos(std::max(0.0, 1 - 0.25 / rPx)), 0.02, M_PI / 6);
  const int n = std::max(1, static_cast<int>(std::ceil(sweep / step)));
  for (int k = 0; k <= n; ++k) {
    const double a = a0 + sweep * k / n;
    out << QPointF(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
}

}  // namespace

QPolygonF capsule(const Vec2& a, const Vec2& b, double r, double px) {
  QPolygonF p;
  const Vec2 d = b - a;
  const double t = d.norm() > 0 ? std::atan2(d.y(), d.x()) : 0.0;
  arc(p, b, r, t - M_PI / 2, M_PI, px);
  arc(p, a, r, t + M_PI / 2, M_PI, px);
  p << p.front();
  return p;
}

QPolygonF channel(const Guide& g, double r, double px) {
  if (!g.arc) return capsule(g.p0, g.p1, r, px);
  // Outer wall from p0 to p1, a round end, the inner wall back, a round end: enough vertices
  // that no chord strays more than a quarter pixel from the circle.
  const double span = std::abs(g.sweep), dir = g.sweep >= 0 ? 1 : -1;
  const double outer = g.radius + r;
  const int n =
      std::clamp(int(span / (2 * std::acos(std::max(0.0, 1 - 0.25 * px / outer)))) + 2, 8, 4000);
  QPolygonF poly;
  auto onCircle = [&](double radius, double a) {
    poly << toQt(g.centre + radius * Vec2(std::cos(a), std::sin(a)));
  };
  for (int i = 0; i <= n; ++i) onCircle(outer, g.a0 + dir * span * i / n);
  const Vec2 e1 = g.p1 - g.centre, e0 = g.p0 - g.centre;
  auto cap = [&](const Vec2& c, const Vec2& out, double from) {
    // The half of a small circle about c facing away from the arc, from the outer wall round.
    const int m = 12;
    const double base = std::atan2(out.y(), out.x());
    for (int i = 1; i < m; ++i) {
      const double a = base + from * M_PI * i / m;
      poly << toQt(c + r * Vec2(std::cos(a), std::sin(a)));
    }
  };
  cap(g.p1, e1, dir);
  for (int i = n; i >= 0; --i) onCircle(std::max(0.0, g.radius - r), g.a0 + dir * span * i / n);
  cap(g.p0, -e0, dir);
  poly << poly.front();
  return poly;
}

QPolygonF roundedHull(const std::vector<Vec2>& hull, double r, double px) {
  // Counter-clockwise convex polygon grown by r: each edge moved out along its normal, the
  // corners rounded by arcs about the vertices.
  QPolygonF p;
  const size_t n = hull.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e0 = hull[i] - hull[(i + n - 1) % n], e1 = hull[(i + 1) % n] - hull[i];
    const double a0 = std::atan2(-e0.x(), e0.y());  // outward normal (e.y, -e.x)
    double sweep = std::atan2(-e1.x(), e1.y()) - a0;
    while (sweep < 0) sweep += 2 * M_PI;
    arc(p, hull[i], r, a0, sweep, px);
  }
  if (!p.isEmpty()) p << p.front();
  return p;
}

BodyItem::BodyItem(const CanvasContext* ctx, BodyGeometry g) : CanvasItem(ctx), g_(std::move(g)) {
  setAcceptHoverEvents(g_.body.shape != Drawing::Shape::Ground);
  const bool ground = g_.body.shape == Drawing::Shape::Ground;
  setToolTip(
      ground
          ? QStringLiteral("1 %1 (the frame)").arg(QString::fromStdString(g_.body.name))
          : QStringLiteral("%1 %2").arg(g_.body.number).arg(QString::fromStdString(g_.body.name)));
  if (!ground && g_.body.shape != Drawing::Shape::Block && !g_.body.outline.empty()) {
    Vec2 c = Vec2::Zero();
    for (const Vec2& p : g_.body.outline) c += p;
    c /= double(g_.body.outline.size());
    // A disc's number off its centre, where its pivot and driver arrow are.
    if (g_.body.shape == Drawing::Shape::Disc) c += 0.6 * g_.body.radius * Vec2(-0.6, 0.8);
    label_ = new LabelItem(QString::number(g_.body.number), this);
    label_->setPos(toQt(c));
    label_->setBold(true);
  }
  rebuild();
}

void BodyItem::setPose(const Transform& pose) {
  setTransform(toQt(pose));
}

void BodyItem::setFlagged(bool on) {
  if (on == flagged_) return;
  flagged_ = on;
  update();
}

void BodyItem::setFlaggedSlots(std::vector<SlotId> slots) {
  if (slots == flaggedSlots_) return;
  flaggedSlots_ = std::move(slots);
  update();
}

bool BodyItem::slotFlagged(SlotId s) const {
  return std::find(flaggedSlots_.begin(), flaggedSlots_.end(), s) != flaggedSlots_.end();
}

void BodyItem::setFaintSlots(std::vector<SlotId> slots) {
  if (slots == faintSlots_) return;
  faintSlots_ = std::move(slots);
  update();
}

bool BodyItem::slotFaint(SlotId s) const {
  return std::find(faintSlots_.begin(), faintSlots_.end(), s) != faintSlots_.end();
}

void BodyItem::setColour(const QColor& c) {
  if (c == colour_) return;
  colour_ = c;
  if (label_) label_->setColours(colour(), style().paper);
  update();
}

QColor BodyItem::colour() const {
  return colour_.isValid() ? colour_ : style().body(g_.body.number);
}

QPolygonF bodyOutline(const Drawing::Body& b, double px) {
  const double r = CanvasStyle::barWidth / 2 * px;
  const std::vector<Vec2>& o = b.outline;
  switch (b.shape) {
    case Drawing::Shape::Bar:
      return capsule(o[0], o[1], r, px);
    case Drawing::Shape::Plate:
      return roundedHull(o, r, px);
    case Drawing::Shape::Disc:
      return capsule(o[0], o[0], b.radius + r, px);
    case Drawing::Shape::Dot:
      return o.empty() ? QPolygonF() : capsule(o[0], o[0], r, px);
    case Drawing::Shape::Block:
    case Drawing::Shape::Ground:
      break;
  }
  return QPolygonF();
}

// What the solver refuses to compute with (a coordinate beyond 1e12 mm, typed or in a file) is
// not drawn either: the design stays as typed, the status bar says why, and no length is
// squared into infinity here (a hatching loop with an infinite length never ended).
static bool drawable(const BodyGeometry& g) {
  auto ok = [](const Vec2& v) { return v.allFinite() && v.cwiseAbs().maxCoeff() <= 1e12; };
  bool all = std::all_of(g.body.outline.begin(), g.body.outline.end(), ok) &&
             std::all_of(g.points.begin(), g.points.end(), ok) && std::isfinite(g.body.radius) &&
             std::abs(g.body.radius) <= 1e12;
  for (const Guide& s : g.slots)
    all = all && ok(s.p0) && ok(s.p1) && ok(s.centre) && std::abs(s.radius) <= 1e12;
  return all;
}

void BodyItem::rebuild() {
  shape_ = QPainterPath();
  channels_.clear();
  hatch_.clear();
  if (!drawable(g_)) {
    body_.clear();
    return;
  }
  body_ = bodyOutline(g_.body, px());
  shape_.addPolygon(body_);
  const double w = CanvasStyle::channelWidth / 2 * px();
  for (const Guide& g : g_.slots) {
    channels_.push_back(channel(g, w, px()));
    hatch_.emplace_back();
    if (g_.body.shape != Drawing::Shape::Ground) continue;
    // The frame's slots: short strokes along both walls, as a fixed guide is drawn.
    // A stroke every 6 pixels, and no more than 2000 along a wall (a slot typed a kilometre
    // long would otherwise make a million).
    const double len = g.length(), step = std::max(6 * px(), len / 2000);
    for (double s = 0; s <= len; s += step) {
      const Vec2 at = g.at(s), d = g.tangentAt(at), n = perp(d);
      for (int side : {-1, 1}) {
        const Vec2 base = at + side * (w + 0.5 * px()) * n;
        hatch_.back() << QLineF(toQt(base), toQt(base + side * 4 * px() * n - 4 * px() * d));
      }
    }
  }
  if (label_) label_->setColours(colour(), style().paper);
}

QRectF BodyItem::boundingRect() const {
  const double m = 6 * px();
  QRectF r = body_.boundingRect();
  for (const QPolygonF& c : channels_) r = r.united(c.boundingRect());
  for (const QVector<QLineF>& h : hatch_)
    for (const QLineF& l : h) r = r.united(QRectF(l.p1(), l.p2()).normalized());
  return r.adjusted(-m, -m, m, m);
}

void BodyItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const QColor line = flagged_ ? st.warning : colour();
  p->setRenderHint(QPainter::Antialiasing);
  // Cosmetic pens: widths in pixels, which the raster engine strokes on its fast path.
  QPen pen = cosmetic(line, hovered_ || flagged_ ? 2.5 : CanvasStyle::outline);
  // Fills without antialiasing, then antialiased one-pixel outlines over their edges: the
  // outline hides the stair steps, and an aliased fill of a large plate costs a fraction of an
  // antialiased one (plates and channels are most of a frame's pixels).
  auto shape = [&](const QPolygonF& whole, const QColor& fill, const QPen& outline) {
    const QPolygonF poly = cutToDevice(whole, p);
    p->setRenderHint(QPainter::Antialiasing, false);
    p->setPen(Qt::NoPen);
    p->setBrush(fill);
    p->drawPolygon(poly);
    p->setRenderHint(QPainter::Antialiasing, true);
    p->setPen(outline);
    p->setBrush(Qt::NoBrush);
    p->drawPolygon(poly);
  };
  if (!body_.isEmpty())
    shape(body_,
          flagged_ ? QColor(st.warning.red(), st.warning.green(), st.warning.blue(), 60) : fill(),
          pen);
  const QPen wall =
      cosmetic(g_.body.shape == Drawing::Shape::Ground ? st.ink : line, CanvasStyle::outline);
  const QPen warned = cosmetic(st.warning, 2.5);
  for (size_t i = 0; i < channels_.size(); ++i) {
    const bool known = i < g_.slotIds.size();
    p->setOpacity(known && slotFaint(g_.slotIds[i]) ? 0.18 : 1.0);
    shape(channels_[i], st.paper, known && slotFlagged(g_.slotIds[i]) ? warned : wall);
    if (i < hatch_.size() && !hatch_[i].isEmpty()) {
      p->setPen(cosmetic(st.faint, 1));
      p->drawLines(hatch_[i]);
    }
  }
  p->setOpacity(1.0);
  if (g_.body.shape != Drawing::Shape::Ground && g_.body.shape != Drawing::Shape::Block) {
    p->setPen(Qt::NoPen);
    p->setBrush(line);
    const double r = CanvasStyle::pointRadius * px();
    if (drawable(g_))
      for (const Vec2& pt : g_.points) p->drawEllipse(toQt(pt), r, r);
  }
}

QColor BodyItem::fill() const {
  if (!colour_.isValid()) return style().bodyFill(g_.body.number);
  QColor c = colour_;
  c.setAlphaF(style().dark ? 0.30 : 0.22);
  return c;
}

void BodyItem::hoverEnterEvent(QGraphicsSceneHoverEvent*) {
  hovered_ = true;
  update();
}

void BodyItem::hoverLeaveEvent(QGraphicsSceneHoverEvent*) {
  hovered_ = false;
  update();
}

}  // namespace linkage::ui
