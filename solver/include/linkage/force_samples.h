// Forces sampled over whole revolutions at the driver's constant speed (linkage/dynamics.h):
// what the editor's force plots and its balance dialog draw. As motion samples do, a sweep ends
// at the first angle the crank cannot pass, with the samples before it kept and its status
// saying where; reactions that the joints do not determine are NaN and their joints named.
#pragma once

#include <vector>

#include "linkage/dynamics.h"

namespace linkage {

struct ForceSamples {
  Status status;  // Ok; prepare()'s refusal (no samples); or why the sweep stopped
  std::vector<JointId> undetermined;
  double rpm = 0;
  long long steps = 0;  // per revolution
  std::vector<double> crankDeg, driverTorqueNm, shakingMomentNm;
  std::vector<Vec2> shakingN;
  // By joint (file order), by sample: the force on the body of the joint's point a.
  std::vector<std::vector<Vec2>> reactionN;
  size_t size() const { return crankDeg.size(); }
  // Every sample of `revs` whole turns was reached.
  bool complete = false;
};

// k is not moved (a copy is). rpm 0: the mechanism's own.
ForceSamples sampleForces(const Kinematics& k, long long steps = 360, double revs = 1,
                          double rpm = 0);

}  // namespace linkage
