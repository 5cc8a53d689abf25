#include "forces/forces_overlay.h"

#include <cmath>

#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "forces/dynamics_item.h"
#include "forces/dynamics_marks.h"

namespace linkage::ui {

ForcesOverlay::ForcesOverlay(CanvasScene* scene, QObject* parent)
    : QObject(parent), scene_(scene), item_(new DynamicsItem(scene->context())) {
  scene_->addOverlay(item_);
  connect(scene_, &CanvasScene::redrawn, this, &ForcesOverlay::follow);
  follow();
}

ForcesOverlay::~ForcesOverlay() {
  if (doc_) doc_->setForcesWanted(this, false);
}

void ForcesOverlay::setReactionsVisible(bool on) {
  if (on == reactions_) return;
  reactions_ = on;
  if (doc_) doc_->setForcesWanted(this, on);
  scaledFor_ = 0;
  follow();
}

void ForcesOverlay::updateScale() {
  mmPerN_ = 0;
  scaledFor_ = doc_ && scene_->solverShown() ? doc_->kinematics().revision() : 0;
  if (!reactions_ || !scaledFor_ || !doc_->motionStatus().ok()) return;
  const Drawing& d = scene_->drawing();
  const QRectF r =
      scene_->motionRect().isEmpty() ? QRectF(toQt(d.min), toQt(d.max)) : scene_->motionRect();
  mmPerN_ = reactionScale(doc_->kinematics(), std::hypot(r.width(), r.height()));
}

void ForcesOverlay::follow() {
  Document* doc = scene_->document();
  if (doc != doc_) {
    if (doc_) doc_->setForcesWanted(this, false);
    doc_ = doc;
    if (doc_) doc_->setForcesWanted(this, reactions_);
    scaledFor_ = 0;
  }
  if (!doc_) return;
  const bool solved = scene_->solverShown();
  if (!solved) {
    mmPerN_ = 0;
    scaledFor_ = 0;
  } else if (scaledFor_ != doc_->kinematics().revision()) {
    updateScale();
  }
  // Not the solver's design drawn: with the reactions on, their legend says why there are none
  // (the document's reason).
  item_->setMarks(dynamicsMarks(*scene_, *doc_, reactions_, solved ? mmPerN_ : 0));
}

}  // namespace linkage::ui
