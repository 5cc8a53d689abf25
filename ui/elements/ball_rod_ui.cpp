// The ball rod in the editor: drawn as a rod between two balls; its two ends and its length in
// the panel. It is made in the file or from the 3D view's picks (docs/spatial.md); the 2D
// canvas has no tool of its own for it.
#include "document/document.h"
#include "elements/ball_rod_item.h"
#include "elements/element_ui.h"
#include "forms/form.h"
#include "linkage/space.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing&) {
  return new BallRodItem(ctx, s.joint);
}

void form(Form& panel, JointId id) {
  Document* doc = panel.document();
  addTypeChoice(panel, id);
  panel.addInfo(Form::tr("Ends"), [doc, id] {
    const Mechanism& m = doc->design();
    const Joint* j = m.joint(id);
    return QStringLiteral("%1, %2").arg(QString::fromStdString(m.pointLabel(j->a)),
                                        QString::fromStdString(m.pointLabel(j->b)));
  });
  panel.addInfo(Form::tr("Length"), [doc, id] {
    const Mechanism& m = doc->design();
    const Joint* j = m.joint(id);
    const double l = (worldOf(m, *m.point(j->a)) - worldOf(m, *m.point(j->b))).norm();
    return QStringLiteral("%1 mm").arg(l, 0, 'g', 6);
  });
}

void jointMenu(MenuActions&, QMenu&, const Joint&) {}

}  // namespace

const ElementUi& ballRodUi() {
  static const ElementUi ui{
      elementKindNamed("ball-rod")->type,
      QT_TRANSLATE_NOOP("Element", "ball rod (a rod with a ball at each end)"),
      item,
      {nullptr, nullptr, nullptr, nullptr, nullptr, nullptr},
      form,
      jointMenu,
      nullptr,
      nullptr};
  return ui;
}

}  // namespace linkage::ui
