#include "tools/click_tools.h"

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "tools/tool_registry.h"

namespace linkage::ui {

namespace {
[[maybe_unused]] const bool ground = registerTool(
    "ground",
    [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new GroundTool(ctx); });
[[maybe_unused]] const bool driver = registerTool(
    "driver",
    [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new DriverTool(ctx); });
[[maybe_unused]] const bool output = registerTool(
    "output",
    [](ToolContext* ctx, std::optional<JointType>) -> Tool* { return new OutputTool(ctx); });
}  // namespace

QString GroundTool::hint() const {
  return tr(
      "Ground: click a point to pin its link to the ground there, or empty canvas for a "
      "ground point");
}

void GroundTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  const Body* g = m.ground();
  if (!g) {
    say(tr("The mechanism has no ground"), true);
    return;
  }
  if (e.snap.kind == Snap::Kind::Point) {
    const Point* p = m.point(e.snap.point);
    if (m.body(p->body)->ground) {
      say(tr("%1 is on the ground already").arg(QString::fromStdString(m.pointLabel(p->id))), true);
      return;
    }
    const PointId gp = addGroundPoint(m, e.snap.at, p->id, ctx().scene->shownPlane());
    const QString what = QString::fromStdString(m.pointLabel(gp));
    commitEdit(doc, tr("Pin to ground at %1").arg(what), std::move(m));
    say(tr("Pinned to the ground at %1").arg(what));
    return;
  }
  const PointId gp = addGroundPoint(m, e.snap.at, {}, ctx().scene->shownPlane());
  const QString what = QString::fromStdString(m.pointLabel(gp));
  commitEdit(doc, tr("Add ground point %1").arg(what), std::move(m));
  say(tr("Added ground point %1").arg(what));
}

QString DriverTool::hint() const {
  return tr("Driver: click a pin to make it the crank (rpm, direction, start in Properties)");
}

void DriverTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  const Joint* j = m.joint(e.pick.joint);
  if (!j || kindOf(*j).role != Role::Revolute) {
    say(tr("Click a pin: the driver is a pin joint"), true);
    return;
  }
  std::string why;
  const JointId id = j->id;
  if (!setDriver(m, id, &why)) {
    say(QString::fromStdString(why), true);
    return;
  }
  const QString what = QString::fromStdString(jointName(m, id));
  commitEdit(doc, tr("Driver at %1").arg(what), std::move(m));
  // Only a design the solver takes is driven by it; else the red line above says why not.
  if (doc->solved())
    say(tr("%1 drives the mechanism").arg(what));
  else
    say(tr("%1 is the driver, but the design is not solved").arg(what), true);
}

QString OutputTool::hint() const {
  return tr("Output: click a point to trace, plot and export it (again to stop)");
}

void OutputTool::press(const CanvasMouse& e) {
  if (e.button != Qt::LeftButton) return;
  if (!e.pick.point) {
    say(tr("Click a point"), true);
    return;
  }
  Document* doc = ctx().doc;
  Mechanism m = doc->design();
  const bool was = std::find(m.outputs.begin(), m.outputs.end(), e.pick.point) != m.outputs.end();
  toggleOutput(m, e.pick.point);
  const QString what = QString::fromStdString(m.pointLabel(e.pick.point));
  editDesign(doc, was ? tr("Not an output: %1").arg(what) : tr("Output %1").arg(what),
             std::move(m));
  say(was ? tr("%1 is no longer an output").arg(what) : tr("%1 is an output").arg(what));
}

}  // namespace linkage::ui
