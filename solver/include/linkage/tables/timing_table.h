// The timing table of `linkage-cli timing` (docs/timing.md): "window,from_deg,to_deg", a row
// "NAME,FROM,TO" per interval of each window (in the diagram's order, intervals in order of
// their start; FROM in [0, 360), TO > FROM, past 360 when it wraps through 0), then a row
// "conflict:N1+N2,FROM,TO" per overlap. 17 significant digits. Shared by every front end.
#pragma once

#include <string>

#include "linkage/timing.h"

namespace linkage {

std::string timingTable(const CycleDiagram& d);

}  // namespace linkage
