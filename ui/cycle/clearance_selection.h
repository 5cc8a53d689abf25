// Which clearance the canvas's selection names, for Analysis > Watch Clearance (Shift+W): two
// points, a point and a slot of another body, or a point and two points of one other body (the
// segment between them: a needle, a blade). A joint stands for a point it joins: a click on a
// pin selects the joint (the needle bar's top is its rod's pin).
#pragma once

#include <QString>

#include "linkage/model.h"

namespace linkage::ui {

class Selection;

// The entry as typed in the Cycle dock ("hook.K needlebar.N-B"), the segment from the first of
// its two points selected; "" when the selection is not one of those.
QString clearanceOfSelection(const Mechanism& m, const Selection& s);

}  // namespace linkage::ui
