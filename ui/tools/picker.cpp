#include "tools/picker.h"

#include <cmath>

#include "canvas/canvas_scene.h"
#include "linkage/elements.h"
#include "linkage/guide.h"

namespace linkage::ui {

namespace {

// The gear or belt under the cursor: drawn lines within a few pixels (the nearest), else the
// smallest pitch circle that holds it. Gears are no pins: they have no point of their own to
// click, so their lines and circles are what a user aims at.
void pickCoupling(const CanvasScene& s, const Vec2& world, double px, Pick& pick) {
  double bestLine = kCouplingPixels * px, bestArea = INFINITY;  // mm
  JointId inside;
  for (const JointItem* j : s.jointItems()) {
    if (!j->pickedByLines() || !j->isVisible() || !j->isEnabled()) continue;
    if (const double d = j->distanceToLines(world); d < bestLine) {
      bestLine = d;
      pick.coupling = j->joint();
      pick.onCouplingLines = true;
    } else if (const double r = j->radiusHolding(world); r < bestArea) {
      bestArea = r;
      inside = j->joint();
    }
  }
  if (!pick.coupling) pick.coupling = inside;
}

}  // namespace

Pick pickAt(const CanvasScene& s, const Vec2& world, double px) {
  Pick pick;
  const Mechanism& m = s.shownMechanism();
  double best = kPickPixels * px;
  // A hidden mechanism (the Mechanisms panel) is not drawn, so nothing of it is picked.
  for (const Point& p : m.points) {
    if (s.bodyHidden(p.body)) continue;
    const Vec2 at = s.worldOf(p.id);
    const double d = (at - world).norm();
    // Among coincident points (a pin), the first in file order: the stable choice.
    if (d < best - 1e-12 * std::max(1.0, best)) {
      best = d;
      pick.point = p.id;
      pick.pointAt = at;
    }
  }
  if (pick.point)
    for (const Joint& j : m.joints)
      if (kindOf(j).role == Role::Revolute && (j.a == pick.point || j.b == pick.point)) {
        pick.joint = j.id;
        break;
      }
  // Slots within their channel (half its width and a little).
  const double reach = (CanvasStyle::channelWidth / 2 + 3) * px;
  double bestSlot = reach;
  // The slots as drawn in the shown plane (linkage/plane_view.h; a ground arc seen edge on: the
  // segment it covers).
  for (const Slot& sl : s.planeView().seen(m).slots) {
    const std::optional<Guide> g = s.drawnSlot(sl.id);
    if (!g || s.bodyHidden(sl.body)) continue;
    const double d = g->distance(s.poseOf(sl.body).inverse(world));
    if (d < bestSlot) {
      bestSlot = d;
      pick.slot = sl.id;
    }
  }
  // Blocks and slot pins under the cursor are their joints.
  if (!pick.joint)
    for (const Joint& j : m.joints)
      if (kindOf(j).reads(FieldType::Slot) && m.point(j.a) && !s.bodyHidden(m.point(j.a)->body) &&
          (s.worldOf(j.a) - world).norm() < CanvasStyle::blockLength / 2 * px) {
        pick.joint = j.id;
        break;
      }
  pickCoupling(s, world, px, pick);
  // The top body whose drawn shape holds the point. Bounding rectangles first, shapes of the
  // bodies only: a Kennedy line's shape is its stroked outline, which cost a mouse move with the
  // instant centres shown a millisecond or more.
  const QPointF q(world.x(), world.y());
  for (QGraphicsItem* item : s.items(q, Qt::IntersectsItemBoundingRect, Qt::DescendingOrder)) {
    // A body, or a joint's symbol that draws one (a slider's block).
    auto* b = dynamic_cast<BodyItem*>(item);
    auto* j = b ? nullptr : dynamic_cast<JointItem*>(item);
    const BodyId drawn = j ? j->drawnBody() : BodyId{};
    if ((!b && !drawn) || !item->isVisible() || !item->isEnabled() ||
        !item->contains(item->mapFromScene(q)))
      continue;
    pick.body = b ? b->id() : drawn;
    pick.onBlock = !b;
    break;
  }
  if (!pick.body && pick.point) pick.body = m.point(pick.point)->body;
  if (!pick.body && pick.slot) pick.body = m.slot(pick.slot)->body;
  if (!pick.body && m.ground()) {
    pick.body = m.ground()->id;
  }
  const Body* b = m.body(pick.body);
  pick.onGround = b && b->ground;
  return pick;
}

Snap snapAt(const CanvasScene& s, const Pick& pick, const Vec2& world, double px, double gridStep) {
  Snap snap;
  const Mechanism& m = s.shownMechanism();
  if (pick.point) {
    snap.kind = Snap::Kind::Point;
    snap.at = pick.pointAt;
    snap.point = pick.point;
    snap.label = QString::fromStdString(m.pointLabel(pick.point));
    return snap;
  }
  // Onto a slot's line where the plane shown holds it (not a ground arc seen edge on: its
  // points are off that plane).
  const Slot* sl = pick.slot ? s.planeView().seen(m).slot(pick.slot) : nullptr;
  if (sl && guideOf(*sl)) {
    const Transform T = s.poseOf(sl->body);
    snap.kind = Snap::Kind::Slot;
    snap.at = T * guideOf(*sl)->project(T.inverse(world));
    snap.slot = pick.slot;
    snap.label = QStringLiteral("on slot %1").arg(QString::fromStdString(m.slotLabel(pick.slot)));
    return snap;
  }
  if (gridStep > 0) {
    snap.kind = Snap::Kind::Grid;
    snap.at = Vec2(std::round(world.x() / gridStep) * gridStep,
                   std::round(world.y() / gridStep) * gridStep);
    // Only when the grid node is near: a coarse grid should not drag the cursor far.
    if ((snap.at - world).norm() <= kPickPixels * px) {
      snap.label = QStringLiteral("grid %1, %2").arg(snap.at.x()).arg(snap.at.y());
      return snap;
    }
  }
  snap.kind = Snap::Kind::Free;
  snap.at = world;
  return snap;
}

QString describePick(const Mechanism& m, const Pick& p) {
  if (p.point) return QString::fromStdString(m.pointLabel(p.point));
  if (p.joint) return QString::fromStdString(jointName(m, p.joint));
  if (p.coupling && p.onCouplingLines) return QString::fromStdString(jointName(m, p.coupling));
  if (p.slot) return QStringLiteral("slot %1").arg(QString::fromStdString(m.slotLabel(p.slot)));
  if (const Body* b = m.body(p.body))
    return b->ground ? QStringLiteral("the ground")
                     : QStringLiteral("body %1").arg(QString::fromStdString(b->name));
  return QString();
}

}  // namespace linkage::ui
