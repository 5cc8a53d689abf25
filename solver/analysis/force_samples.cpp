#include "linkage/force_samples.h"

#include <cmath>

#include "linkage/space.h"

namespace linkage {

ForceSamples sampleForces(const Kinematics& k, long long steps, double revs, double rpm) {
  ForceSamples out;
  Kinematics probe = k;
  probe.setAccelerations(true);  // an editor may have them off while no view shows them
  if (rpm > 0) probe.setRpm(rpm);
  out.rpm = probe.valid() ? probe.rpm() : 0;
  out.steps = steps;
  // The editor's plots show a force in its plane's x and y: a machine in space has more (the
  // shaking force's z, the bearings' loads out of their planes, the rods' tension), which they
  // do not draw yet; linkage-cli dynamics writes them (docs/dynamics.md).
  if (probe.valid())
    if (std::string why = notInSpaceYet(probe.mechanism(), "force plots"); !why.empty())
      return out.status = Status::badModel(why + " (linkage-cli dynamics writes the forces)"), out;
  ForceSolver solver;
  if (!(out.status = solver.prepare(probe)).ok()) return out;
  out.undetermined = solver.result().undetermined;
  const Mechanism& m = probe.mechanism();
  out.reactionN.assign(m.joints.size(), {});
  const long long n = std::llround(static_cast<double>(steps) * revs);
  for (long long i = 0; i <= n; ++i) {
    const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(steps);
    if (Status s = probe.moveTo(deg); !s.ok()) return out.status = s, out;
    const Forces& f = solver.compute(probe);
    if (!f.status.ok()) return out.status = f.status, out;
    out.crankDeg.push_back(deg);
    out.driverTorqueNm.push_back(f.driverTorqueNm);
    out.shakingN.push_back(f.shakingForceN);
    out.shakingMomentNm.push_back(f.shakingMomentNm);
    for (size_t j = 0; j < f.joints.size(); ++j) out.reactionN[j].push_back(f.joints[j].force);
  }
  out.complete = true;
  return out;
}

}  // namespace linkage
