#include "tools/select_tool.h"

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/commands.h"
#include "linkage/edits.h"
#include "tools/selection.h"
#include "tools/tool_overlay.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

namespace {
[[maybe_unused]] const bool registered = registerTool(
    "select",
    [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new SelectTool(ctx); });
}  // namespace

namespace {
constexpr int kDragStartPixels = 4;
}

SelectTool::SelectTool(ToolContext* ctx) : Tool(ctx) {
  frame_.setSingleShot(true);
  frame_.setInterval(0);
  connect(&frame_, &QTimer::timeout, this, &SelectTool::solvePending);
}

QString SelectTool::hint() const {
  switch (mode_) {
    case Mode::Turn:
      return tr("Dragging: the crank turns so that the point follows the mouse");
    case Mode::Reshape:
      return tr("Changing the design: the point moves in its link; release to keep, Esc to undo");
    default:
      return tr(
          "Select: click a point, joint, slot, block or link (again: what is under it; Shift "
          "adds); drag a point to move the mechanism, Ctrl+drag to change the design");
  }
}

void SelectTool::deactivate() {
  if (dragging()) endDrag(true);
  mode_ = Mode::Idle;
  ctx().overlay->setBand(std::nullopt);
}

void SelectTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  pressed_ = e;
  mode_ = Mode::Pressed;
}

void SelectTool::move(const CanvasMouse& e) {
  if (mode_ == Mode::Idle) return;
  if (mode_ == Mode::Pressed) {
    if ((e.viewPos - pressed_.viewPos).manhattanLength() < kDragStartPixels) return;
    const Pick& p = pressed_.pick;
    if (p.point || p.joint || (p.body && !p.onGround))
      beginDrag(e);
    else
      mode_ = Mode::Band;
  }
  if (mode_ == Mode::Band) {
    ctx().overlay->setBand(QRectF(toQt(pressed_.world), toQt(e.world)).normalized());
    return;
  }
  if (!dragging()) return;
  target_ = e.world;
  if (mode_ == Mode::Reshape && gridStep_ > 0 && !(e.modifiers & Qt::AltModifier))
    target_ = Vec2(std::round(target_.x() / gridStep_) * gridStep_,
                   std::round(target_.y() / gridStep_) * gridStep_);
  pending_ = true;
  if (!frame_.isActive()) frame_.start();
}

void SelectTool::release(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  switch (mode_) {
    case Mode::Pressed:
      select(pressed_.pick, e.modifiers & Qt::ShiftModifier);
      break;
    case Mode::Band:
      selectBand(QRectF(toQt(pressed_.world), toQt(e.world)).normalized(),
                 e.modifiers & Qt::ShiftModifier);
      ctx().overlay->setBand(std::nullopt);
      break;
    case Mode::Turn:
    case Mode::Reshape:
      solvePending();
      endDrag(true);
      break;
    case Mode::Idle:
      break;
  }
  mode_ = Mode::Idle;
  emit hintChanged();
}

bool SelectTool::key(QKeyEvent* e) {
  if (e->key() != Qt::Key_Escape) return false;
  if (dragging()) {
    endDrag(false);
    mode_ = Mode::Idle;
    emit hintChanged();
    return true;
  }
  ctx().selection->clear();
  return true;
}

void SelectTool::select(const Pick& p, bool toggle) {
  Selection& s = *ctx().selection;
  // What is under the cursor, the most specific first: a joint, a point, a slider block, a
  // gear's or belt's drawn lines, a slot, a link, the gear or belt whose pitch circle holds the
  // cursor. A click again on what is selected takes the next: things drawn on top of one
  // another (a block on its pin and its slot, a pulley's pivot and its belt) are each reached.
  struct Candidate {
    PointId point;
    JointId joint;
    SlotId slot;
    BodyId body;
  };
  std::vector<Candidate> under;
  if (p.joint) under.push_back({{}, p.joint, {}, {}});
  if (p.point) under.push_back({p.point, {}, {}, {}});
  if (p.body && p.onBlock) under.push_back({{}, {}, {}, p.body});
  if (p.coupling && p.onCouplingLines) under.push_back({{}, p.coupling, {}, {}});
  if (p.slot) under.push_back({{}, {}, p.slot, {}});
  if (p.body && !p.onGround && !p.onBlock) under.push_back({{}, {}, {}, p.body});
  if (p.coupling && !p.onCouplingLines) under.push_back({{}, p.coupling, {}, {}});
  size_t next = 0;
  if (!toggle && s.size() == 1)
    for (size_t i = 0; i < under.size(); ++i) {
      const Candidate& c = under[i];
      if ((c.joint && s.contains(c.joint)) || (c.point && s.contains(c.point)) ||
          (c.slot && s.contains(c.slot)) || (c.body && s.contains(c.body)))
        next = (i + 1) % under.size();
    }
  if (!toggle) {
    const bool had = !s.empty();
    s.blockSignals(true);
    s.clear();
    s.blockSignals(false);
    if (had && under.empty()) emit s.changed();
  }
  if (under.empty()) {
    if (!toggle) emit s.changed();
    return;
  }
  const Candidate& c = under[next];
  if (c.joint)
    s.add(c.joint, toggle);
  else if (c.point)
    s.add(c.point, toggle);
  else if (c.slot)
    s.add(c.slot, toggle);
  else
    s.add(c.body, toggle);
}

