// Slot travel on the canvas (issue 18): the blocks and pins that leave their slot over a turn
// (linkage/slot_travel.h, exact extremes), what the canvas draws in the warning colour and the
// sentence the window's design status shows. Computed once per solve of a design (the solver's
// revision), never per frame.
#pragma once

#include <QString>
#include <cstdint>
#include <vector>

#include "linkage/model.h"

namespace linkage::ui {

class Document;

struct SlotWarning {
  JointId joint;
  SlotId slot;
  double byMm = 0;      // how far beyond the end it runs
  double atDeg = 0;     // the crank angle where it is farthest out
  bool pastEnd = true;  // beyond the slot's second end (p1); false: before its first (p0)
};

class SlotWarnings {
 public:
  // The warnings of the document's solved design (none when it is not solved or its motion is
  // not determined, or the crank cannot turn a whole revolution).
  const std::vector<SlotWarning>& of(const Document& doc);
  // "block 'needlebar.B' leaves slot 'ground.needle' by 2.31 mm past its end at crank 137.2°"
  // for the farthest one, and how many others there are; empty when none.
  QString text(const Document& doc);

 private:
  std::uint64_t revision_ = 0;
  std::vector<SlotWarning> warnings_;
};

}  // namespace linkage::ui
