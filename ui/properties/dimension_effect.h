// What a link's typed dimensions do to the machine's first output point at the crank angle
// (issue 29: "the typed dimension fields show it too"): for each of the link's dimensions
// (linkage/sensitivity.h, named as its side fields are), the point's move per unit, exact, in a
// line of the link's form under its sides. Empty when the mechanism has no output, the point is
// the link's own dimension's, or the solver cannot differentiate it (said).
#pragma once

#include <QString>

#include "linkage/model.h"

namespace linkage::ui {

class Document;

QString dimensionEffect(const Document& doc, BodyId body);

}  // namespace linkage::ui
