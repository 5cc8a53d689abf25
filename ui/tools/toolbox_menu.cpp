// The right-click menus: what can be done with the point, joint, link or place under the
// cursor, as PMKS+ users know them.
#include <QMenu>

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "elements/element_ui.h"
#include "linkage/edits.h"
#include "linkage/elements.h"
#include "tools/selection.h"
#include "tools/toolbox.h"

namespace linkage::ui {

// A point's entries: attach, pin to the ground, the kinds' "... Here", output.
void Toolbox::pointMenu(QMenu& menu, const Point& point, const Vec2& at) {
  Document* doc = ctx_.doc;
  const Mechanism& m = doc->design();
  const PointId id = point.id;
  const QString label = QString::fromStdString(m.pointLabel(id));
  menu.addSection(label);
  menu.addAction(tr("Attach a Link Here"), this, [this, id, at] {
    startTool(QStringLiteral("link"), ToolStart{.point = id, .at = at});
  });
  if (!m.body(point.body)->ground)
    menu.addAction(tr("Pin to the Ground Here"), this, [this, id, at, label] {
      const std::string plane = ctx_.scene->shownPlane();
      editWith(tr("Pin to ground at %1").arg(label),
               [&](Mechanism& n, std::string&) { return bool(addGroundPoint(n, at, id, plane)); });
    });
  for (const ElementUi* k : elementUis())
    if (k->pointMenu) k->pointMenu(*this, menu, id);
  if (!m.body(point.body)->ground)
    menu.addAction(tr("Add a &Load Here"), this, [this, id, label] {
      // 10 N downwards to start with: its numbers are edited in the Properties.
      editWith(tr("Add a load at %1").arg(label), [&](Mechanism& n, std::string&) {
        n.addLoad(Load{id, {}, Vec2(0, -10), 0, std::nullopt, std::nullopt, "", {}});
        return true;
      });
      ctx_.selection->clear();
      ctx_.selection->add(id);
    });
  QAction* out = menu.addAction(tr("Output Point"), this, [doc, id, label] {
    Mechanism n = doc->design();
    toggleOutput(n, id);
    editDesign(doc, tr("Output %1").arg(label), std::move(n));
  });
  out->setCheckable(true);
  out->setChecked(std::find(m.outputs.begin(), m.outputs.end(), id) != m.outputs.end());
}

// A moving body's entries: a point or a slot here, the kinds' entries, flip, delete.
void Toolbox::bodyMenu(QMenu& menu, const Body& body, const Vec2& at) {
  Document* doc = ctx_.doc;
  const BodyId id = body.id;
  const QString name = QString::fromStdString(body.name);
  const Vec2 sketch = ctx_.scene->poseOf(id).inverse(at);
  menu.addSection(tr("Link %1").arg(name));
  menu.addAction(tr("Add a Point Here"), this, [this, id, sketch, name] {
    editWith(tr("Add a point to %1").arg(name),
             [&](Mechanism& n, std::string&) { return bool(addBodyPoint(n, id, sketch)); });
  });
  menu.addAction(tr("Add a Slot From Here"), this, [this, id, at] {
    startTool(QStringLiteral("slot"), ToolStart{.body = id, .at = at});
  });
  for (const ElementUi* k : elementUis())
    if (k->bodyMenu) k->bodyMenu(*this, menu, id);
  menu.addAction(tr("Add a &Torque"), this, [this, id, name] {
    editWith(tr("Add a torque on %1").arg(name), [&](Mechanism& n, std::string&) {
      n.addLoad(Load{{}, id, Vec2::Zero(), 0.1, std::nullopt, std::nullopt, "", {}});
      return true;
    });
    ctx_.selection->clear();
    ctx_.selection->add(id);
  });
  QAction* flip = menu.addAction(tr("Flip Assembly"), this, [this, doc, id] {
    QString why;
    if (!flipAssembly(doc, id, &why)) ctx_.message(tr("Cannot flip: %1").arg(why), true);
  });
  const std::vector<BodyId> ok =
      doc->solved() ? doc->kinematics().flippableBodies() : std::vector<BodyId>{};
  flip->setEnabled(std::find(ok.begin(), ok.end(), id) != ok.end());
  menu.addAction(tr("Delete Link"), this, [doc, id, name] {
    Mechanism n = doc->design();
    n.remove(id);
    editDesign(doc, tr("Delete %1").arg(name), std::move(n));
  });
}

// A joint's entries, under its name: its kind's, then delete.
void Toolbox::jointMenu(QMenu& menu, const Joint& joint) {
  Document* doc = ctx_.doc;
  const JointId id = joint.id;
  const QString label = QString::fromStdString(jointName(doc->design(), id));
  menu.addSection(label);
  elementUi(joint.type).jointMenu(*this, menu, joint);
  menu.addAction(tr("Delete Joint"), this, [doc, id, label] {
    Mechanism n = doc->design();
    n.remove(id);
    editDesign(doc, tr("Delete %1").arg(label), std::move(n));
  });
}

void Toolbox::editField(JointId joint, const QString& label) {
  ctx_.selection->blockSignals(true);
  ctx_.selection->clear();
  ctx_.selection->blockSignals(false);
  ctx_.selection->add(joint);
  emit fieldWanted(label);
}

QMenu* Toolbox::contextMenu(const CanvasMouse& e, QWidget* parent) {
  Document* doc = ctx_.doc;
  const Mechanism& m = doc->design();
  auto* menu = new QMenu(parent);
  const Pick& p = e.pick;
  const Point* point = m.point(p.point);
  const Joint* joint = m.joint(p.joint);
  if (point) pointMenu(*menu, *point, ctx_.scene->worldOf(point->id));
  if (joint) jointMenu(*menu, *joint);
  // A gear or belt under the cursor (its lines, or inside a pitch circle).
  if (const Joint* coupling = m.joint(p.coupling); coupling && coupling != joint)
    jointMenu(*menu, *coupling);
  const Body* body = m.body(p.body);
  if (body && !body->ground && !point) bodyMenu(*menu, *body, e.snap.at);
  if (!point && !joint && (!body || body->ground)) {
    menu->addAction(tr("Add a Ground Point Here"), this, [this, at = e.snap.at] {
      const std::string plane = ctx_.scene->shownPlane();
      editWith(tr("Add ground point"),
               [&](Mechanism& n, std::string&) { return bool(addGroundPoint(n, at, {}, plane)); });
    });
  }
  return menu;
}

}  // namespace linkage::ui
