// The pin in the editor: a pin (a hatched ground pivot when one side is the ground), made by the
// link and ground tools; its place and whether it drives the mechanism in the panel; "Make It
// the Driver" on its menu.
#include <QCheckBox>
#include <QMenu>

#include "document/document.h"
#include "elements/element_ui.h"
#include "elements/menu_actions.h"
#include "elements/pin_item.h"
#include "forms/driver_rows.h"
#include "forms/form.h"
#include "linkage/edits.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing&) {
  return new PinItem(ctx, s.joint, s.groundPivot ? PinItem::Kind::GroundPivot : PinItem::Kind::Pin);
}

void form(Form& panel, JointId id) {
  Document* doc = panel.document();
  addTypeChoice(panel, id);
  addPointPlace(panel, doc->design().joint(id)->a);
  auto isDriver = [doc, id] { return doc->design().driver && doc->design().driver->joint == id; };
  panel.addCheck(
      Form::tr("Driver"), Form::tr("drives the mechanism (the crank)"), isDriver,
      [isDriver] { return !isDriver(); },
      [&panel, id](bool) {
        QString why;
        panel.change(
            Form::tr("Driver"),
            [&](Mechanism& m, QString* w) {
              std::string s;
              const bool ok = setDriver(m, id, &s);
              *w = QString::fromStdString(s);
              return ok;
            },
            &why);
      });
  if (isDriver()) addDriverRows(panel);
}

void jointMenu(MenuActions& box, QMenu& menu, const Joint& j) {
  const Mechanism& m = box.document()->design();
  const JointId id = j.id;
  const QString label = QString::fromStdString(jointName(m, id));
  QAction* drive = menu.addAction(MenuActions::tr("Make It the Driver"), &menu, [&box, id, label] {
    box.editWith(MenuActions::tr("Driver at %1").arg(label),
                 [&](Mechanism& n, std::string& why) { return setDriver(n, id, &why); });
  });
  drive->setEnabled(!(m.driver && m.driver->joint == id));
}

}  // namespace

const ElementUi& pinUi() {
  static const ElementUi ui{JointType::Pin, QT_TRANSLATE_NOOP("Element", "pin"),
                            item,           {nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
                            form,           jointMenu,
                            nullptr,        nullptr};
  return ui;
}

}  // namespace linkage::ui
