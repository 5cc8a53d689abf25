// The instant-centre overlay: every centre as a dot labelled "i,j" (primary, Kennedy and
// velocity-derived centres in their own colours), a centre at infinity or far outside the view
// as an arrow at the view's edge pointing its way (with its distance when finite), and for the
// hovered or chosen centre the two Kennedy lines that found it, through the centres that define
// them, as the homework draws them by hand. One item paints them all: it needs the view's
// visible rectangle, which it reads from the painter.
#pragma once

#include <vector>

#include "canvas/canvas_item.h"
#include "linkage/drawing.h"

namespace linkage::ui {

class CentresItem : public CanvasItem {
 public:
  explicit CentresItem(const CanvasContext* ctx);
  void setCentres(const std::vector<Drawing::Centre>& centres);
  const std::vector<Drawing::Centre>& centres() const { return centres_; }
  // The centre (i, j) whose Kennedy lines are drawn; (0, 0) for none.
  void setChosen(int i, int j);
  std::pair<int, int> chosen() const { return chosen_; }
  // The finite centre within `radiusPx` screen pixels of a scene point, or (0, 0).
  std::pair<int, int> centreNear(const QPointF& scenePos, double radiusPx) const;

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) override;

 private:
  const Drawing::Centre* find(int i, int j) const;
  QColor colour(const Drawing::Centre& c) const;
  void paintLines(QPainter* p, const Drawing::Centre& c, const QRectF& view) const;
  void paintEdgeArrow(QPainter* p, const Drawing::Centre& c, const QRectF& view);
  // Labels are stacked so that two never overlap (arrows at the edge often gather).
  void paintLabel(QPainter* p, const QPointF& at, const QString& text, const QColor& ink);

  std::vector<Drawing::Centre> centres_;
  std::pair<int, int> chosen_{0, 0};
  std::vector<QRectF> placed_;  // labels painted so far in this paint (device pixels)
  QRectF device_;               // the view, device pixels
};

}  // namespace linkage::ui
