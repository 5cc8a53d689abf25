// The optimiser's variables and targets as text (`linkage-cli optimize`'s --vary and --target,
// and the Python module's optimize()): one syntax, read in one place.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/optimize.h"

namespace linkage {

// DIM=LO:HI
bool parseOptVary(const std::string& text, OptVariable& v);
// KIND:...=VALUE[*WEIGHT] (position:body.point@DEG=X,Y[,Z], Z a machine in space's); false with
// `why` naming the target and the fault. A path's file is read here.
bool parseOptTarget(const Mechanism& m, std::string text, OptTarget& t, std::string& why);
// The target's name in the output: body.point, body.point@DEG, mu:..., fx / fy / force.
std::string optTargetName(const Mechanism& m, const OptTarget& t);

}  // namespace linkage
