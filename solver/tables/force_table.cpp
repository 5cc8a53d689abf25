#include "linkage/tables/force_table.h"

#include "linkage/io/numbers.h"

namespace linkage {

std::string forceTableHeader(const Mechanism& m) {
  std::string h = "t_s,crank_deg,driver_torque_Nm,shaking_fx_N,shaking_fy_N,shaking_moment_Nm";
  for (const Joint& j : m.joints) {
    const ElementKind& kind = kindOf(j);
    for (const char* c : kind.reactionColumns)
      h += std::string(",") + kind.name + ":" + m.pointLabel(j.a) + "." + c;
  }
  return h;
}

std::string forceTableRow(const Mechanism& m, const Forces& f, double tS, double crankDeg,
                          const std::vector<char>& undetermined) {
  std::string r = formatNumber(tS) + "," + formatNumber(crankDeg) + "," +
                  formatNumber(f.driverTorqueNm) + "," + formatNumber(f.shakingForceN.x()) + "," +
                  formatNumber(f.shakingForceN.y()) + "," + formatNumber(f.shakingMomentNm);
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const JointReaction& x = f.joints[i];
    const double values[3] = {x.force.x(), x.force.y(), x.coupleNm};
    const size_t n = kindOf(m.joints[i]).reactionColumns.size();
    for (size_t c = 0; c < n; ++c) r += "," + (undetermined[i] ? "" : formatNumber(values[c]));
  }
  return r;
}

std::vector<char> undeterminedJoints(const Mechanism& m, const std::vector<JointId>& joints) {
  std::vector<char> u(m.joints.size(), 0);
  for (JointId j : joints)
    if (const int i = m.jointIndex(j); i >= 0) u[i] = 1;
  return u;
}

}  // namespace linkage
