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
// KIND:...=VALUE[*WEIGHT] (position:body.point@DEG=X,Y[,Z], Z a machine in space's;
// stroke:body.point[@DIR]=MM); false with `why` naming the target and the fault. A path's file
// is read here: x,y or (a machine in space's) x,y,z a line.
bool parseOptTarget(const Mechanism& m, std::string text, OptTarget& t, std::string& why);
// A direction in the world: x, y, z (the axes) or DX,DY[,DZ] (any length, not 0; DZ 0 when
// left out); nullopt else. A stroke's (`stroke:body.point@DIR=MM`, `sensitivity --direction`).
std::optional<Vec3> parseDirection(const std::string& text);
// x, y, z for the axes, else DX,DY,DZ: what parseDirection reads back.
std::string directionName(const Vec3& d);
// The target's name in the output: body.point, body.point@DEG, mu:..., fx / fy / force.
std::string optTargetName(const Mechanism& m, const OptTarget& t);

}  // namespace linkage
