// What a watched clearance says in words (issue 26): which part it measured to (a point, the
// segment between two points of a body, a slot as drawn) and what it found, for the Cycle
// dock's list and cursor line, its diagram and the canvas marks. A 0 is never a bare "0 mm":
// it says that the two meet (where along the part, when the point crosses it) or that the point
// runs along the part's line (the crank intervals where it is on the part).
#pragma once

#include <QString>

#include "linkage/clearance.h"
#include "linkage/model.h"

namespace linkage::ui {

// "hook.K – needlebar.N", "hook.K – segment needlebar.N-B", "hook.K – slot ground.plate".
QString clearanceLabel(const Mechanism& m, const ClearanceWatch& w);
// "point needlebar.N", "segment needlebar.N-B", "slot ground.plate".
QString partName(const Mechanism& m, const ClearancePart& part);
// What is measured, in a sentence: "From the point hook.K to the segment needlebar.N-B as drawn
// (beyond its ends, to the nearer end)."; for a point, how to name a part instead.
QString clearanceDescription(const Mechanism& m, const ClearanceWatch& w);
// What was found, with angles to `decimals` of a degree: "closest 4.411 mm at 210.25°",
// "0 mm, meets it at 206.57°, 4.74 mm from needlebar.N", "runs along its line, on it (0 mm)
// 281.46°–78.54°".
QString clearanceFigures(const Mechanism& m, const ClearanceWatch& w, const Clearance& c,
                         int decimals = 2);
// The briefest for a small place (the diagram's row): "closest 4.411 mm at 210.3°", "meets it
// at 206.6°", "on it 281.5°–78.5°".
QString clearanceNote(const Clearance& c, int decimals = 1);
// Where the point crosses the line of the segment or slot, one crossing a line ("meets it at
// 206.57°, 4.74 mm from needlebar.N", "crosses its line at 26.57°, 23.88 mm beyond
// needlebar.N"); empty for a point.
QString clearanceCrossings(const Mechanism& m, const ClearanceWatch& w, const Clearance& c);

}  // namespace linkage::ui
