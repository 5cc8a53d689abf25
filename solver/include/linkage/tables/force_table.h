// The force table of `linkage-cli dynamics` (docs/dynamics.md): header, then one row per crank
// angle with t, crank angle, the driver's torque, the shaking force and moment, and each joint's
// reaction in the columns its kind names (linkage/elements.h). 17 significant digits; the
// reactions the joints do not determine are left empty. Shared by every front end.
#pragma once

#include <string>
#include <vector>

#include "linkage/dynamics.h"

namespace linkage {

std::string forceTableHeader(const Mechanism& m);

// undetermined: by joint index, 1 where its reaction is not determined.
std::string forceTableRow(const Mechanism& m, const Forces& f, double tS, double crankDeg,
                          const std::vector<char>& undetermined);

// undetermined() as forceTableRow() takes it.
std::vector<char> undeterminedJoints(const Mechanism& m, const std::vector<JointId>& joints);

}  // namespace linkage
