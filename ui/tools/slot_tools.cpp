#include "tools/slot_tools.h"

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "tools/tool_overlay.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

namespace {
[[maybe_unused]] const bool slotTool = registerTool(
    "slot", [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new SlotTool(ctx); });
// The slot joints' tool, for the kind whose tool it is (ui/elements/: a slider block, a pin in
// a slot).
[[maybe_unused]] const bool slotJoint =
    registerTool("slotJoint", [](ToolContext* ctx, std::optional<JointType> kind) -> Tool* {
      return kind ? new SlotJointTool(ctx, *kind) : nullptr;
    });
}  // namespace

QString SlotTool::hint() const {
  if (!start_)
    return tr(
        "Slot: click where it starts, on the link it is cut in (on empty canvas: in the "
        "ground)");
  if (end_) return tr("Arc slot: click a point it passes through; Esc cancels");
  return tr("Slot: click where it ends (Shift: an arc, bent by a third click); Esc cancels");
}

void SlotTool::deactivate() {
  cancel();
}

void SlotTool::cancel() {
  start_.reset();
  end_.reset();
  body_ = {};
  dragged_ = false;
  ctx().overlay->clearPreview();
  emit hintChanged();
}

void SlotTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  if (end_) {
    finish(*end_, e.snap.at);
    return;
  }
  if (start_) {
    end(e.snap.at, e.modifiers & Qt::ShiftModifier);
    return;
  }
  start_ = e.snap.at;
  const Mechanism& shown = ctx().scene->shownMechanism();
  body_ = e.pick.body ? e.pick.body : (shown.ground() ? shown.ground()->id : BodyId{});
  pressAt_ = e.viewPos;
  dragged_ = false;
  ctx().overlay->setPath({*start_}, e.snap.at);
  emit hintChanged();
}

void SlotTool::startAt(const Vec2& at, BodyId body) {
  start_ = at;
  body_ = body;
  dragged_ = false;
  ctx().overlay->setPath({at}, at);
  emit hintChanged();
}

void SlotTool::move(const CanvasMouse& e) {
  if (!start_) return;
  preview(e.snap.at);
  if (!end_ && (e.buttons & Qt::LeftButton) && (e.viewPos - pressAt_).manhattanLength() > 6)
    dragged_ = true;
}

void SlotTool::release(const CanvasMouse& e) {
  // A press and drag draws the slot (or the arc's chord) at once.
  if (start_ && !end_ && dragged_ && e.button == Qt::LeftButton)
    end(e.snap.at, e.modifiers & Qt::ShiftModifier);
}

void SlotTool::end(const Vec2& at, bool arc) {
  if (!arc) {
    finish(at);
    return;
  }
  if ((at - *start_).norm() < 1e-9) return;
  end_ = at;
  dragged_ = false;
  emit hintChanged();
}

void SlotTool::preview(const Vec2& cursor) {
  if (!end_) {
    ctx().overlay->setPath({*start_}, cursor);
    return;
  }
  // The arc from the start through the cursor to the end, as it would be made.
  const std::optional<Guide> g = guideOf(Slot{{}, {}, "", *start_, *end_, cursor, {}});
  if (!g) {
    ctx().overlay->setPath({*start_, *end_}, std::nullopt);
    return;
  }
  std::vector<Vec2> arc;
  const int n = 64;
  for (int i = 0; i <= n; ++i) arc.push_back(g->at(g->length() * i / n));
  ctx().overlay->setPath(arc, std::nullopt);
}

bool SlotTool::key(QKeyEvent* e) {
  if (e->key() == Qt::Key_Escape && start_) {
    cancel();
    return true;
  }
  return false;
}

void SlotTool::finish(const Vec2& end, const std::optional<Vec2>& mid) {
  if (!start_ || (end - *start_).norm() < 1e-9) return;
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  if (!m.contains(body_)) {
    cancel();
    return;
  }
  // The ends in the body's own drawing: where it is drawn now, mapped back.
  const Transform T = ctx().scene->poseOf(body_);
  const SlotId s =
      mid ? addBodyArcSlot(m, body_, T.inverse(*start_), T.inverse(*mid), T.inverse(end))
          : addBodySlot(m, body_, T.inverse(*start_), T.inverse(end));
  const bool ground = m.body(body_)->ground;
  cancel();
  if (!s) {
    if (mid) say(tr("No arc: the three points are on one line"), true);
    return;
  }
  // The ground's slot drawn on a plane of a machine in space: its ends in the world.
  if (ground) ctx().scene->planeView().placeGround(*m.slot(s));
  const QString what = QString::fromStdString(m.slotLabel(s));
  commitEdit(doc, tr("Add slot %1").arg(what), std::move(m));
  say(tr("Added slot %1").arg(what));
}

QString SlotJointTool::hint() const {
  const bool block = elementKind(type_).role == Role::Prismatic;
  if (!point_)
    return block ? tr("Block: click the point where the slider block goes")
                 : tr("Pin in slot: click the point that runs in a slot");
  return block ? tr("Block: click the slot the block slides in; Esc cancels")
               : tr("Pin in slot: click the slot the pin runs in; Esc cancels");
}

void SlotJointTool::deactivate() {
  point_ = {};
  emit hintChanged();
}

void SlotJointTool::startAt(PointId p) {
  point_ = p;
  emit hintChanged();
}

bool SlotJointTool::key(QKeyEvent* e) {
  if (e->key() == Qt::Key_Escape && point_) {
    deactivate();
    return true;
  }
  return false;
}

void SlotJointTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  if (!point_) {
    if (!e.pick.point) {
      say(tr("Click a point first"), true);
      return;
    }
    point_ = e.pick.point;
    emit hintChanged();
    return;
  }
  if (!e.pick.slot) {
    say(tr("Click a slot"), true);
    return;
  }
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  std::string why;
  QString text;
  if (elementKind(type_).role == Role::Prismatic) {
    const BodyId b = addBlock(m, point_, e.pick.slot, ctx().scene->worldOf(point_), &why);
    if (b) text = tr("Add block %1").arg(QString::fromStdString(m.body(b)->name));
  } else {
    const JointId j = addPinInSlot(m, point_, e.pick.slot, &why);
    if (j) text = tr("Pin %1 in slot").arg(QString::fromStdString(m.pointLabel(point_)));
  }
  point_ = {};
  emit hintChanged();
  if (text.isEmpty()) {
    say(QString::fromStdString(why), true);
    return;
  }
  commitEdit(doc, text, std::move(m));
  say(text);
}

}  // namespace linkage::ui
