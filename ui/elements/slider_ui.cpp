// The slider in the editor: its block drawn along the slot, the Block tool (B: a point, then
// the slot), its type (it changes into a pin in the slot) and place in the panel and menu.
#include <QMenu>

#include "elements/block_item.h"
#include "elements/element_ui.h"

namespace linkage::ui {

namespace {

JointItem* item(const CanvasContext* ctx, const JointSymbol& s, const Drawing& d) {
  return new BlockItem(ctx, s.joint, s.bodies[0], bodyNumber(d, s.bodies[0]));
}

void pointMenu(MenuActions& box, QMenu& menu, PointId p) {
  addSlotJointStart(box, menu, p, "block",
                    QT_TRANSLATE_NOOP("Toolbox", "Slider Block in a Slot Here..."));
}

}  // namespace

const ElementUi& sliderUi() {
  static const ElementUi ui{
      JointType::Slider,
      QT_TRANSLATE_NOOP("Element", "slider (the block keeps its angle)"),
      item,
      {"block", QT_TRANSLATE_NOOP("Toolbox", "Slider &Block"), "B",
       QT_TRANSLATE_NOOP("Toolbox", "Put a slider block at a point, sliding in a slot"),
       "tool-block", "slotJoint"},
      slotJointForm,
      addTypeMenu,
      nullptr,
      pointMenu};
  return ui;
}

}  // namespace linkage::ui
