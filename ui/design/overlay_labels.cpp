#include "design/overlay_labels.h"

#include <algorithm>
#include <cmath>

namespace linkage::ui {

OverlayLabels::OverlayLabels(QPainter* p, const QColor& paper, LabelBoard* board)
    : p_(p),
      device_(board->freePart(QRectF(0, 0, p->device()->width(), p->device()->height()))),
      back_(paper),
      placed_(board) {
  back_.setAlphaF(0.8);
}

QRectF OverlayLabels::rectAt(const Place& place, const QString& text) const {
  const QPointF d = p_->worldTransform().map(place.at) + place.offsetPx;
  QRectF r = QRectF(p_->fontMetrics().boundingRect(text)).adjusted(-3, -1, 3, 1);
  r.moveCenter(d);
  if (place.anchor & Qt::AlignLeft) r.moveLeft(d.x());
  if (place.anchor & Qt::AlignRight) r.moveRight(d.x());
  return r;
}

QRectF OverlayLabels::inside(QRectF r) const {
  // The right and bottom first: a label wider than the view keeps its start in sight.
  if (r.right() > device_.right() - 2) r.moveRight(device_.right() - 2);
  if (r.bottom() > device_.bottom() - 2) r.moveBottom(device_.bottom() - 2);
  if (r.left() < device_.left() + 2) r.moveLeft(device_.left() + 2);
  if (r.top() < device_.top() + 2) r.moveTop(device_.top() + 2);
  return r;
}

bool OverlayLabels::clear(const QRectF& r) const {
  return placed_->isFree(r);
}

QRectF OverlayLabels::nearestFree(const QRectF& start) const {
  const QRectF room = device_.adjusted(2, 2, -2, -2);
  auto fits = [&](const QRectF& r) { return room.contains(r) && clear(r); };
  // Whole label heights down, then up, nearest first: level with its place, the label stays
  // beside what it names (most paints end here).
  const double dy = start.height() + 1, dx = start.width() / 2 + 1;
  const int rows = static_cast<int>(room.height() / dy) + 1;
  for (int j = 1; j <= rows; ++j)
    for (int sign : {1, -1})
      if (const QRectF r = start.translated(0, sign * j * dy); fits(r)) return r;
  // A crowded column: aside too, by half widths, the nearest place first (a step aside
  // counting double).
  const int cols = static_cast<int>(room.width() / dx) + 1;
  std::vector<std::pair<double, QPointF>> steps;
  for (int j = -rows; j <= rows; ++j)
    for (int i = -cols; i <= cols; ++i)
      if (i != 0) steps.push_back({std::hypot(2 * i * dx, j * dy), QPointF(i * dx, j * dy)});
  std::stable_sort(steps.begin(), steps.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& step : steps)
    if (const QRectF r = start.translated(step.second); fits(r)) return r;
  return start;
}

QRectF OverlayLabels::paint(const QPointF& at, const QPointF& offsetPx, const QString& text,
                            const QColor& ink, Qt::Alignment anchor) {
  return paint(std::vector<Place>{{at, offsetPx, anchor}}, text, ink);
}

QRectF OverlayLabels::paint(const std::vector<Place>& places, const QString& text,
                            const QColor& ink) {
  QRectF r;
  bool found = false;
  for (const Place& place : places) {
    r = inside(rectAt(place, text));
    if ((found = clear(r))) break;
  }
  if (!found) r = nearestFree(inside(rectAt(places.front(), text)));
  placed_->take(r);
  painted_.push_back(r);
  p_->save();
  p_->resetTransform();
  p_->fillRect(r, back_);
  p_->setPen(ink);
  p_->drawText(r, Qt::AlignCenter, text);
  p_->restore();
  return r;
}

}  // namespace linkage::ui
