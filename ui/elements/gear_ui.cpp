// The gear in the editor: pitch circles (a belt: pulleys and the belt), the Gear tool (E: two
// pivoted bodies; Shift for a belt), its type and ratio (edited), carrier and centres in the
// panel, "Gears in Mesh" / "Belt" / "Edit Ratio..." on its menu, and "Couple to..." on a
// pivoted body's menu.
#include <QMenu>

#include "document/document.h"
#include "elements/element_ui.h"
#include "elements/gear_item.h"
#include "elements/menu_actions.h"
#include "forms/form.h"
#include "linkage/edits.h"
#include "linkage/gear.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing& d) {
  return new GearItem(ctx, s, ctx->style.body(bodyNumber(d, s.bodies[0])),
                      ctx->style.body(bodyNumber(d, s.bodies[1])));
}

void form(Form& panel, JointId id) {
  Document* doc = panel.document();
  auto joint = [doc, id] { return *doc->design().joint(id); };
  // Gears in mesh turn opposite ways (a negative ratio), a belt or chain the same way.
  panel.addChoice(
      Form::tr("Type"),
      {Form::tr("gears in mesh (turn opposite ways)"),
       Form::tr("belt or chain (turn the same way)")},
      [joint] { return gearRatio(joint()) < 0 ? 0 : 1; },
      [&panel, id](int i) {
        panel.change(
            Form::tr("Gear type"),
            [&](Mechanism& m, QString*) {
              Joint& j = *m.joint(id);
              if ((gearRatio(j) > 0) == (i == 1)) return false;  // the type it has: no edit
              setGearRatio(j, -gearRatio(j));
              return true;
            },
            nullptr);
      });
  panel.addNumber(
      Form::tr("Ratio"), [joint] { return gearRatio(joint()); },
      [&panel, id](double v, QString* why) {
        return panel.change(
            Form::tr("Gear ratio"),
            [&](Mechanism& m, QString* w) {
              setGearRatio(*m.joint(id), v);
              const std::string problem = checkJoints(m);
              *w = QString::fromStdString(problem);
              return problem.empty();
            },
            why);
      },
      QString());
  panel.addInfo(Form::tr("Carrier"), [doc, joint] {
    const Body* c = doc->design().body(joint().carrier);
    return c ? QString::fromStdString(c->name) : Form::tr("the ground");
  });
  panel.addInfo(Form::tr("Centres"), [doc, joint] {
    const Mechanism& m = doc->design();
    return QStringLiteral("%1, %2").arg(QString::fromStdString(m.pointLabel(joint().a)),
                                        QString::fromStdString(m.pointLabel(joint().b)));
  });
}

void jointMenu(MenuActions& box, QMenu& menu, const Joint& j) {
  const JointId id = j.id;
  const QString label = QString::fromStdString(jointName(box.document()->design(), id));
  for (bool belt : {false, true}) {
    QAction* a = menu.addAction(belt ? MenuActions::tr("Belt (the same way)")
                                     : MenuActions::tr("Gears in Mesh (opposite ways)"),
                                &menu, [&box, id, label, belt] {
                                  box.editWith(MenuActions::tr("Change %1").arg(label),
                                               [&](Mechanism& n, std::string&) {
                                                 Joint& g = *n.joint(id);
                                                 if ((gearRatio(g) > 0) != belt)
                                                   setGearRatio(g, -gearRatio(g));
                                                 return true;
                                               });
                                });
    a->setCheckable(true);
    a->setChecked((gearRatio(j) > 0) == belt);
  }
  // The ratio typed where it always is, the Properties: one field, one way to change it.
  menu.addAction(MenuActions::tr("Edit &Ratio..."), &menu,
                 [&box, id] { box.editField(id, Form::tr("Ratio")); });
}

void bodyMenu(MenuActions& box, QMenu& menu, BodyId body) {
  if (pivotsOf(box.document()->design(), body).empty()) return;
  menu.addAction(MenuActions::tr("Couple to (Gear or Belt)..."), &menu,
                 [&box, body] { box.startTool(QStringLiteral("gear"), ToolStart{.body = body}); });
}

}  // namespace

const ElementUi& gearUi() {
  static const ElementUi ui{
      JointType::Gear,
      QT_TRANSLATE_NOOP("Element", "gear or belt"),
      item,
      {"gear", QT_TRANSLATE_NOOP("Toolbox", "G&ear or Belt"), "E",
       QT_TRANSLATE_NOOP("Toolbox",
                         "Couple two pivoted bodies by gears in mesh, or a belt (Shift)"),
       "tool-gear", "gear"},
      form,
      jointMenu,
      bodyMenu,
      nullptr};
  return ui;
}

}  // namespace linkage::ui
