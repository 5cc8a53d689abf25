// Labels of the design overlays: upright text of one size in device pixels at a scene point,
// on a backing of the paper colour, each moved off the labels placed before it in the same
// frame (the output points' names, values at neighbouring joints, extremes close together, the
// arcs' values beside the stroke's) and kept inside the view: the canvas's LabelBoard
// (draw/label_board.h). Unlike the centres' labels these are always drawn: they are values.
#pragma once

#include <QColor>
#include <QGraphicsItem>
#include <QPainter>
#include <QRectF>
#include <QString>
#include <vector>

#include "draw/label_board.h"

namespace linkage::ui {

class OverlayLabels {
 public:
  // Kept inside p's device, in the board's free area (above the message strip); `paper`: the
  // backing's colour.
  OverlayLabels(QPainter* p, const QColor& paper, LabelBoard* board);
  // Where labels go, device pixels.
  const QRectF& bounds() const { return device_; }
  // Paints `text` `offsetPx` (x right, y down) from the scene point `at`, there by its left
  // edge (Qt::AlignLeft), its right edge (Qt::AlignRight) or its centre; returns where it
  // went, device pixels.
  QRectF paint(const QPointF& at, const QPointF& offsetPx, const QString& text, const QColor& ink,
               Qt::Alignment anchor = Qt::AlignCenter);
  // The first of these places where the label overlaps none placed before (else the first,
  // moved off them: by whole label heights up or down, then aside, the nearest free place in
  // the bounds; overprinted only when the bounds hold no free place at all).
  struct Place {
    QPointF at, offsetPx;
    Qt::Alignment anchor = Qt::AlignCenter;
  };
  QRectF paint(const std::vector<Place>& places, const QString& text, const QColor& ink);
  // Where the labels painted so far went, device pixels.
  const std::vector<QRectF>& painted() const { return painted_; }

 private:
  QRectF rectAt(const Place& place, const QString& text) const;
  QRectF inside(QRectF r) const;  // moved into the bounds
  QRectF nearestFree(const QRectF& start) const;
  bool clear(const QRectF& r) const;

  QPainter* p_;
  QRectF device_;
  QColor back_;
  LabelBoard* placed_;
  std::vector<QRectF> painted_;
};

}  // namespace linkage::ui
