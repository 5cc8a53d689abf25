#include "elements/element_ui.h"

#include <QCoreApplication>
#include <QMenu>

#include "document/document.h"
#include "elements/menu_actions.h"
#include "forms/form.h"
#include "linkage/edits.h"

namespace linkage::ui {

const ElementUi& pinUi();
const ElementUi& sliderUi();
const ElementUi& pinInSlotUi();
const ElementUi& gearUi();
const ElementUi& ballRodUi();
const ElementUi& camUi();

std::span<const ElementUi* const> elementUis() {
  static const ElementUi* const table[] = {&pinUi(),  &sliderUi(),  &pinInSlotUi(),
                                           &gearUi(), &ballRodUi(), &camUi()};
  return table;
}

const ElementUi& elementUi(JointType t) {
  return *elementUis()[t.index];
}

QString describe(JointType t) {
  return QCoreApplication::translate("Element", elementUi(t).describe);
}

int bodyNumber(const Drawing& d, BodyId b) {
  for (const Drawing::Body& x : d.bodies)
    if (x.id == b) return x.number;
  return 0;
}

namespace {
// The kinds a joint of kind t can change into (t among them), in table order.
std::vector<JointType> sameKinds(JointType t) {
  std::vector<JointType> out;
  for (const ElementKind& k : elementKinds())
    if (sameFields(k.type, t)) out.push_back(k.type);
  return out;
}
}  // namespace

void addTypeChoice(Form& panel, JointId id) {
  Document* doc = panel.document();
  const std::vector<JointType> kinds = sameKinds(doc->design().joint(id)->type);
  if (kinds.size() < 2) {
    panel.addInfo(Form::tr("Type"), [doc, id] { return describe(doc->design().joint(id)->type); });
    return;
  }
  QStringList items;
  for (JointType t : kinds) items << describe(t);
  auto current = [doc, id, kinds] {
    const JointType t = doc->design().joint(id)->type;
    return int(std::find(kinds.begin(), kinds.end(), t) - kinds.begin());
  };
  panel.addChoice(Form::tr("Type"), items, current, [&panel, id, kinds](int i) {
    QString why;
    if (!panel.change(
            Form::tr("Joint type"),
            [&](Mechanism& m, QString* w) {
              std::string s;
              const bool ok = changeJointType(m, id, kinds[i], &s);
              *w = QString::fromStdString(s);
              return ok;
            },
            &why))
      panel.warn(why);
  });
}

void addTypeMenu(MenuActions& box, QMenu& menu, const Joint& j) {
  const std::vector<JointType> kinds = sameKinds(j.type);
  if (kinds.size() < 2) return;
  QMenu* type = menu.addMenu(MenuActions::tr("Change Type"));
  const JointId id = j.id;
  const QString label = QString::fromStdString(jointName(box.document()->design(), id));
  for (JointType t : kinds) {
    QAction* a = type->addAction(describe(t), type, [&box, id, t, label] {
      box.editWith(MenuActions::tr("Change type of %1").arg(label),
                   [&](Mechanism& n, std::string& why) { return changeJointType(n, id, t, &why); });
    });
    a->setCheckable(true);
    a->setChecked(j.type == t);
  }
}

void addSlotJointStart(MenuActions& box, QMenu& menu, PointId p, const char* tool,
                       const char* text) {
  menu.addAction(QCoreApplication::translate("Toolbox", text), &menu, [&box, p, tool] {
    box.startTool(QString::fromLatin1(tool), ToolStart{.point = p});
  });
}

void slotJointForm(Form& panel, JointId id) {
  addTypeChoice(panel, id);
  addPointPlace(panel, panel.document()->design().joint(id)->a);
}

void addPointPlace(Form& panel, PointId a) {
  Document* doc = panel.document();
  for (int axis = 0; axis < 2; ++axis)
    panel.addNumber(
        axis ? QStringLiteral("y") : QStringLiteral("x"),
        [doc, a, axis] { return doc->design().point(a)->pos[axis]; },
        [&panel, a, axis](double v, QString* why) {
          return panel.change(
              Form::tr("Move joint"),
              [&](Mechanism& m, QString*) {
                for (PointId q : pinnedTogether(m, a)) m.point(q)->pos[axis] = v;
                return true;
              },
              why);
        },
        Form::tr("mm"));
}

}  // namespace linkage::ui
