// The base of the canvas's items: what they share is the scale (millimetres per screen pixel,
// so that symbols keep their size on screen at any zoom) and the style (palette colours).
// Items are in scene coordinates, millimetres with y up (the view flips the y axis). ui/draw/
// is the layer below the canvas and the element kinds (ui/elements/): both draw with it.
#pragma once

#include <QGraphicsItem>
#include <QPainterPath>
#include <QPen>
#include <QPolygonF>
#include <QTransform>

#include "draw/label_board.h"
#include "draw/style.h"
#include "linkage/geometry.h"

namespace linkage {
class PlaneView;
}

namespace linkage::ui {

// A pen whose width is in screen pixels: the raster engine strokes it on its fast path, and it
// looks the same at any zoom.
inline QPen cosmetic(const QColor& c, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen p(c, width, style);
  p.setCosmetic(true);
  return p;
}

// The solver's vectors and poses in Qt's terms (scene coordinates: millimetres, y up).
QPointF toQt(const Vec2& v);
QTransform toQt(const Transform& t);

// A polygon far larger than what the painter paints on, cut to that area and as much again on
// every side: Qt's raster engine strokes coordinates beyond its fast path's range on a slow one
// (a plate typed a kilometre long cost 0.4 s a paint at 4 pixels a millimetre). The cut covers
// the same pixels; its new edges lie outside what is seen.
QPolygonF cutToDevice(const QPolygonF& poly, const QPainter* p);

struct CanvasContext {
  double px = 0.1;  // mm per screen pixel
  CanvasStyle style;
  // The labels of this paint (cleared as the view starts one): items that label step aside.
  mutable LabelBoard labels;
  // A machine in space: the plane the canvas shows (linkage/plane_view.h); the solver's
  // positions, in each body's plane class frame, are mapped into it. Null: nothing to map.
  const PlaneView* view = nullptr;
};

class CanvasItem : public QGraphicsItem {
 public:
  explicit CanvasItem(const CanvasContext* ctx, QGraphicsItem* parent = nullptr)
      : QGraphicsItem(parent), ctx_(ctx) {}
  // The scale or the palette changed: geometry that depends on them is made again.
  void restyle() {
    prepareGeometryChange();
    rebuild();
    update();
  }

 protected:
  // May replace this item's own children (labels), never another item.
  virtual void rebuild() {}
  const CanvasContext& ctx() const { return *ctx_; }
  double px() const { return ctx_->px; }
  const CanvasStyle& style() const { return ctx_->style; }

 private:
  const CanvasContext* ctx_;
};

// Text that stays upright and of one size whatever the view does, on a backing of the paper
// colour so that it reads over lines; anchored at its position, shifted by `offset` pixels.
class LabelItem : public QGraphicsItem {
 public:
  LabelItem(const QString& text, QGraphicsItem* parent = nullptr);
  void setText(const QString& text);
  QString text() const { return text_; }
  void setColours(const QColor& ink, const QColor& paper);
  // Pixels, x right and y down, from the anchor to the text's centre.
  void setOffset(const QPointF& offset);
  void setBold(bool bold);
  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  QRectF textRect() const;
  QString text_;
  QColor ink_ = Qt::black, halo_ = Qt::white;
  QPointF offset_;
  bool bold_ = false;
};

}  // namespace linkage::ui
