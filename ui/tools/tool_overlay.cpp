#include "tools/tool_overlay.h"

#include <QGraphicsScene>
#include <QPainter>

#include "canvas/canvas_scene.h"
#include "linkage/guide.h"
#include "tools/selection.h"

namespace linkage::ui {

namespace {

// The symbol of `j` when it is outlined by lines of its own (a gear's or belt's), else nullptr.
const JointItem* linesItem(const CanvasScene& s, JointId j) {
  for (const JointItem* item : s.jointItems())
    if (item->joint() == j && item->isVisible()) return item->pickedByLines() ? item : nullptr;
  return nullptr;
}

}  // namespace

ToolOverlay::ToolOverlay(const CanvasContext* ctx, const CanvasScene* scene,
                         const Selection* selection)
    : CanvasItem(ctx), scene_(scene), selection_(selection) {
  setAcceptedMouseButtons(Qt::NoButton);
  setZValue(95);
}

void ToolOverlay::setHover(const Pick& p) {
  if (p.point == hover_.point && p.body == hover_.body && p.slot == hover_.slot &&
      p.joint == hover_.joint && p.coupling == hover_.coupling &&
      p.onCouplingLines == hover_.onCouplingLines)
    return;
  hover_ = p;
  update();
}

void ToolOverlay::setSnap(const std::optional<Snap>& s) {
  snap_ = s;
  update();
}

void ToolOverlay::setPath(const std::vector<Vec2>& vertices, std::optional<Vec2> cursor) {
  path_ = vertices;
  cursor_ = cursor;
  update();
}

void ToolOverlay::setBand(const std::optional<QRectF>& r) {
  band_ = r;
  update();
}

void ToolOverlay::clearPreview() {
  path_.clear();
  cursor_.reset();
  band_.reset();
  snap_.reset();
  update();
}

QRectF ToolOverlay::boundingRect() const {
  return scene() ? scene()->sceneRect() : QRectF();
}

void ToolOverlay::label(QPainter* p, const QPointF& at, const QString& text,
                        const QColor& ink) const {
  const QPointF d = p->worldTransform().map(at);
  p->save();
  p->resetTransform();
  QRectF r = p->fontMetrics().boundingRect(text);
  r.moveTopLeft(d + QPointF(10, 8));
  QColor back = style().paper;
  back.setAlphaF(0.85);
  p->fillRect(r.adjusted(-3, -1, 3, 1), back);
  p->setPen(ink);
  p->drawText(r, Qt::AlignCenter, text);
  p->restore();
}

void ToolOverlay::paintSelection(QPainter* p) const {
  const CanvasStyle& st = style();
  const double u = px();
  const QPen ring = cosmetic(st.highlight, 2);
  p->setBrush(Qt::NoBrush);
  for (BodyId b : selection_->bodies)
    if (const BodyItem* item = scene_->bodyItem(b)) {
      p->setPen(cosmetic(st.highlight, 3));
      p->drawPolygon(cutToDevice(item->sceneTransform().map(item->outline()), p));
    }
  const Mechanism& m = scene_->shownMechanism();
  p->setPen(ring);
  for (PointId pt : selection_->points) {
    const Vec2 at = scene_->worldOf(pt);
    if (at.allFinite()) p->drawEllipse(toQt(at), 8 * u, 8 * u);
  }
  for (JointId j : selection_->joints)
    if (const JointItem* g = linesItem(*scene_, j)) {
      // A gear or belt: its pitch circles (and belt) traced over.
      p->setPen(cosmetic(st.highlight, 3));
      p->drawPath(g->lines());
      p->setPen(ring);
    } else if (const Joint* joint = m.joint(j)) {
      const Vec2 at = scene_->worldOf(joint->a);
      if (at.allFinite())
        p->drawRect(QRectF(toQt(at) - QPointF(10 * u, 10 * u), QSizeF(20 * u, 20 * u)));
    }
  for (SlotId s : selection_->slots_)
    if (const Slot* sl = scene_->planeView().seen(m).slot(s))  // a ground slot in the plane
      p->drawPolygon(cutToDevice(slotOutline(*sl, scene_->poseOf(sl->body), u), p));
}

QPolygonF slotOutline(const Slot& s, const Transform& pose, double px, double margin) {
  const double r = (CanvasStyle::channelWidth / 2 + margin) * px;
  // Around the channel as BodyItem draws it: an arc's outline was once its chord's capsule.
  if (const std::optional<Guide> g = guideOf(s)) return toQt(pose).map(channel(*g, r, px));
  return capsule(pose * s.p0, pose * s.p1, r, px);
}

void ToolOverlay::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  paintSelection(p);
  const Mechanism& m = scene_->shownMechanism();
  // The body under the cursor, outlined.
  if (hover_.body && !hover_.onGround)
    if (const BodyItem* item = scene_->bodyItem(hover_.body)) {
      p->setPen(cosmetic(st.highlight, 1.5, Qt::DashLine));
      p->setBrush(Qt::NoBrush);
      p->drawPolygon(cutToDevice(item->sceneTransform().map(item->outline()), p));
    }
  // The gear or belt whose lines are under the cursor, traced.
  if (hover_.coupling && hover_.onCouplingLines)
    if (const JointItem* g = linesItem(*scene_, hover_.coupling)) {
      p->setPen(cosmetic(st.highlight, 1.5, Qt::DashLine));
      p->setBrush(Qt::NoBrush);
      p->drawPath(g->lines());
    }
  // The link being drawn.
  if (!path_.empty()) {
    QPolygonF poly;
    for (const Vec2& v : path_) poly << toQt(v);
    if (cursor_) poly << toQt(*cursor_);
    p->setPen(cosmetic(st.highlight, 2));
    p->drawPolyline(poly);
    p->setBrush(st.paper);
    for (const Vec2& v : path_) p->drawEllipse(toQt(v), 4 * u, 4 * u);
  }
  if (band_) {
    QColor fill = st.highlight;
    fill.setAlphaF(0.12);
    p->setPen(cosmetic(st.highlight, 1, Qt::DashLine));
    p->setBrush(fill);
    p->drawRect(*band_);
  }
  // What a click would snap to, named.
  if (snap_ && snap_->kind != Snap::Kind::Free) {
    const QPointF at = toQt(snap_->at);
    p->setPen(cosmetic(st.highlight, 2));
    p->setBrush(Qt::NoBrush);
    if (snap_->kind == Snap::Kind::Point)
      p->drawEllipse(at, 7 * u, 7 * u);
    else if (snap_->kind == Snap::Kind::Slot)
      p->drawRect(QRectF(at - QPointF(5 * u, 5 * u), QSizeF(10 * u, 10 * u)));
    else {
      p->drawLine(at - QPointF(6 * u, 0), at + QPointF(6 * u, 0));
      p->drawLine(at - QPointF(0, 6 * u), at + QPointF(0, 6 * u));
    }
    QString text = snap_->label;
    if (snap_->kind != Snap::Kind::Point && hover_.body && !hover_.onGround)
      if (const Body* b = m.body(hover_.body))
        text += QStringLiteral(" \u2013 on %1").arg(QString::fromStdString(b->name));
    label(p, at, text, st.highlight);
  }
}

}  // namespace linkage::ui
