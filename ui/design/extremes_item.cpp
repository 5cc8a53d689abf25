#include "design/extremes_item.h"

#include <QGraphicsScene>
#include <QPainter>
#include <QWidget>
#include <cmath>
#include <map>

#include "canvas/body_item.h"
#include "design/extremes_notes.h"
#include "linkage/elements.h"

namespace linkage::ui {

namespace {

// A colour 45% of the way from the paper to c, opaque: light lines that cost what solid ones do
// (translucent antialiased lines took the raster engine twice as long as the whole canvas).
QColor faint(const QColor& c, const QColor& paper) {
  const double f = 0.45;
  return QColor::fromRgbF(f * c.redF() + (1 - f) * paper.redF(),
                          f * c.greenF() + (1 - f) * paper.greenF(),
                          f * c.blueF() + (1 - f) * paper.blueF());
}

}  // namespace

ExtremePoses findExtremePoses(const Kinematics& k, const LimitMeasure& what) {
  ExtremePoses out;
  out.measure = what;
  const Mechanism& m = k.mechanism();
  out.limits = findLimits(k, what);
  if (!out.limits.status.ok()) return out;
  // Where a body's extreme is marked: its first point.
  PointId mark = what.point;
  for (const Point& p : m.points)
    if (!mark && p.body == what.body) mark = p.id;
  Kinematics turned = k;
  if (out.status = turned.moveTo(0); !out.status.ok()) return out;
  for (const LocalExtreme& e : out.limits.extremes) {
    if (out.status = turned.moveTo(e.crankDeg); !out.status.ok()) break;
    out.poses.push_back({e, describeDrawing(turned), turned.position(mark)});
  }
  return out;
}

ExtremesItem::ExtremesItem(const CanvasContext* ctx) : CanvasItem(ctx) {
  setAcceptedMouseButtons(Qt::NoButton);
}

void ExtremesItem::setPoses(ExtremePoses poses) {
  poses_ = std::move(poses);
  restyle();
  if (notes_) notes_->update();
}

void ExtremesItem::clear() {
  setPoses({});
}

void ExtremesItem::rebuild() {
  ghosts_.clear();
  const double u = px();
  for (const ExtremePose& pose : poses_.poses) {
    const Drawing& d = pose.drawing;
    Ghost g;
    std::map<BodyId, int> number;
    for (const Drawing::Body& b : d.bodies) {
      number[b.id] = b.number;
      if (b.shape == Drawing::Shape::Ground) continue;
      const QPolygonF o = bodyOutline(b, u);
      if (!o.isEmpty()) g.outlines.emplace_back(toQt(b.pose).map(o), b.number);
    }
    // Blocks as their outlines, moving pins as dots (by the joints' structural roles).
    for (const JointSymbol& b : d.joints) {
      const Role role = elementKind(b.type).role;
      if (role == Role::Prismatic) {
        const Vec2 l = b.direction * (CanvasStyle::blockLength / 2 * u);
        const Vec2 w = perp(b.direction) * (CanvasStyle::blockWidth / 2 * u);
        g.outlines.emplace_back(
            QPolygonF({toQt(b.at - l - w), toQt(b.at + l - w), toQt(b.at + l + w),
                       toQt(b.at - l + w), toQt(b.at - l - w)}),
            number[b.bodies[0]]);
      } else if ((role == Role::Revolute && !b.groundPivot) || role == Role::PointOnCurve) {
        g.pins.push_back(toQt(b.at));
      }
    }
    ghosts_.push_back(std::move(g));
  }
}

QRectF ExtremesItem::boundingRect() const {
  QRectF r;
  for (const Ghost& g : ghosts_)
    for (const auto& [outline, n] : g.outlines) r = r.united(outline.boundingRect());
  const double m = CanvasStyle::pinRadius * px() + 2 * px();
  return r.adjusted(-m, -m, m, m);
}

void ExtremesItem::paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) {
  if (ghosts_.empty()) return;
  const CanvasStyle& st = style();
  const double u = px();
  p->setRenderHint(QPainter::Antialiasing);
  for (const Ghost& g : ghosts_) {
    for (const auto& [outline, n] : g.outlines) {
      p->setPen(cosmetic(faint(st.body(n), st.paper), 1));
      p->setBrush(Qt::NoBrush);
      p->drawPolygon(outline);
    }
    p->setPen(cosmetic(faint(st.ink, st.paper), 1));
    p->setBrush(Qt::NoBrush);
    const double r = 0.8 * CanvasStyle::pinRadius * u;
    for (const QPointF& c : g.pins) p->drawEllipse(c, r, r);
  }
}

}  // namespace linkage::ui
