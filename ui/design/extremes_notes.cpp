#include "design/extremes_notes.h"

#include <QGraphicsScene>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "canvas/body_item.h"
#include "design/extremes_item.h"

namespace linkage::ui {

ExtremesNotes::ExtremesNotes(const CanvasContext* ctx, const ExtremesItem* extremes,
                             std::shared_ptr<LabelBoard> board)
    : CanvasItem(ctx), extremes_(extremes), board_(std::move(board)) {
  setAcceptedMouseButtons(Qt::NoButton);
}

QRectF ExtremesNotes::boundingRect() const {
  // Labels and the dimension are drawn in device pixels beside the positions.
  return extremes_->poses().poses.empty() || !scene() ? QRectF() : scene()->sceneRect();
}

void ExtremesNotes::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const ExtremePoses& poses = extremes_->poses();
  if (poses.poses.empty()) return;
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  OverlayLabels labels(p, st.paper, board_.get());
  const bool body = bool(poses.measure.body);
  const ExtremePose *lowest = nullptr, *highest = nullptr;
  for (const ExtremePose& e : poses.poses) {
    if (!e.at.allFinite()) continue;
    // Open: the mechanism shows through when it passes the place.
    p->setPen(cosmetic(st.ink, 1.5));
    p->setBrush(Qt::NoBrush);
    const double r = CanvasStyle::outputRadius * u;
    p->drawEllipse(toQt(e.at), r, r);
    if (e.extreme.value == poses.limits.min) lowest = &e;
    if (e.extreme.value == poses.limits.max) highest = &e;
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
    for (const ExtremePose& e : poses.poses)
      if (e.at.allFinite())
        labels.paint(toQt(e.at), QPointF(12, 0), text(e), st.ink, Qt::AlignLeft);
    return;
  }
  // The stroke along the direction as a dimension beside the point's positions, on the side
  // away from the mechanism, each extreme's value at its height on it.
  const Vec2 dir = poses.measure.direction.normalized();
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
  // The values at their places along the dimension, the stroke at its middle.
  struct Label {
    QPointF at;
    QString text;
    QColor ink;
    QPointF device;  // where `at` is, device pixels
  };
  std::vector<Label> notes;
  notes.push_back({toQt((a + b) / 2),
                   QStringLiteral("stroke %1 mm").arg(poses.limits.stroke, 0, 'f', 2),
                   ink,
                   {}});
  for (const ExtremePose& e : poses.poses)
    notes.push_back(
        {toQt(a + (e.extreme.value - lowest->extreme.value) * dir), text(e), st.ink, {}});
  for (Label& l : notes) l.device = p->worldTransform().map(l.at);
  const double h = p->fontMetrics().height() + 3;
  if (std::abs(dir.x()) > std::abs(dir.y())) {
    // Across the view: each above (or below) its place, in rows away from the mechanism where
    // they would overlap.
    const double out = n.y() > 0 ? -1 : 1;
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
      labels.paint(l.at, r.center() - l.device, l.text, l.ink);
    }
    return;
  }
  // Up the view: a column beside the dimension, each at its value's height, in the order of
  // the heights; where they would overlap (a dwell's extremes close together) each goes just
  // below the one above it, so that the column reads top to bottom as the values do.
  const bool right = n.x() >= 0;
  std::stable_sort(notes.begin(), notes.end(),
                   [](const Label& x, const Label& y) { return x.device.y() < y.device.y(); });
  double y = -1e300;
  for (const Label& l : notes) {
    y = std::max(l.device.y(), y + h);
    labels.paint(l.at, QPointF(right ? 10 : -10, y - l.device.y()), l.text, l.ink,
                 right ? Qt::AlignLeft : Qt::AlignRight);
  }
}

}  // namespace linkage::ui
