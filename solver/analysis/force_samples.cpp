#include "linkage/force_samples.h"

#include <cmath>

namespace linkage {

ForceSamples sampleForces(const Kinematics& k, long long steps, double revs, double rpm) {
  ForceSamples out;
  Kinematics probe = k;
  probe.setAccelerations(true);  // an editor may have them off while no view shows them
  if (rpm > 0) probe.setRpm(rpm);
  out.rpm = probe.valid() ? probe.rpm() : 0;
  out.steps = steps;
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
