// The forces on a window's canvas (forces/dynamics_item.h): the design's centres of mass,
// counterweights and loads always; each joint's reaction at the pose while the reactions are
// shown (View > Joint Reactions), on one scale per design. It follows the scene: drawn again
// each time the scene is (a new pose or design), the scale made again for a new design. The
// document computes accelerations for the reactions only while they are shown.
#pragma once

#include <QObject>
#include <QPointer>
#include <cstdint>

namespace linkage::ui {

class CanvasScene;
class Document;
class DynamicsItem;

class ForcesOverlay : public QObject {
  Q_OBJECT

 public:
  explicit ForcesOverlay(CanvasScene* scene, QObject* parent = nullptr);
  ~ForcesOverlay() override;

  // The joints' reactions drawn (the masses and loads are, always).
  void setReactionsVisible(bool on);
  bool reactionsVisible() const { return reactions_; }
  DynamicsItem* item() const { return item_; }

 private:
  // The scene was drawn again: the marks follow it.
  void follow();
  void updateScale();

  CanvasScene* scene_;
  DynamicsItem* item_;
  QPointer<Document> doc_;
  bool reactions_ = false;
  double mmPerN_ = 0;  // the reactions' scale, fixed per design
  // What the scale is of (the solver's revision; 0: nothing): made again when it changes.
  std::uint64_t scaledFor_ = 0;
};

}  // namespace linkage::ui
