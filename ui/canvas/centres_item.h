// The instant-centre overlay: every centre as a dot labelled "i,j" (primary, Kennedy and
// velocity-derived centres in their own colours), a centre at infinity or far outside the view
// as an arrow at the view's edge pointing its way (with its distance when finite), and for the
// hovered or chosen centre the two Kennedy lines that found it, through the centres that define
// them, as the homework draws them by hand. One item paints them all: it needs the view's
// visible rectangle, which it reads from the painter.
#pragma once

#include <QFont>
#include <QPixmap>
#include <QStaticText>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "draw/canvas_item.h"
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
  // An arrow at the view's edge for a centre outside it: where, which way.
  struct EdgeTip {
    QPointF tip, direction;
    const Drawing::Centre* centre;
  };
  // In device pixels: the tip and its direction.
  std::optional<EdgeTip> edgeTip(const Drawing::Centre& c, const QRectF& view,
                                 const QTransform& toDevice) const;
  void paintEdgeArrows(QPainter* p, const std::vector<EdgeTip>& tips);
  void paintEdgeArrow(QPainter* p, const std::vector<EdgeTip>& group);
  static QString edgeText(const Drawing::Centre& c);
  // A label where no other is (the canvas's LabelBoard) near the device point `at`, with the
  // painter in device pixels; false when there is no free place, and it is not drawn.
  bool paintLabel(QPainter* p, const QPointF& at, const QString& text, const QColor& ink);
  QStaticText& staticText(const QString& text, const QFont& font);
  // A centre's dot drawn once per colour, kind and pixel ratio.
  const QPixmap& dot(const QColor& ink, bool primary, qreal dpr);
  void rebuild() override;

  std::vector<Drawing::Centre> centres_;
  std::pair<int, int> chosen_{0, 0};
  QRectF device_;  // the view, device pixels
  // The labels' text laid out once (a machine's 465 centres: most of a frame was text layout).
  std::unordered_map<QString, std::pair<QStaticText, QFont>> texts_;
  std::map<std::tuple<QRgb, bool, int>, QPixmap> dots_;
};

}  // namespace linkage::ui
