// The numbers beside the plots: the values at the cursor, and the list under them (each
// curve's extremes, or each harmonic's amplitude and phase), in the units shown.
#pragma once

#include <QString>
#include <vector>

#include "figures/units.h"
#include "plots/curve_set.h"

class QTreeWidget;

namespace linkage::ui {

// 5 significant digits ("—" for a value that is not there); degrees with 2 decimals.
QString formatValue(double v);
QString formatDegrees(double deg);

// One line per set: "needlebar.G at 40.00°: y -58.464 mm, vy -787.97 mm/s, ay ..." (the set's
// title first when there are several). Moves each set's solver copy to `deg`.
QString cursorValues(const std::vector<CurveSet*>& sets, double deg, const PlotUnits& u);

// A row per set and order: maximum and minimum with their crank angles, and the range (the
// stroke, for a point's position).
void listExtremes(QTreeWidget* list, const std::vector<const CurveSet*>& sets, const PlotUnits& u);
// A row per set, order and harmonic k = 1 ... maxK (and the mean): amplitude and phase of
// the term amplitude cos(k phi + phase).
void listHarmonics(QTreeWidget* list, const std::vector<const CurveSet*>& sets, const PlotUnits& u,
                   int maxK = 20);
// The list as text, a line a row (for tests and the clipboard).
QString listText(const QTreeWidget* list, bool harmonics);

}  // namespace linkage::ui
