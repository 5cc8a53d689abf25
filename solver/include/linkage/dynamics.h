// Forces at the driver's constant speed (kinetostatics): from the exact accelerations, the
// driver's torque, every joint's reaction, the shaking force and moment on the frame, at one
// pose, by one linear solve with the transpose of the constraint Jacobian the kinematics has:
//
//   J^T lambda = Q,   Q = the applied forces (gravity, loads) and the inertia forces
//                        (-m a_com at the centre of mass, -J alpha) of each body,
//
// the constraint forces -J^T lambda balancing them. On the closed-form path it is solved group by
// group in the structure's order reversed (from the outermost group to the crank, each group's
// few rows from its own bodies' balance: what a designer does by hand); otherwise with J whole.
// Units: masses kg, lengths mm, moments of inertia kg mm^2, forces N, torques N m.
//
// Where the reactions are not determined (redundant joints: more equations than the motion
// needs, so the reactions can be shared between them in more than one way) those joints are
// named and their reactions are NaN, never a number that means nothing; the driver's torque and
// the shaking force and moment do not depend on it.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "linkage/elements.h"
#include "linkage/kinematics.h"

namespace linkage {

struct Forces {
  Status status;  // Ok; BadModel, Underconstrained as prepare() said; or the kinematics' state
  double crankDeg = 0;
  // The torque the driver applies to the body of its b point (relative to a's), + ccw.
  double driverTorqueNm = 0;
  // What the moving bodies exert on the ground through the joints and the driver:
  //   sum(loads) + sum(m g) - sum(m a_com), and about the sketch origin
  //   sum(r_load x F_load) + sum(torque loads) + sum(r_com x m (g - a_com)) - sum(J alpha).
  Vec2 shakingForceN = Vec2::Zero();
  double shakingMomentNm = 0;
  // The same in the world, in 3D (a machine in space: the bodies' planes lifted; the moment
  // about the world's origin): shakingForceN is its x and y, shakingMomentNm its z. A planar
  // machine's z force is the weights along the drawing's normal (gravity's z, Mechanism::
  // gravityZ; 0 without it), its x and y moments theirs.
  Vec3 shakingForce3N = Vec3::Zero();
  Vec3 shakingMoment3Nm = Vec3::Zero();
  // Mechanism::joints order: the force on the body of the joint's point a from the other side
  // (its kind says how: linkage/elements.h); NaN for the undetermined.
  std::vector<JointReaction> joints;
  std::vector<JointId> undetermined;  // file order
  // A machine in space: the bodies with a load out of their planes and no single joint with the
  // ground (a bearing) to take it (docs/dynamics.md): that load is in no reaction.
  std::vector<BodyId> outOfPlaneUnsupported;
};

void shaking(const Kinematics& k, Vec3& forceN, Vec3& momentNm);

// The generalized forces the joints' multipliers balance (J^T lambda = Q): each moving body's
// applied and inertia force (N) and moment about its frame origin (N mm), in the order of the
// kinematics' coordinates, at k's pose. A planar machine's (what a reaction's derivative reads:
// linkage/force_sensitivity.h).
Eigen::VectorXd generalizedForces(const Kinematics& k);

// Its change along a change of the motion (a dimension's: linkage/sensitivity.h's columns dq/dp,
// dq'/dp, dq''/dp at k's pose, per radian of crank) that moves no mass in its body (each centre
// stays where it is drawn) and no load's force: the centres' accelerations and the moment arms
// turning with their bodies, and each point load's arm from its body's frame origin changing by
// armMove(point) (in that frame's axes, as the generalized forces are). A machine in space's in
// its plane classes' frames. comMove(body index), where given, moves a centre of mass in its body
// (turned into the frame's axes): a plane's origin carries its bodies' masses.
Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Eigen::VectorXd& dq,
                                        const Eigen::VectorXd& dqd, const Eigen::VectorXd& dqdd,
                                        const std::function<Vec2(PointId)>& armMove,
                                        const std::function<Vec2(int)>& comMove = nullptr);

class ForceSolver {
 public:
  // For k's mechanism (its masses, gravity and loads): BadModel without a driver or when the
  // kinematics hold nothing; Underconstrained where the driver leaves freedoms (a motion not
  // determined has no forces). Names the joints whose reactions are not determined.
  Status prepare(const Kinematics& k);
  // At k's pose (k holds the mechanism prepare() saw): NaN everywhere at a singular position;
  // BadModel, and NaN everywhere, where the forces overflow (past 1e308).
  const Forces& compute(const Kinematics& k);
  const Forces& result() const { return out_; }

 private:
  friend void shaking(const Kinematics& k, Vec3& forceN, Vec3& momentNm);
  friend Eigen::VectorXd generalizedForces(const Kinematics& k);
  friend Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Eigen::VectorXd& dq,
                                                 const Eigen::VectorXd& dqd,
                                                 const Eigen::VectorXd& dqdd,
                                                 const std::function<Vec2(PointId)>& armMove,
                                                 const std::function<Vec2(int)>& comMove);

  // Its change along a change of the motion (a dimension's: linkage/sensitivity.h's columns dq/dp,
  // dq'/dp, dq''/dp at k's pose, per radian of crank) that moves no mass in its body (each centre
  // stays where it is drawn) and no load's force: the centres' accelerations and the moment arms
  // turning with their bodies, and each point load's arm from its body's frame origin changing by
  // armMove(point) (in that frame's axes, as the generalized forces are). A machine in space's in
  // its plane classes' frames.
  Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Eigen::VectorXd& dq,
                                          const Eigen::VectorXd& dqd, const Eigen::VectorXd& dqdd,
                                          const std::function<Vec2(PointId)>& armMove);
  const Forces& overflowed(Forces& out);
  struct Impl;
  struct ImplDeleter {
    void operator()(Impl* p) const;
  };
  std::unique_ptr<Impl, ImplDeleter> d_;
  Forces out_;
};

// Whether every force, torque and force's magnitude of f is a finite number (the undetermined
// reactions, NaN by design, aside). ForceSolver::compute() says BadModel where they are not.
bool finiteForces(const Forces& f);

// One-off: prepared and computed at k's pose.
Forces computeForces(const Kinematics& k);

// The shaking force and moment alone, from the bodies' motion (no joint reaction needed): what
// balancing sweeps. In the plane (a planar machine's: Forces::shakingForceN, shakingMomentNm), or
// in the world (Forces::shakingForce3N, shakingMoment3Nm).
void shaking(const Kinematics& k, Vec2& forceN, double& momentNm);
void shaking(const Kinematics& k, Vec3& forceN, Vec3& momentNm);

}  // namespace linkage
