// The canvas: millimetres with y up, zoom at the cursor (wheel), pan (middle drag, or Space and
// drag), fit to the mechanism, an adaptive grid. Space tapped without a drag is reported
// (spaceTapped) so that the window can use it for play/pause.
#pragma once

#include <QGraphicsView>
#include <optional>

namespace linkage::ui {

class CanvasScene;

class CanvasView : public QGraphicsView {
  Q_OBJECT

 public:
  explicit CanvasView(CanvasScene* scene, QWidget* parent = nullptr);
  CanvasScene* canvasScene() const { return scene_; }

  void setGridVisible(bool on);
  bool gridVisible() const { return grid_; }
  // The grid's spacing at this zoom (mm): 1, 2 or 5 x 10^n, at least 12 pixels.
  double gridStep() const;
  // Pixels per millimetre.
  double zoom() const;
  void setZoom(double pxPerMm);
  // Zooms about a viewport point (the view's centre when none is given).
  void zoomBy(double factor, std::optional<QPoint> anchor = std::nullopt);
  // Pixels per millimetre at which the drawing is at its real size (the screen's logical DPI).
  double actualSizeZoom() const { return logicalDpiX() / 25.4; }
  // The whole mechanism (and its traced paths) in view, with a margin, in the part of the view
  // that the widget laid over its bottom edge (the message strip) leaves free.
  void fitToMechanism();
  // A child widget over the bottom of the view (not part of it: the view does not shrink);
  // fitting keeps the mechanism out from under it while it is shown.
  void setBottomCover(QWidget* cover) { cover_ = cover; }
  // The viewport's part above the cover, where fitting places the mechanism.
  QRect uncoveredRect() const;
  // Panning now (middle button, or Space held): the tools leave the mouse to the view.
  bool panning() const { return panning_; }
  bool spaceHeld() const { return spaceDown_; }
  // The centre whose Kennedy lines are drawn when the mouse is on no centre.
  void setSelectedCentre(int i, int j);

 Q_SIGNALS:
  void cursorMoved(QPointF mm);
  void spaceTapped();
  void centreHovered(int i, int j);

 protected:
  bool event(QEvent* e) override;
  void paintEvent(QPaintEvent* e) override;
  void drawBackground(QPainter* p, const QRectF& rect) override;
  void wheelEvent(QWheelEvent* e) override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void keyPressEvent(QKeyEvent* e) override;
  void keyReleaseEvent(QKeyEvent* e) override;
  void resizeEvent(QResizeEvent* e) override;
  void changeEvent(QEvent* e) override;

 private:
  void scaleChanged();
  void panBy(const QPoint& delta);

  CanvasScene* scene_;
  bool grid_ = true;
  bool spaceDown_ = false, spaceUsed_ = false, panning_ = false;
  QPoint lastPan_;
  std::pair<int, int> selectedCentre_{0, 0}, hoveredCentre_{0, 0};
  bool autoFit_ = true;
  QWidget* cover_ = nullptr;
};

}  // namespace linkage::ui
