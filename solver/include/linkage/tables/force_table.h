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

// A reaction's column of its kind (reactionColumns, or a machine in space's fn_N, mx_Nm, my_Nm)
// as the table writes it; a coupling's m_Nm is the couple it transmits.
double reactionValue(const JointReaction& x, const char* column, bool coupling);

// The columns of a joint of this kind whose derivatives linkage/force_sensitivity.h gives: its
// kind's, and on a machine in space what it bears out of its plane (fn_N, mx_Nm, my_Nm; not a
// coupling's transmitted couple).
std::vector<const char*> differentiatedColumns(const Mechanism& m, const ElementKind& kind);

// undetermined() as forceTableRow() takes it.
std::vector<char> undeterminedJoints(const Mechanism& m, const std::vector<JointId>& joints);

}  // namespace linkage
