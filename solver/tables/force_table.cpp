#include "linkage/tables/force_table.h"

#include <cmath>
#include <cstring>
#include <span>

#include "linkage/io/numbers.h"
#include "linkage/space.h"

namespace linkage {

namespace {

// What a machine in space adds to a kind's columns (docs/dynamics.md): a joint in the plane,
// what its bearing takes out of the plane; a gear, the couple it transmits.
constexpr const char* kOutOfPlane[] = {"fn_N", "mx_Nm", "my_Nm"};
constexpr const char* kTransmitted[] = {"m_Nm"};

std::span<const char* const> outOfPlaneColumns(const ElementKind& kind) {
  if (kind.role == Role::Coupling || kind.role == Role::Distance) return {};
  return kOutOfPlane;
}

std::span<const char* const> spaceColumns(const ElementKind& kind) {
  if (kind.role == Role::Coupling) return kTransmitted;
  return outOfPlaneColumns(kind);
}

}  // namespace

std::vector<const char*> differentiatedColumns(const Mechanism& m, const ElementKind& kind) {
  std::vector<const char*> out(kind.reactionColumns.begin(), kind.reactionColumns.end());
  if (isSpatial(m))
    for (const char* c : outOfPlaneColumns(kind)) out.push_back(c);
  return out;
}

// A column's value by its name: planar columns are the force, its couple and a rod's pull.
double reactionValue(const JointReaction& x, const char* column, bool coupling) {
  if (!std::strcmp(column, "fx_N")) return x.force.x();
  if (!std::strcmp(column, "fy_N")) return x.force.y();
  if (!std::strcmp(column, "axial_N")) return x.axialN;
  if (!std::strcmp(column, "contact_N")) return x.contactN;
  if (!std::strcmp(column, "fn_N")) return x.normalN;
  if (!std::strcmp(column, "mx_Nm")) return x.tiltNm.x();
  if (!std::strcmp(column, "my_Nm")) return x.tiltNm.y();
  return coupling ? x.transmittedNm : x.coupleNm;  // m_Nm
}

std::string forceTableHeader(const Mechanism& m) {
  const bool space = isSpatial(m);
  std::string h = "t_s,crank_deg,driver_torque_Nm,shaking_fx_N,shaking_fy_N,";
  h += space ? "shaking_fz_N,shaking_mx_Nm,shaking_my_Nm,shaking_mz_Nm" : "shaking_moment_Nm";
  for (const Joint& j : m.joints) {
    const ElementKind& kind = kindOf(j);
    const std::string at = std::string(",") + kind.name + ":" + m.pointLabel(j.a) + ".";
    for (const char* c : kind.reactionColumns) h += at + c;
    if (space)
      for (const char* c : spaceColumns(kind)) h += at + c;
  }
  return h;
}

std::string forceTableRow(const Mechanism& m, const Forces& f, double tS, double crankDeg,
                          const std::vector<char>& undetermined) {
  const bool space = isSpatial(m);
  std::string r = formatNumber(tS) + "," + formatNumber(crankDeg) + "," +
                  formatNumber(f.driverTorqueNm) + "," + formatNumber(f.shakingForceN.x()) + "," +
                  formatNumber(f.shakingForceN.y());
  if (space)
    for (double v : {f.shakingForce3N.z(), f.shakingMoment3Nm.x(), f.shakingMoment3Nm.y(),
                     f.shakingMoment3Nm.z()})
      r += "," + formatNumber(v);
  else
    r += "," + formatNumber(f.shakingMomentNm);
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const JointReaction& x = f.joints[i];
    const ElementKind& kind = kindOf(m.joints[i]);
    const bool coupling = kind.role == Role::Coupling;
    // A bevel pair's tooth force is not computed, only the couple it transmits.
    const bool bevel = space && coupling && !undetermined[i] &&
                       !parallel(planeOf(m, m.point(m.joints[i].a)->body),
                                 planeOf(m, m.point(m.joints[i].b)->body));
    auto cell = [&](const char* c) {
      // (A bearing's load out of its plane is not known where a joint of its body's is not.)
      const double v = reactionValue(x, c, coupling);
      const bool empty =
          undetermined[i] || (bevel && std::strcmp(c, "m_Nm") != 0) || !std::isfinite(v);
      return "," + (empty ? std::string() : formatNumber(v));
    };
    for (const char* c : kind.reactionColumns) r += cell(c);
    if (space)
      for (const char* c : spaceColumns(kind)) r += cell(c);
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
