// Forces sampled over whole revolutions at the driver's constant speed (linkage/dynamics.h):
// what the editor's force plots and its balance dialog draw; on a machine in space, in the world
// as well (the columns of `linkage-cli dynamics`). As motion samples do, a sweep ends
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
  // By joint (file order), by sample: the force on the body of the joint's point a (a machine in
  // space: in its plane class's frame, as `linkage-cli dynamics` writes it).
  std::vector<std::vector<Vec2>> reactionN;
  // A machine in space (linkage/space.h): what `linkage-cli dynamics` writes besides, in the
  // world. Empty for a planar machine.
  bool inSpace = false;
  std::vector<Vec3> shaking3N, shakingMoment3Nm;  // the world's; the moment about its origin
  // By joint, by sample: its force in the world (its class frame's x and y lifted, with what it
  // bears along the normal, fn_N); a ball rod's: its pull on a's body; NaN where not known (a
  // bevel pair's tooth force, an undetermined joint).
  std::vector<std::vector<Vec3>> reaction3N;
  // By joint, by sample: a ball rod's tension (axial_N, + pulling its ends together), a gear's
  // couple on a's body about its axis (m_Nm), NaN for the other kinds.
  std::vector<std::vector<double>> axialOrCouple;
  size_t size() const { return crankDeg.size(); }
  // Every sample of `revs` whole turns was reached.
  bool complete = false;
};

// How a joint's reaction reads on a machine in space (docs/dynamics.md, "Machines in space"): a
// force (in its plane class's frame, lifted to the world with what it bears along the normal), a
// ball rod's tension, or a bevel pair's couple alone (its tooth force is not computed).
enum class SpaceReaction { Force, Tension, Couple };
SpaceReaction spaceReactionOf(const Mechanism& m, const Joint& j);
// Joint j's reaction r at k's pose as ForceSamples holds it in space: its force in the world
// (NaN for a bevel pair) and its tension or couple (NaN for the kinds with neither).
void reactionInSpace(const Kinematics& k, int j, const JointReaction& r, Vec3& force,
                     double& tensionOrCouple);

// k is not moved (a copy is). rpm 0: the mechanism's own.
ForceSamples sampleForces(const Kinematics& k, long long steps = 360, double revs = 1,
                          double rpm = 0);

}  // namespace linkage
