// The marks of DynamicsItem made from a document at its pose: masses and loads of the design as
// drawn, and the reactions of Document::forces() while forces are shown.
#pragma once

#include "forces/dynamics_item.h"
#include "linkage/kinematics.h"

namespace linkage::ui {

class CanvasScene;
class Document;

// The reactions' scale (mm per N) for a design: the largest reaction over a turn drawn a quarter
// of the mechanism's extent, rounded down to a 1-2-5 step of newtons per 10 mm so that the
// legend reads. 0 when there are no forces to draw.
double reactionScale(const Kinematics& k, double extentMm);

DynamicsMarks dynamicsMarks(const CanvasScene& scene, Document& doc, bool forces, double mmPerN);

}  // namespace linkage::ui