void SelectTool::selectBand(const QRectF& r, bool add) {
  Selection& s = *ctx().selection;
  const CanvasScene& scene = *ctx().scene;
  const Mechanism& m = scene.shownMechanism();
  s.blockSignals(true);
  if (!add) s.clear();
  auto inside = [&](PointId p) { return r.contains(toQt(scene.worldOf(p))); };
  for (const Joint& j : m.joints)
    if (inside(j.a) && (!j.b || inside(j.b)) && !s.contains(j.id)) s.add(j.id);
  for (const Point& p : m.points)
    if (inside(p.id) && !s.contains(p.id)) s.add(p.id);
  for (const Body& b : m.bodies) {
    if (b.ground) continue;
    bool all = false;
    for (const Point& p : m.points)
      if (p.body == b.id) {
        all = inside(p.id);
        if (!all) break;
      }
    if (all && !s.contains(b.id)) s.add(b.id);
  }
  s.blockSignals(false);
  emit s.changed();
}

void SelectTool::beginDrag(const CanvasMouse& e) {
  const Pick& p = pressed_.pick;
  const Mechanism& m = ctx().scene->shownMechanism();
  dragPoint_ = p.point;
  if (!dragPoint_ && p.joint) dragPoint_ = m.joint(p.joint)->a;
  if (!dragPoint_ && p.body) {
    // A link grabbed away from its points: its point nearest the cursor.
    double best = INFINITY;
    for (const Point& q : m.points)
      if (q.body == p.body && (ctx().scene->worldOf(q.id) - pressed_.world).norm() < best) {
        best = (ctx().scene->worldOf(q.id) - pressed_.world).norm();
        dragPoint_ = q.id;
      }
  }
  if (!dragPoint_) {
    mode_ = Mode::Band;
    return;
  }
  before_ = ctx().doc->state();
  gridStep_ = ctx().view->gridVisible() ? ctx().view->gridStep() : 0;
  if (e.modifiers & Qt::ControlModifier) {
    mode_ = Mode::Reshape;
    moving_.clear();
    for (PointId q : pinnedTogether(ctx().doc->design(), dragPoint_))
      if (const Point* pt = ctx().doc->design().point(q))
        moving_.emplace_back(q, ctx().scene->poseOf(pt->body));
  } else {
    mode_ = Mode::Turn;
  }
  emit hintChanged();
}

void SelectTool::solvePending() {
  if (!pending_ || !dragging()) return;
  pending_ = false;
  Document* doc = ctx().doc;
  if (mode_ == Mode::Turn) {
    // The solver takes the target in the plane class's frame (linkage/plane_view.h).
    const Kinematics::DragResult r =
        doc->dragTo(dragPoint_, ctx().scene->planeView().toClass(target_));
    if (!r.status.ok()) say(QString::fromStdString(r.status.message), !r.atLimit);
    return;
  }
  // Reshape: the points move in their bodies' frames as those were when the drag began.
  Mechanism m = before_->design;
  const PlaneView& view = ctx().scene->planeView();
  for (const auto& [q, T] : moving_)
    if (Point* pt = m.point(q)) {
      const Body* b = m.body(pt->body);
      if (b && b->ground)
        view.placeGround(*pt, target_);  // where the shown plane sees it, its depth kept
      else
        pt->pos = T.inverse(target_);
    }
  doc->setDesign(m);
  if (!doc->solveStatus().ok()) say(QString::fromStdString(doc->solveStatus().message), true);
}

void SelectTool::endDrag(bool keep) {
  frame_.stop();
  pending_ = false;
  Document* doc = ctx().doc;
  if (mode_ == Mode::Reshape && before_) {
    if (keep) {
      // The label first: the design is moved into the call (in an order of evaluation the
      // compiler chooses, which named a point of a moved-from design "?").
      const QString text =
          tr("Move %1").arg(QString::fromStdString(doc->design().pointLabel(dragPoint_)));
      commitEdit(doc, text, doc->design(), *before_);
    } else {
      doc->restore(*before_);
    }
  } else if (mode_ == Mode::Turn && !keep && before_) {
    doc->setCrankDeg(before_->kinematics.crankDeg());
  }
  before_.reset();
  moving_.clear();
}

}  // namespace linkage::ui
