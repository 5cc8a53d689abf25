// Labels of the design overlays: upright text of one size in device pixels at a scene point,
// on a backing of the paper colour, each moved off the labels placed before it in the same
// frame (the output points' names, values at neighbouring joints, extremes close together, the
// arcs' values beside the stroke's) and kept inside the view: the canvas's LabelBoard
// (canvas/label_board.h). Unlike the centres' labels these are always drawn: they are values.
#pragma once

#include <QColor>
#include <QGraphicsItem>
#include <QPainter>
#include <QRectF>
#include <QString>
#include <vector>

#include "canvas/label_board.h"

namespace linkage::ui {

class OverlayLabels {
 public:
  // Kept inside p's device; `paper`: the backing's colour.
  OverlayLabels(QPainter* p, const QColor& paper, LabelBoard* board);
  // Paints `text` `offsetPx` (x right, y down) from the scene point `at`, there by its left
  // edge (Qt::AlignLeft), its right edge (Qt::AlignRight) or its centre; returns where it
  // went, device pixels.
  QRectF paint(const QPointF& at, const QPointF& offsetPx, const QString& text, const QColor& ink,
               Qt::Alignment anchor = Qt::AlignCenter);
  // The first of these places where the label overlaps none placed before (else the first,
  // moved off them).
  struct Place {
    QPointF at, offsetPx;
    Qt::Alignment anchor = Qt::AlignCenter;
  };
  QRectF paint(const std::vector<Place>& places, const QString& text, const QColor& ink);

 private:
  QRectF rectAt(const Place& place, const QString& text) const;
  bool clear(const QRectF& r) const;

  QPainter* p_;
  QRectF device_;
  QColor back_;
  LabelBoard* placed_;
};

}  // namespace linkage::ui
