// The pin in a slot in the editor: a filled pin in the channel, the Pin in Slot tool (P: a
// point, then the slot), its type (it changes into a slider) and place in the panel and menu.
#include <QMenu>

#include "elements/element_ui.h"
#include "elements/pin_item.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing&) {
  return new PinItem(ctx, s.joint, PinItem::Kind::InSlot);
}

void pointMenu(MenuActions& box, QMenu& menu, PointId p) {
  addSlotJointStart(box, menu, p, "pinInSlot",
                    QT_TRANSLATE_NOOP("Toolbox", "Pin in a Slot Here..."));
}

}  // namespace

const ElementUi& pinInSlotUi() {
  static const ElementUi ui{
      JointType::PinInSlot,
      QT_TRANSLATE_NOOP("Element", "pin in slot (turns freely)"),
      item,
      {"pinInSlot", QT_TRANSLATE_NOOP("Toolbox", "&Pin in Slot"), "P",
       QT_TRANSLATE_NOOP("Toolbox", "Let a point run in a slot, turning freely"),
       "tool-pin-in-slot", "slotJoint"},
      slotJointForm,
      addTypeMenu,
      nullptr,
      pointMenu};
  return ui;
}

}  // namespace linkage::ui
