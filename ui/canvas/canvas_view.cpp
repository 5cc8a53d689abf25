#include "canvas/canvas_view.h"

#include <QKeyEvent>
#include <QScrollBar>
#include <QtMath>
#include <cmath>

#include "canvas/canvas_scene.h"
#include "document/document.h"

namespace linkage::ui {

namespace {
constexpr double kMinZoom = 1e-3, kMaxZoom = 1e4;  // pixels per mm
}

CanvasView::CanvasView(CanvasScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent), scene_(scene) {
  setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
  // Animation moves most items every frame: repainting the whole viewport is cheaper than
  // collecting regions.
  setViewportUpdateMode(FullViewportUpdate);
  setOptimizationFlags(DontAdjustForAntialiasing);
  setCacheMode(CacheBackground);
  setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setTransformationAnchor(NoAnchor);
  setResizeAnchor(AnchorViewCenter);
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setFrameShape(QFrame::NoFrame);
  setZoom(4);
  scene_->setPalette(palette());
}

double CanvasView::zoom() const {
  return std::abs(transform().m11());
}

void CanvasView::setZoom(double pxPerMm) {
  pxPerMm = std::clamp(pxPerMm, kMinZoom, kMaxZoom);
  // y up: the scene is in millimetres with y pointing up.
  setTransform(QTransform::fromScale(pxPerMm, -pxPerMm));
  scaleChanged();
}

void CanvasView::zoomBy(double factor, std::optional<QPoint> anchor) {
  autoFit_ = false;
  // The point under the anchor (the view's centre by default) stays where it is.
  const QPoint at = anchor.value_or(viewport()->rect().center());
  const QPointF before = mapToScene(at);
  const double z = std::clamp(zoom() * factor, kMinZoom, kMaxZoom);
  scale(z / zoom(), z / zoom());
  scaleChanged();
  const QPointF drift = mapToScene(at) - before;
  centerOn(mapToScene(viewport()->rect().center()) - drift);
}

void CanvasView::scaleChanged() {
  scene_->setPixelSize(1.0 / zoom());
  resetCachedContent();
}

QRect CanvasView::uncoveredRect() const {
  QRect free = viewport()->rect();
  if (cover_ && !cover_->isHidden()) {
    // At most half the view: a strip taller than that is read, then the drawing is seen again.
    const int top = viewport()->mapFrom(this, cover_->geometry().topLeft()).y();
    free.setBottom(std::max(free.bottom() - free.height() / 2, std::min(free.bottom(), top - 1)));
  }
  return free;
}

void CanvasView::fitToMechanism() {
  QRectF r = scene_->mechanismRect();
  if (r.isEmpty()) r = r.adjusted(-50, -50, 50, 50);
  const QRect free = uncoveredRect();
  // Pixels around it, for symbols and labels: less in a small view (an animation's frames).
  const double margin = std::clamp(0.07 * std::min(free.width(), free.height()), 12.0, 60.0);
  const double zx = (free.width() - 2 * margin) / std::max(r.width(), 1e-9);
  const double zy = (free.height() - 2 * margin) / std::max(r.height(), 1e-9);
  setZoom(std::max(kMinZoom, std::min(zx, zy)));
  // The mechanism's centre at the free part's centre: the view's centre is that far below it.
  const double below = (viewport()->rect().center().y() - free.center().y()) / zoom();
  centerOn(r.center() - QPointF(0, below));
  // Until the user zooms or pans, the view keeps fitting the mechanism as the window resizes
  // (a file opened before the window is shown is fitted again once it has its size).
  autoFit_ = true;
}

void CanvasView::setGridVisible(bool on) {
  grid_ = on;
  resetCachedContent();
  viewport()->update();
}

void CanvasView::setSelectedCentre(int i, int j) {
  selectedCentre_ = {i, j};
  if (hoveredCentre_.first == 0) scene_->centresItem()->setChosen(i, j);
}

double CanvasView::gridStep() const {
  const double minPx = 12, z = zoom();
  double spacing = std::pow(10.0, std::floor(std::log10(minPx / z)));
  for (double f : {1.0, 2.0, 5.0, 10.0})
    if (spacing * f * z >= minPx) return spacing * f;
  return spacing * 10;
}

void CanvasView::drawBackground(QPainter* p, const QRectF& rect) {
  const CanvasStyle& st = scene_->style();
  p->fillRect(rect, st.paper);
  if (!grid_) return;
  // Minor spacing 1, 2 or 5 x 10^n mm, at least 12 pixels; majors at the next power of ten.
  const double spacing = gridStep();
  const double major = std::pow(10.0, std::floor(std::log10(spacing)) + 1);
  auto lines = [&](double step, const QColor& c) {
    QPen pen(c, 0);
    pen.setCosmetic(true);
    p->setPen(pen);
    QVector<QLineF> v;
    for (double x = std::ceil(rect.left() / step) * step; x <= rect.right(); x += step)
      v << QLineF(x, rect.top(), x, rect.bottom());
    for (double y = std::ceil(rect.top() / step) * step; y <= rect.bottom(); y += step)
      v << QLineF(rect.left(), y, rect.right(), y);
    p->drawLines(v);
  };
  p->setRenderHint(QPainter::Antialiasing, false);
  lines(spacing, st.grid);
  lines(major, st.gridMajor);
  QPen axes(st.faint, 0);
  axes.setCosmetic(true);
  p->setPen(axes);
  p->drawLine(QLineF(rect.left(), 0, rect.right(), 0));
  p->drawLine(QLineF(0, rect.top(), 0, rect.bottom()));
}

void CanvasView::wheelEvent(QWheelEvent* e) {
  const double steps = e->angleDelta().y() / 120.0;
  if (steps != 0) {
    // At the cursor (the view's own anchor follows the last mouse move, not the wheel).
    zoomBy(std::pow(1.2, steps), e->position().toPoint());
  }
  e->accept();
}

void CanvasView::panBy(const QPoint& delta) {
  autoFit_ = false;
  // Scroll bars are off but still move the view over the (large) scene rectangle.
  horizontalScrollBar()->setValue(horizontalScrollBar()->value() - delta.x());
  verticalScrollBar()->setValue(verticalScrollBar()->value() - delta.y());
}

void CanvasView::mousePressEvent(QMouseEvent* e) {
  if (e->button() == Qt::MiddleButton || (e->button() == Qt::LeftButton && spaceDown_)) {
    panning_ = true;
    spaceUsed_ = spaceDown_;
    lastPan_ = e->pos();
    viewport()->setCursor(Qt::ClosedHandCursor);
    e->accept();
    return;
  }
  QGraphicsView::mousePressEvent(e);
}

void CanvasView::mouseMoveEvent(QMouseEvent* e) {
  emit cursorMoved(mapToScene(e->pos()));
  if (panning_) {
    panBy(e->pos() - lastPan_);
    lastPan_ = e->pos();
    e->accept();
    return;
  }
  if (scene_->centresVisible()) {
    const auto near = scene_->centresItem()->centreNear(mapToScene(e->pos()), 8);
    if (near != hoveredCentre_) {
      hoveredCentre_ = near;
      scene_->centresItem()->setChosen(near.first ? near.first : selectedCentre_.first,
                                       near.first ? near.second : selectedCentre_.second);
      emit centreHovered(near.first, near.second);
    }
  }
  QGraphicsView::mouseMoveEvent(e);
}

void CanvasView::mouseReleaseEvent(QMouseEvent* e) {
  if (panning_ && (e->button() == Qt::MiddleButton || e->button() == Qt::LeftButton)) {
    panning_ = false;
    viewport()->setCursor(spaceDown_ ? Qt::OpenHandCursor : Qt::ArrowCursor);
    e->accept();
    return;
  }
  QGraphicsView::mouseReleaseEvent(e);
}

bool CanvasView::event(QEvent* e) {
  // Space is the window's play/pause shortcut; on the canvas it is also held to pan, so the
  // canvas takes the key and reports a tap itself.
  if (e->type() == QEvent::ShortcutOverride) {
    auto* k = static_cast<QKeyEvent*>(e);
    if (k->key() == Qt::Key_Space && k->modifiers() == Qt::NoModifier) {
      e->accept();
      return true;
    }
  }
  return QGraphicsView::event(e);
}

void CanvasView::paintEvent(QPaintEvent* e) {
  // Labels where they can be read: above the message strip, as Fit places the drawing.
  scene_->context()->labels.setFreeArea(uncoveredRect());
  QGraphicsView::paintEvent(e);
}

void CanvasView::keyPressEvent(QKeyEvent* e) {
  if (e->key() == Qt::Key_Space && e->modifiers() == Qt::NoModifier) {
    if (!e->isAutoRepeat()) {
      spaceDown_ = true;
      spaceUsed_ = false;
      viewport()->setCursor(Qt::OpenHandCursor);
    }
    e->accept();
    return;
  }
  QGraphicsView::keyPressEvent(e);
}

void CanvasView::keyReleaseEvent(QKeyEvent* e) {
  if (e->key() == Qt::Key_Space) {
    if (!e->isAutoRepeat()) {
      spaceDown_ = false;
      if (!panning_) viewport()->setCursor(Qt::ArrowCursor);
      if (!spaceUsed_ && !panning_) emit spaceTapped();
    }
    e->accept();
    return;
  }
  QGraphicsView::keyReleaseEvent(e);
}

void CanvasView::resizeEvent(QResizeEvent* e) {
  QGraphicsView::resizeEvent(e);
  if (autoFit_ && scene_->document()) fitToMechanism();
}

void CanvasView::changeEvent(QEvent* e) {
  if (e->type() == QEvent::PaletteChange) {
    scene_->setPalette(palette());
    resetCachedContent();
  }
  QGraphicsView::changeEvent(e);
}

}  // namespace linkage::ui
