#include "draw/label_board.h"

#include <QGraphicsScene>
#include <QPainter>
#include <cmath>

namespace linkage::ui {

template <class F>
void LabelBoard::forCells(const QRectF& r, F f) const {
  const long long x0 = static_cast<long long>(std::floor(r.left() / kCell)),
                  x1 = static_cast<long long>(std::floor(r.right() / kCell)),
                  y0 = static_cast<long long>(std::floor(r.top() / kCell)),
                  y1 = static_cast<long long>(std::floor(r.bottom() / kCell));
  for (long long x = x0; x <= x1; ++x)
    for (long long y = y0; y <= y1; ++y) f((x << 32) ^ (y & 0xffffffffLL));
}

void LabelBoard::clear() {
  rects_.clear();
  cells_.clear();
}

bool LabelBoard::isFree(const QRectF& r) const {
  bool free = true;
  forCells(r, [&](long long key) {
    if (!free) return;
    const auto it = cells_.find(key);
    if (it == cells_.end()) return;
    for (int i : it->second)
      if (rects_[i].intersects(r)) {
        free = false;
        return;
      }
  });
  return free;
}

void LabelBoard::take(const QRectF& r) {
  const int i = static_cast<int>(rects_.size());
  rects_.push_back(r);
  forCells(r, [&](long long key) { cells_[key].push_back(i); });
}

std::optional<QRectF> LabelBoard::place(const std::vector<QRectF>& tries, const QRectF& bounds) {
  const QRectF inside = freePart(bounds);
  for (const QRectF& r : tries)
    if (inside.contains(r) && isFree(r)) {
      take(r);
      return r;
    }
  return std::nullopt;
}

LabelStart::LabelStart(std::function<void(const QTransform&)> start) : start_(std::move(start)) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(-1e9);
}

QRectF LabelStart::boundingRect() const {
  return scene() ? scene()->sceneRect() : QRectF();
}

void LabelStart::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  start_(p->worldTransform());
}

}  // namespace linkage::ui
