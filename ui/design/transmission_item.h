// The transmission angles at the current pose, drawn where they act: at each joint where a
// link drives another body (linkage/transmission.h), an arc between the two links (a dyad's
// middle pin), or between the rod and the normal of its slot (a rod driving a block or a pin in
// a slot: mu = 90 degrees minus the angle between rod and slot, so the arc closes as the rod
// turns across the slot), with the value "μ1 47.3°" beside it, in the warning colour where the
// angle is outside the band. Numbered as the paper numbers mu_1, mu_2, mu_3: in the order the
// structure solves the groups.
//
// Per frame it reads a few positions and transmissionAngle per joint (no solve): setPose is
// what the animation pays for it.
#pragma once

#include <vector>

#include <memory>

#include "design/overlay_labels.h"
#include "draw/canvas_item.h"
#include "linkage/transmission.h"

namespace linkage::ui {

struct TransmissionArc {
  int index = 0;               // of the joint in joints(): drawn as mu_(index + 1)
  Vec2 centre = Vec2::Zero();  // the joint, world mm
  Vec2 from = Vec2::UnitX();   // unit direction the arc starts at ...
  double sweepDeg = 0;         // ... and turns counter-clockwise by (the angle drawn)
  Vec2 normal = Vec2::Zero();  // a rod's: the slot's normal the angle is measured from
  double mu = 0;               // transmissionAngle at this pose, degrees
  bool outside = false;        // outside the band
};

class TransmissionItem : public CanvasItem {
 public:
  explicit TransmissionItem(const CanvasContext* ctx);
  // The joints of the design (transmissionJoints), or none.
  void setJoints(std::vector<TransmissionJoint> joints);
  const std::vector<TransmissionJoint>& joints() const { return joints_; }
  void setBand(const TransmissionBand& band);
  // The arcs at k's pose (k holds the joints' mechanism); an invalid k clears them.
  void setPose(const Kinematics& k);
  const std::vector<TransmissionArc>& arcs() const { return arcs_; }
  // The colour an arc and its value are painted in.
  QColor colourOf(const TransmissionArc& a) const;

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget*) override;

 private:
  std::vector<TransmissionJoint> joints_;
  std::vector<TransmissionArc> arcs_;
  TransmissionBand band_;
};

}  // namespace linkage::ui
