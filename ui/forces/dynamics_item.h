// What the design says about forces, drawn over the mechanism: each body's centre of mass (the
// quartered circle of engineering drawings) and the counterweights a balance added (disks, the
// larger the heavier), the loads as arrows at their points (a torque as a turning arrow; faint
// and dashed outside their window of crank angles), and, while forces are shown, each joint's
// reaction at the current pose as an arrow on one scale for the whole turn (so that arrows grow
// and shrink as the machine turns), with the scale and the driver's torque in the corner. A
// reaction the joints do not determine is marked so, never drawn with a length.
#pragma once

#include <QString>
#include <vector>

#include "draw/canvas_item.h"

namespace linkage::ui {

struct DynamicsMarks {
  struct Mass {
    QPointF com;
    std::vector<QPointF> counterweights;
    std::vector<double> counterweightKg;
  };
  struct Load {
    QPointF at;
    QPointF forceN;       // a force, or
    double torqueNm = 0;  // a torque (+ ccw) when `torque`
    bool torque = false;
    bool active = true;
    QString label;
  };
  struct Reaction {
    QPointF at, forceN;
    bool determined = true;
  };
  std::vector<Mass> masses;
  std::vector<Load> loads;
  std::vector<Reaction> reactions;
  double mmPerN = 0;  // the reactions' scale
  QString legend;     // the scale and the driver's torque, or why there are no forces
};

class DynamicsItem : public CanvasItem {
 public:
  explicit DynamicsItem(const CanvasContext* ctx);
  void setMarks(DynamicsMarks marks);
  const DynamicsMarks& marks() const { return marks_; }

  QRectF boundingRect() const override;
  void paint(QPainter* p, const QStyleOptionGraphicsItem*, QWidget* widget) override;

 private:
  void paintMass(QPainter* p, const DynamicsMarks::Mass& m) const;
  void paintLoad(QPainter* p, const DynamicsMarks::Load& l) const;
  void paintReaction(QPainter* p, const DynamicsMarks::Reaction& r) const;
  void paintText(QPainter* p, const QPointF& at, const QString& text, const QColor& ink) const;
  void paintLegend(QPainter* p, const QRectF& device) const;

  DynamicsMarks marks_;
};

// Colours of loads and reactions, readable on both palettes.
QColor loadColour(const CanvasStyle& s);
QColor reactionColour(const CanvasStyle& s);

}  // namespace linkage::ui
