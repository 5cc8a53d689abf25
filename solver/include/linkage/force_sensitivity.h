// A joint's reaction differentiated with respect to the dimensions (issue 29: "the derivative of
// ... a force"), exactly. The joints' multipliers balance the bodies' applied and inertia forces,
// J^T lambda = Q; along a dimension p both sides change, J with the pose (dq/dp) and the
// constants, Q with the motion (dq/dp, dq'/dp, dq''/dp: the centres' accelerations, the moment
// arms), so J^T dlambda = dQ - dJ^T lambda. One component, lambda_r = w . Q with w = J^-1 e_r
// (the motion that opens row r by one unit: the reaction is the work of Q on it), changes by
//   dlambda_r = w . dQ - lambda . (dJ w),
// dJ w the change of J w with w held, what the velocities' sensitivities already compute for
// J q' (linkage/sensitivity.h, Sensitivity::jacobianChange): no second derivative is written
// out again. A joint's reaction is what its rows put on one of its bodies, -sum lambda_r J_r
// (the force and its moment about the body's frame origin, read about the joint's point a as
// linkage/dynamics.h reports it), so it changes by -sum (dlambda_r J_r + lambda_r dJ_r): a
// slider's normal force turns with its slot, a cam's contact force with its common normal. A
// gear's, restated as a tooth force at its pitch point (a belt's as a run's pull) that its
// pivots' pins carry, is differentiated through its kind's reactChange() (forward-mode, the same
// formula: elements/gear.cpp). On a machine in space the in-plane reaction in its plane class's
// frame and a ball rod's tension (axialN), from the world's sensitivities, and a bearing's load out
// of its plane (normalN, tiltNm: analysis/bearing_change.h, the multipliers' whole change
// J^-T (dQ - dJ^T lambda) moving every other joint's force on the body). Redundant joints (their
// shares are not determined) are refused by name.
#pragma once

#include <memory>
#include <vector>

#include "linkage/balance.h"
#include "linkage/elements.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"

namespace linkage {

struct JointForceSensitivity {
  Status status;
  JointReaction reaction;     // as linkage/dynamics.h reports it
  Vec2 force = Vec2::Zero();  // its force, N
  std::vector<Dimension> dims;
  std::vector<Vec2> derivative;  // d(force)/d(dimension k), N per unit
  // d(each part)/d(dimension k): the force (N), where it acts (mm), the couple (N m), a cam's
  // contact force (N), per unit.
  std::vector<JointReaction> change;
};

// d(generalized forces)/d(dimension dim) at the pose of s's last at() (linkage/dynamics.h
// generalizedForcesChange with the sensitivities' motion; a plane's origin carries its bodies'
// masses): N and N mm per unit, in the plane classes' frames.
Eigen::VectorXd generalizedForcesChange(const Kinematics& k, const Sensitivity& s, int dim);

// Whether `joint` is a body's bearing on a machine in space (its one joint with the ground): it
// then takes the body's load out of its plane (linkage/dynamics.h normalN, tiltNm).
bool bearsOutOfPlane(const Kinematics& k, JointId joint);

// At k's pose and speed, for `joint` (any kind: its reaction's parts as its dynamics columns
// name them, linkage/tables/force_table.h reactionValue).
JointForceSensitivity jointForceSensitivity(const Kinematics& k, JointId joint,
                                            std::vector<Dimension> dims);

// A counterweight's share of joint's reaction at k's pose (linkage/balance.h: its mass cw.kg at
// cw.staticMoment / cw.kg from its pivot in its body's sketch frame, turning with the body), and
// the share's derivatives with respect to the static moment's x and y, its mass the least that
// gives the moment at the body's reach (|s| / R, as optimize's counterweight variables take it).
// The reactions are linear in the forces (J^T lambda = Q with the pose held), so a mass adds
// J^-T of its weight and inertia: m g - m a at its place, a point mass's. On a machine in space
// in the body's class frame (gravity's part in it): the in-plane force, couple and a ball rod's
// tension, and a bearing's load out of its plane (normal force, tilts: the share's multipliers'
// forces on its body at their depths, and the counterweight's weight along the normal where it
// is on that body, its first moment kg (pivot - r) + R s).
struct CounterweightShare {
  Status status;
  JointReaction share;       // force, couple, contact and axial only (`at` is the joint's)
  JointReaction perX, perY;  // d(share)/d(static moment's x and y), per kg mm
};

CounterweightShare counterweightShare(const Kinematics& k, JointId joint, const Counterweight& cw);

// counterweightShare at many poses of one design (a search's turn): the joint's rows, the
// reactions that make it and what is refused worked out once by prepare(); at() then solves the
// share at k's pose (k holding the design prepare() saw, or a copy: another revision is refused;
// Singular where the share is unbounded).
class CounterweightShares {
 public:
  CounterweightShares();
  ~CounterweightShares();
  Status prepare(const Kinematics& k, JointId joint);
  CounterweightShare at(const Kinematics& k, const Counterweight& cw) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> d_;
};

// The share's derivatives with respect to dims (per unit), the counterweight's mass, moment and
// spin held, fixed in its body's drawing (its place from the pivot, which a dimension may move)
// and turning with the body: its forces' change with the body's turn, spin and spin's rate and
// the pivot's arm, and the reactions' own change with the pose (J^-T (dQ - dJ^T lambda), as
// jointForceSensitivity's). turn0[d]: a turn of the body per unit of dimension d taken off (the
// optimiser draws each design again at crank 0, where the counterweight is placed), else 0.
struct CounterweightShareChange {
  Status status;
  std::vector<JointReaction> change;  // by dimension: force, couple, contact and axial
};
CounterweightShareChange counterweightShareChange(const Kinematics& k, JointId joint,
                                                  const Counterweight& cw,
                                                  std::vector<Dimension> dims,
                                                  const std::vector<double>& turn0 = {});

}  // namespace linkage
