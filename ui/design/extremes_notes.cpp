#include "design/extremes_notes.h"

#include <QGraphicsScene>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "canvas/body_item.h"
#include "design/extremes_item.h"

namespace linkage::ui {

ExtremesNotes::ExtremesNotes(const CanvasContext* ctx, const ExtremesItem* extremes)
    : CanvasItem(ctx), extremes_(extremes) {
  setAcceptedMouseButtons(Qt::NoButton);
}

QRectF ExtremesNotes::boundingRect() const {
  // Labels and the dimension are drawn in device pixels beside the positions.
  return extremes_->poses().poses.empty() || !scene() ? QRectF() : scene()->sceneRect();
}

namespace {

// "max 131.20 mm (crank 87.3°)", or the angle in degrees for a body.
QString extremeText(const ExtremePose& e, bool body) {
  const QString value = body ? QStringLiteral("%1\u00b0").arg(e.extreme.value, 0, 'f', 2)
                             : QStringLiteral("%1 mm").arg(e.extreme.value, 0, 'f', 2);
  return QStringLiteral("%1 %2 (crank %3\u00b0)")
      .arg(e.extreme.max ? QStringLiteral("max") : QStringLiteral("min"), value)
      .arg(e.extreme.crankDeg, 0, 'f', 1);
}

// The stroke's dimension line, from a (level with the lowest position) to b, along dir, off
// the positions by n (unit, away from the mechanism).
struct Dimension {
  Vec2 dir, n, a, b;
};

// A label along the dimension.
struct Label {
  QPointF at;
  QString text;
  QColor ink;
  QPointF device;  // where `at` is, device pixels
};

// Each position of the point marked open, so that the mechanism shows through when it passes
// the place; lowest and highest receive the positions of the motion's limits.
void markPositions(QPainter* p, const ExtremePoses& poses, const QColor& ink, double u,
                   const ExtremePose*& lowest, const ExtremePose*& highest) {
  for (const ExtremePose& e : poses.poses) {
    if (!e.at.allFinite()) continue;
    p->setPen(cosmetic(ink, 1.5));
    p->setBrush(Qt::NoBrush);
    const double r = CanvasStyle::outputRadius * u;
    p->drawEllipse(toQt(e.at), r, r);
    if (e.extreme.value == poses.limits.min) lowest = &e;
    if (e.extreme.value == poses.limits.max) highest = &e;
  }
}

// The stroke along the direction beside the point's positions, on the side away from the
// mechanism.
Dimension strokeDimension(const ExtremePoses& poses, const ExtremePose& lowest,
                          const ExtremePose& highest, double u) {
  Dimension d;
  d.dir = poses.measure.direction.normalized();
  const Drawing& drawing = lowest.drawing;
  d.n = perp(d.dir);
  if (d.n.dot(lowest.at - (drawing.min + drawing.max) / 2) < 0) d.n = -d.n;
  d.a = lowest.at + 40 * u * d.n;
  d.b = d.a + (highest.at - lowest.at).dot(d.dir) * d.dir;
  return d;
}

// Extension lines from the limits' positions, the dimension line and its arrowheads.
void drawDimension(QPainter* p, const Dimension& d, const Vec2& lowest, const Vec2& highest,
                   const QColor& ink, double u) {
  p->setPen(cosmetic(ink, 1));
  p->drawLine(toQt(lowest + 6 * u * d.n), toQt(d.a + 6 * u * d.n));
  p->drawLine(toQt(highest + 6 * u * d.n), toQt(d.b + 6 * u * d.n));
  p->drawLine(toQt(d.a), toQt(d.b));
  const Vec2 s = (d.b - d.a).norm() > 0 ? Vec2((d.b - d.a).normalized()) : d.dir;
  p->setBrush(ink);
  for (const auto& [tip, back] : {std::pair{d.a, s}, std::pair{d.b, Vec2(-s)}}) {
    const Vec2 base = tip + 8 * u * back;
    p->drawPolygon(
        QPolygonF({toQt(tip), toQt(base + 3 * u * perp(back)), toQt(base - 3 * u * perp(back))}));
  }
}

// Across the view: each label above (or below) its place, in rows away from the mechanism
// where they would overlap; rows that would run out of the view (or under the message strip)
// come back towards the mechanism together, so that they keep their order.
void labelAcross(QPainter* p, OverlayLabels& labels, const std::vector<Label>& notes,
                 const Dimension& d) {
  const double h = p->fontMetrics().height() + 3;
  const double out = d.n.y() > 0 ? -1 : 1;
  std::vector<QRectF> taken;
  for (const Label& l : notes) {
    QRectF r = QRectF(p->fontMetrics().boundingRect(l.text)).adjusted(-3, -1, 3, 1);
    r.moveCenter(l.device + QPointF(0, out * 14));
    auto overlaps = [&] {
      return std::any_of(taken.begin(), taken.end(),
                         [&](const QRectF& q) { return q.intersects(r); });
    };
    while (overlaps()) r.translate(0, out * h);
    taken.push_back(r);
  }
  const QRectF room = labels.bounds().adjusted(2, 2, -2, -2);
  double over = 0;
  for (const QRectF& r : taken)
    over = std::max(over, out < 0 ? room.top() - r.top() : r.bottom() - room.bottom());
  for (size_t i = 0; i < notes.size(); ++i)
    labels.paint(notes[i].at, taken[i].center() - QPointF(0, out * over) - notes[i].device,
                 notes[i].text, notes[i].ink);
}

// Up the view: a column beside the dimension, each label at its value's height, in the order
// of the heights; where they would overlap (a dwell's extremes close together) each goes just
// below the one above it, so that the column reads top to bottom as the values do.
void labelUp(QPainter* p, OverlayLabels& labels, std::vector<Label> notes, const Dimension& d) {
  const double h = p->fontMetrics().height() + 3;
  const bool right = d.n.x() >= 0;
  std::stable_sort(notes.begin(), notes.end(),
                   [](const Label& x, const Label& y) { return x.device.y() < y.device.y(); });
  std::vector<double> ys;
  for (const Label& l : notes)
    ys.push_back(std::max(l.device.y(), ys.empty() ? -1e300 : ys.back() + h));
  // A column running under the message strip moves up whole, as far as the view's top allows,
  // so that it still reads top to bottom.
  const QRectF& room = labels.bounds();
  if (!ys.empty()) {
    const double over = ys.back() + h / 2 - (room.bottom() - 2);
    const double shift = std::min(over, ys.front() - h / 2 - (room.top() + 2));
    if (over > 0 && shift > 0)
      for (double& y : ys) y -= shift;
  }
  for (size_t i = 0; i < notes.size(); ++i) {
    const Label& l = notes[i];
    labels.paint(l.at, QPointF(right ? 10 : -10, ys[i] - l.device.y()), l.text, l.ink,
                 right ? Qt::AlignLeft : Qt::AlignRight);
  }
}

}  // namespace

void ExtremesNotes::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const ExtremePoses& poses = extremes_->poses();
  rects_.clear();
  if (poses.poses.empty()) return;
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  OverlayLabels labels(p, st.paper, &ctx().labels);
  const bool body = bool(poses.measure.body);
  const ExtremePose *lowest = nullptr, *highest = nullptr;
  markPositions(p, poses, st.ink, u, lowest, highest);
  // (No dimension where an end of a motion that does not repeat is the lowest or highest.)
  if (body || !lowest || !highest) {
    for (const ExtremePose& e : poses.poses)
      if (e.at.allFinite())
        labels.paint(toQt(e.at), QPointF(12, 0), extremeText(e, body), st.ink, Qt::AlignLeft);
    rects_ = labels.painted();
    return;
  }
  const Dimension d = strokeDimension(poses, *lowest, *highest, u);
  drawDimension(p, d, lowest->at, highest->at, st.kennedyCentre, u);
  // The values at their places along the dimension, the stroke at its middle.
  std::vector<Label> notes;
  notes.push_back({toQt((d.a + d.b) / 2),
                   QStringLiteral("stroke %1 mm").arg(poses.limits.stroke, 0, 'f', 2),
                   st.kennedyCentre,
                   {}});
  for (const ExtremePose& e : poses.poses)
    notes.push_back({toQt(d.a + (e.extreme.value - lowest->extreme.value) * d.dir),
                     extremeText(e, body),
                     st.ink,
                     {}});
  for (Label& l : notes) l.device = p->worldTransform().map(l.at);
  if (std::abs(d.dir.x()) > std::abs(d.dir.y()))
    labelAcross(p, labels, notes, d);
  else
    labelUp(p, labels, std::move(notes), d);
  rects_ = labels.painted();
}

}  // namespace linkage::ui
