// Where labels are on the canvas in one paint, in device pixels, so that the next label can be
// put where none is: the velocity chain's dimensions (painted first) and then the instant
// centres' labels, which step aside from them and from each other. A label with no free place
// near its anchor is not drawn (the Instant Centres panel lists every centre): a pile of
// overprinted labels reads as nothing. Cleared as each paint begins, by LabelStart, the lowest
// item of the scene (the view caches its background: drawBackground is not called per paint).
//
// Rects are kept in a grid of cells, so that a check is against the few labels near it, not
// all of them (a 31-body machine has 465 centres).
#pragma once

#include <QGraphicsItem>
#include <QRectF>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

namespace linkage::ui {

class LabelBoard {
 public:
  // The labels of the last paint go; the free area stays (the view sets it per paint).
  void clear();
  // The part of the view labels may use, device pixels: the view's, less what the widgets laid
  // over it cover (the message strip: CanvasView::uncoveredRect); empty: the whole device.
  void setFreeArea(const QRectF& r) { free_ = r; }
  // `device` within the free area.
  QRectF freePart(const QRectF& device) const {
    return free_.isEmpty() ? device : device.intersected(free_);
  }
  bool isFree(const QRectF& r) const;
  void take(const QRectF& r);
  // The first of `tries` (each a place for the label) that is free and inside `bounds` (and
  // the free area), taken; nullopt when none is.
  std::optional<QRectF> place(const std::vector<QRectF>& tries, const QRectF& bounds);
  int size() const { return static_cast<int>(rects_.size()); }
  const std::vector<QRectF>& rects() const { return rects_; }

 private:
  static constexpr double kCell = 48;  // pixels
  template <class F>
  void forCells(const QRectF& r, F f) const;
  std::vector<QRectF> rects_;
  QRectF free_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

// Paints nothing: the first item of every paint, it lets the scene start the board
// (CanvasScene::startLabels).
class LabelStart : public QGraphicsItem {
 public:
  explicit LabelStart(std::function<void(const QTransform&)> start);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  std::function<void(const QTransform&)> start_;
};

}  // namespace linkage::ui
