#include "design/overlay_labels.h"

namespace linkage::ui {

OverlayLabels::OverlayLabels(QPainter* p, const QColor& paper, LabelBoard* board)
    : p_(p),
      device_(0, 0, p->device()->width(), p->device()->height()),
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

bool OverlayLabels::clear(const QRectF& r) const {
  return placed_->isFree(r);
}

QRectF OverlayLabels::paint(const QPointF& at, const QPointF& offsetPx, const QString& text,
                            const QColor& ink, Qt::Alignment anchor) {
  return paint(std::vector<Place>{{at, offsetPx, anchor}}, text, ink);
}

QRectF OverlayLabels::paint(const std::vector<Place>& places, const QString& text,
                            const QColor& ink) {
  QRectF r;
  for (const Place& place : places) {
    r = rectAt(place, text);
    if (clear(r)) break;
  }
  if (!clear(r)) {
    // Off the labels placed before: down, then up, by whole label heights.
    const QRectF start = rectAt(places.front(), text);
    r = start;
    for (int tries = 1; tries < 12 && !clear(r); ++tries) {
      const int step = (tries + 1) / 2 * (tries % 2 ? 1 : -1);
      r = start.translated(0, step * (r.height() + 1));
    }
  }
  if (r.right() > device_.right() - 2) r.moveRight(device_.right() - 2);
  if (r.bottom() > device_.bottom() - 2) r.moveBottom(device_.bottom() - 2);
  if (r.left() < device_.left() + 2) r.moveLeft(device_.left() + 2);
  if (r.top() < device_.top() + 2) r.moveTop(device_.top() + 2);
  placed_->take(r);
  p_->save();
  p_->resetTransform();
  p_->fillRect(r, back_);
  p_->setPen(ink);
  p_->drawText(r, Qt::AlignCenter, text);
  p_->restore();
  return r;
}

}  // namespace linkage::ui
