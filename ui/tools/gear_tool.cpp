#include "tools/gear_tool.h"

#include <QKeyEvent>

#include "document/commands.h"
#include "document/document.h"
#include "linkage/edits.h"
#include "tools/selection.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

namespace {
[[maybe_unused]] const bool registered = registerTool(
    "gear", [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new GearTool(ctx); });
}  // namespace

QString GearTool::hint() const {
  if (!first_) return tr("Gear or belt: click a body that turns about a pivot");
  return tr(
      "Gear or belt: click the body it drives (pivoted on the same body); Shift: a belt; "
      "Esc cancels");
}

void GearTool::deactivate() {
  first_ = {};
  emit hintChanged();
}

void GearTool::startAt(BodyId first) {
  first_ = first;
  emit hintChanged();
}

bool GearTool::key(QKeyEvent* e) {
  if (e->key() == Qt::Key_Escape && first_) {
    deactivate();
    return true;
  }
  return false;
}

void GearTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  const Mechanism& design = ctx().doc->design();
  const BodyId b = e.pick.body;
  const Body* body = design.body(b);
  if (!body || body->ground || e.pick.onGround) {
    say(tr("Click a moving body"), true);
    return;
  }
  if (pivotsOf(design, b).empty()) {
    say(tr("%1 turns about no pivot: pin it first").arg(QString::fromStdString(body->name)), true);
    return;
  }
  if (!first_) {
    startAt(b);
    return;
  }
  Mechanism m = design;
  std::string why;
  const bool belt = e.modifiers & Qt::ShiftModifier;
  const JointId j = addCoupling(m, first_, b, belt ? 1.0 : -1.0, &why);
  first_ = {};
  emit hintChanged();
  if (!j) {
    say(QString::fromStdString(why), true);
    return;
  }
  const QString text = (belt ? tr("Belt %1 - %2") : tr("Gears %1 - %2"))
                           .arg(QString::fromStdString(m.pointLabel(m.joint(j)->a)),
                                QString::fromStdString(m.pointLabel(m.joint(j)->b)));
  commitEdit(ctx().doc, text, std::move(m));
  ctx().selection->clear();
  ctx().selection->add(j);
  say(text);
}

}  // namespace linkage::ui
