#include "design/extremes_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <map>

#include "canvas/body_item.h"
#include "design/overlay_labels.h"

namespace linkage::ui {

namespace {

// A colour 45% of the way from the paper to c, opaque: light lines that cost what solid ones do
// (translucent antialiased lines took the raster engine twice as long as the whole canvas).
QColor faint(const QColor& c, const QColor& paper) {
  const double f = 0.45;
  return QColor::fromRgbF(f * c.redF() + (1 - f) * paper.redF(),
                          f * c.greenF() + (1 - f) * paper.greenF(),
                          f * c.blueF() + (1 - f) * paper.blueF());
}

}  // namespace

ExtremePoses findExtremePoses(const Kinematics& k, const LimitMeasure& what) {
  ExtremePoses out;
  out.measure = what;
  const Mechanism& m = k.mechanism();
  if (const Body* b = what.body ? m.body(what.body) : nullptr)
    out.label = QString::fromStdString(b->name);
  else if (m.contains(what.point))
    out.label = QString::fromStdString(m.pointLabel(what.point));
  out.limits = findLimits(k, what);
  if (!out.limits.status.ok()) return out;
  // Where a body's extreme is marked: its first point.
  PointId mark = what.point;
  for (const Point& p : m.points)
    if (!mark && p.body == what.body) mark = p.id;
  Kinematics turned = k;
  if (!turned.moveTo(0).ok()) return out;
  for (const Extreme& e : out.limits.extremes) {
    if (!turned.moveTo(e.crankDeg).ok()) break;
    out.poses.push_back({e, describeDrawing(turned), turned.position(mark)});
  }
  return out;
}

ExtremesItem::ExtremesItem(const CanvasContext* ctx, std::shared_ptr<LabelBoard> board)
    : CanvasItem(ctx), board_(std::move(board)) {
  setAcceptedMouseButtons(Qt::NoButton);
}

void ExtremesItem::setPoses(ExtremePoses poses) {
  poses_ = std::move(poses);
  restyle();
}

void ExtremesItem::clear() {
  setPoses({});
}

void ExtremesItem::rebuild() {
  ghosts_.clear();
  const double u = px();
  for (const ExtremePose& pose : poses_.poses) {
    const Drawing& d = pose.drawing;
    Ghost g;
    std::map<BodyId, int> number;
    for (const Drawing::Body& b : d.bodies) {
      number[b.id] = b.number;
      if (b.shape == Drawing::Shape::Ground) continue;
      const QPolygonF o = bodyOutline(b, u);
      if (!o.isEmpty()) g.outlines.emplace_back(toQt(b.pose).map(o), b.number);
    }
    for (const Drawing::Block& b : d.blocks) {
      const Vec2 l = b.direction * (CanvasStyle::blockLength / 2 * u);
      const Vec2 w = perp(b.direction) * (CanvasStyle::blockWidth / 2 * u);
      g.outlines.emplace_back(QPolygonF({toQt(b.at - l - w), toQt(b.at + l - w), toQt(b.at + l + w),
                                         toQt(b.at - l + w), toQt(b.at - l - w)}),
                              number[b.body]);
    }
    for (const Drawing::Pin& p : d.pins)
      if (!p.groundPivot) g.pins.push_back(toQt(p.at));
    for (const Drawing::SlotPin& p : d.slotPins) g.pins.push_back(toQt(p.at));
    ghosts_.push_back(std::move(g));
  }
}

QRectF ExtremesItem::boundingRect() const {
  // Labels and the stroke's dimension are drawn in device pixels beside the ghosts.
  return poses_.poses.empty() || !scene() ? QRectF() : scene()->sceneRect();
}

void ExtremesItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  if (ghosts_.empty()) return;
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  for (const Ghost& g : ghosts_) {
    for (const auto& [outline, n] : g.outlines) {
      p->setPen(cosmetic(faint(st.body(n), st.paper), 1));
      p->setBrush(Qt::NoBrush);
      p->drawPolygon(outline);
    }
    p->setPen(cosmetic(faint(st.ink, st.paper), 1));
    p->setBrush(Qt::NoBrush);
    const double r = 0.8 * CanvasStyle::pinRadius * u;
    for (const QPointF& c : g.pins) p->drawEllipse(c, r, r);
  }
  OverlayLabels labels(p, st.paper, board_.get());
  const bool body = bool(poses_.measure.body);
  const ExtremePose *lowest = nullptr, *highest = nullptr;
  for (const ExtremePose& e : poses_.poses) {
    p->setPen(cosmetic(st.ink, 1.5));
    p->setBrush(st.paper);
    const double r = CanvasStyle::outputRadius * u;
    p->drawEllipse(toQt(e.at), r, r);
    if (e.extreme.value == poses_.limits.min) lowest = &e;
    if (e.extreme.value == poses_.limits.max) highest = &e;
  }
  auto text = [&](const ExtremePose& e) {
    const QString value = body ? QStringLiteral("%1\u00b0").arg(e.extreme.value, 0, 'f', 2)
                               : QStringLiteral("%1 mm").arg(e.extreme.value, 0, 'f', 2);
    return QStringLiteral("%1 %2 (crank %3\u00b0)")
        .arg(e.extreme.max ? QStringLiteral("max") : QStringLiteral("min"), value)
        .arg(e.extreme.crankDeg, 0, 'f', 1);
  };
  // (No dimension where an end of a motion that does not repeat is the lowest or highest.)
  if (body || !lowest || !highest) {
    for (const ExtremePose& e : poses_.poses)
      labels.paint(toQt(e.at), QPointF(12, 0), text(e), st.ink, Qt::AlignLeft);
    return;
  }
  // The stroke along the direction as a dimension beside the point's positions, on the side
  // away from the mechanism, each extreme's value at its height on it.
  const Vec2 dir = poses_.measure.direction.normalized();
  const Drawing& d = lowest->drawing;
  Vec2 n = perp(dir);
  if (n.dot(lowest->at - (d.min + d.max) / 2) < 0) n = -n;
  const Vec2 a = lowest->at + 40 * u * n;
  const Vec2 b = a + (highest->at - lowest->at).dot(dir) * dir;
  const QColor ink = st.kennedyCentre;
  p->setPen(cosmetic(ink, 1));
  p->drawLine(toQt(lowest->at + 6 * u * n), toQt(a + 6 * u * n));
  p->drawLine(toQt(highest->at + 6 * u * n), toQt(b + 6 * u * n));
  p->drawLine(toQt(a), toQt(b));
  const Vec2 s = (b - a).norm() > 0 ? Vec2((b - a).normalized()) : dir;
  p->setBrush(ink);
  for (const auto& [tip, back] : {std::pair{a, s}, std::pair{b, Vec2(-s)}}) {
    const Vec2 base = tip + 8 * u * back;
    p->drawPolygon(
        QPolygonF({toQt(tip), toQt(base + 3 * u * perp(back)), toQt(base - 3 * u * perp(back))}));
  }
  const bool right = n.x() >= 0;
  const Qt::Alignment side = right ? Qt::AlignLeft : Qt::AlignRight;
  // The labels in a column beside the dimension, each at its value's height, in the order of
  // their heights: where they would overlap (a dwell's extremes close together) each goes just
  // below the one above it, so that the column still reads top to bottom as the values do.
  struct Label {
    QPointF at;
    QString text;
    QColor ink;
    double y = 0;  // device pixels, where it goes
  };
  std::vector<Label> column;
  for (const ExtremePose& e : poses_.poses)
    column.push_back({toQt(a + (e.extreme.value - lowest->extreme.value) * dir), text(e), st.ink});
  column.push_back({toQt((a + b) / 2),
                    QStringLiteral("stroke %1 mm").arg(poses_.limits.stroke, 0, 'f', 2), ink});
  for (Label& l : column) l.y = p->worldTransform().map(l.at).y();
  std::stable_sort(column.begin(), column.end(),
                   [](const Label& x, const Label& y) { return x.y < y.y; });
  const double h = p->fontMetrics().height() + 3;
  for (size_t i = 1; i < column.size(); ++i)
    column[i].y = std::max(column[i].y, column[i - 1].y + h);
  for (const Label& l : column)
    labels.paint(l.at, QPointF(right ? 10 : -10, l.y - p->worldTransform().map(l.at).y()), l.text,
                 l.ink, side);
}

}  // namespace linkage::ui
