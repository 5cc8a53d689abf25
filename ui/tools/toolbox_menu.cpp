// The right-click menus: what can be done with the point, joint, link or place under the
// cursor, as PMKS+ users know them.
#include <QMenu>

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "document/edits.h"
#include "tools/link_tool.h"
#include "tools/slot_tools.h"
#include "tools/toolbox.h"

namespace linkage::ui {

QMenu* Toolbox::contextMenu(const CanvasMouse& e, QWidget* parent) {
  Document* doc = ctx_.doc;
  const Mechanism& m = doc->design();
  const CanvasScene& scene = *ctx_.scene;
  auto* menu = new QMenu(parent);
  auto edit = [this, doc](const QString& text, auto change) {
    Mechanism next = doc->design();
    std::string why;
    if (!change(next, why)) {
      ctx_.message(QString::fromStdString(why), true);
      return;
    }
    commitEdit(doc, text, std::move(next));
  };
  const Pick& p = e.pick;
  const Point* point = m.point(p.point);
  const Joint* joint = m.joint(p.joint);
  if (point) {
    const PointId id = point->id;
    const Vec2 at = scene.worldOf(id);
    const QString label = QString::fromStdString(m.pointLabel(id));
    menu->addSection(label);
    menu->addAction(tr("Attach a Link Here"), this, [this, id, at] {
      setTool(QStringLiteral("link"));
      static_cast<LinkTool*>(current_)->startAt(LinkVertex{at, id});
    });
    if (!m.body(point->body)->ground)
      menu->addAction(tr("Pin to the Ground Here"), this, [edit, id, at, label] {
        edit(tr("Pin to ground at %1").arg(label),
             [&](Mechanism& n, std::string&) { return bool(addGroundPoint(n, at, id)); });
      });
    menu->addAction(tr("Slider Block in a Slot Here..."), this, [this, id] {
      setTool(QStringLiteral("block"));
      static_cast<SlotJointTool*>(current_)->startAt(id);
    });
    menu->addAction(tr("Pin in a Slot Here..."), this, [this, id] {
      setTool(QStringLiteral("pinInSlot"));
      static_cast<SlotJointTool*>(current_)->startAt(id);
    });
    QAction* out = menu->addAction(tr("Output Point"), this, [doc, id, label] {
      Mechanism n = doc->design();
      toggleOutput(n, id);
      editDesign(doc, tr("Output %1").arg(label), std::move(n));
    });
    out->setCheckable(true);
    out->setChecked(std::find(m.outputs.begin(), m.outputs.end(), id) != m.outputs.end());
  }
  if (joint) {
    const JointId id = joint->id;
    const QString label = QString::fromStdString(m.jointLabel(id));
    menu->addSection(label);
    if (joint->type == JointType::Pin) {
      QAction* drive = menu->addAction(tr("Make It the Driver"), this, [edit, id, label] {
        edit(tr("Driver at %1").arg(label),
             [&](Mechanism& n, std::string& why) { return setDriver(n, id, &why); });
      });
      drive->setEnabled(!(m.driver && m.driver->joint == id));
    } else {
      QMenu* type = menu->addMenu(tr("Change Type"));
      for (JointType t : {JointType::Slider, JointType::PinInSlot}) {
        QAction* a = type->addAction(
            t == JointType::Slider ? tr("Slider (block keeps its angle)")
                                   : tr("Pin in slot (turns freely)"),
            this, [edit, id, t, label] {
              edit(tr("Change type of %1").arg(label),
                   [&](Mechanism& n, std::string& why) { return changeJointType(n, id, t, &why); });
            });
        a->setCheckable(true);
        a->setChecked(joint->type == t);
      }
    }
    menu->addAction(tr("Delete Joint"), this, [doc, id, label] {
      Mechanism n = doc->design();
      n.remove(id);
      editDesign(doc, tr("Delete %1").arg(label), std::move(n));
    });
  }
  const Body* body = m.body(p.body);
  if (body && !body->ground && !point) {
    const BodyId id = body->id;
    const QString name = QString::fromStdString(body->name);
    const Vec2 sketch = scene.poseOf(id).inverse(e.snap.at);
    menu->addSection(tr("Link %1").arg(name));
    menu->addAction(tr("Add a Point Here"), this, [edit, id, sketch, name] {
      edit(tr("Add a point to %1").arg(name),
           [&](Mechanism& n, std::string&) { return bool(addBodyPoint(n, id, sketch)); });
    });
    menu->addAction(tr("Add a Slot From Here"), this, [this, id, at = e.snap.at] {
      setTool(QStringLiteral("slot"));
      static_cast<SlotTool*>(current_)->startAt(at, id);
    });
    QAction* flip = menu->addAction(tr("Flip Assembly"), this, [this, doc, id] {
      QString why;
      if (!flipAssembly(doc, id, &why)) ctx_.message(tr("Cannot flip: %1").arg(why), true);
    });
    const std::vector<BodyId> ok =
        doc->solved() ? doc->kinematics().flippableBodies() : std::vector<BodyId>{};
    flip->setEnabled(std::find(ok.begin(), ok.end(), id) != ok.end());
    menu->addAction(tr("Delete Link"), this, [doc, id, name] {
      Mechanism n = doc->design();
      n.remove(id);
      editDesign(doc, tr("Delete %1").arg(name), std::move(n));
    });
  }
  if (!point && !joint && (!body || body->ground)) {
    menu->addAction(tr("Add a Ground Point Here"), this, [edit, at = e.snap.at] {
      edit(tr("Add ground point"),
           [&](Mechanism& n, std::string&) { return bool(addGroundPoint(n, at)); });
    });
  }
  return menu;
}

}  // namespace linkage::ui
