#include "elements/joint_item.h"

namespace linkage::ui {

void JointItem::setFlagged(bool on) {
  if (on == flagged_) return;
  flagged_ = on;
  update();
}

}  // namespace linkage::ui
