// The kinematic model of one mechanism at one crank angle, and the way to move it: the API the
// command line and the editor drive. It owns its state (no global state); every failure comes
// back as a Status naming the joint, body and crank angle.
//
// Moving to a crank angle tracks the motion continuously from the current one, in steps of at
// most `maxStepDeg`: a predictor (second-order Taylor from the last regular position) and Newton
// on the independent equations. A step is refused, and halved, when Newton does not contract
// from the predictor, when its first correction is far (another branch), or when the sign of
// det J changes (the path crossed a singular position, where the other branch can be picked
// up). Refused down to `minStepDeg`, the reason is reported: a limit position (the mechanism
// locks), a singular crossing, or a position solve that fails.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "assembly.h"
#include "closed_form.h"
#include "model.h"
#include "motion.h"
#include "newton.h"
#include "status.h"
#include "structure.h"
#include "system.h"

namespace linkage {

struct KinematicsOptions {
  double maxStepDeg = 2.0;
  double minStepDeg = 1e-7;
  NewtonOptions newton;
  // Solve mechanisms made of a crank and dyads group by group in closed form (closed_form.h)
  // instead of by Newton on all coordinates; the general solve remains the fallback.
  bool closedForm = true;
  // Compute accelerations at every step. Positions and velocities always are: the tracker's
  // predictor and its branch and dead-point checks need velocities, so accelerations are the
  // part of a step a caller can leave out. The closed-form groups then skip them (they come
  // back as NaN, never stale); the general solve computes them anyway, as its test that a step
  // stayed on its branch uses them.
  bool accelerations = true;
  // Coordinates from which the general solve factors J as a sparse matrix and the structure
  // analysis tries its sparse test first (sparse_lu.h); tests set it to compare both on one
  // mechanism.
  int sparseFrom = kSparseFrom;
};

class Kinematics {
 public:
  explicit Kinematics(KinematicsOptions opt = {}) : opt_(opt) {}

  // Compiles, analyses and assembles the mechanism, then moves to crank angle 0 (the drawing
  // turned by the driver's start offset). On failure nothing usable is kept (valid() is false).
  Status load(const Mechanism& m);

  // Replaces the mechanism by an edited version of it and re-solves at the current crank angle,
  // starting from the current pose of every body that is still there (matched by id).
  // An edit of dimensions only (points or slots moved; see sameTopology) on the closed-form path
  // re-solves only the groups whose geometry changed and those that depend on them, on the
  // same assembly branches; other edits, or one that a group cannot follow, are solved whole.
  Status edit(const Mechanism& m);
  // Groups the last edit solved again, or -1 when it was solved whole.
  int lastEditGroups() const { return lastEditGroups_; }

  // Tracks the motion to the given crank angle (degrees, from the start, in the driving
  // direction). On failure the state stays at the last position reached.
  Status moveTo(double crankDeg);

  bool valid() const { return valid_; }
  double crankDeg() const;
  double rpm() const { return sys_.rpm; }
  void setRpm(double rpm) { sys_.rpm = rpm; }
  // Switches accelerations on or off (see KinematicsOptions); switched on, they are computed at
  // once for the current position.
  void setAccelerations(bool on);
  double omega() const;  // rad/s of the driver

  const Mechanism& mechanism() const { return mech_; }
  const System& system() const { return sys_; }
  const Structure& structure() const { return structure_; }
  const AssemblyReport& assembly() const { return assembly_; }
  // Things a user should know that are not failures (assembly moves, idle freedoms held).
  const std::vector<std::string>& notes() const { return notes_; }

  // False at a singular position, where positions are known but velocities are not.
  bool derivativesValid() const { return cur().regular; }

  // mm, mm/s, mm/s^2 at the driver's speed. Where derivativesValid() is false (moveTo returned
  // Singular) velocities and accelerations are not determined and come back as NaN.
  Vec2 position(PointId p) const;
  // All three at once (one lookup, one rotation of the point): what a motion table or a plot
  // of a point needs at each angle.
  struct PointMotion {
    Vec2 position, velocity, acceleration;
  };
  PointMotion motion(PointId p) const;
  Vec2 velocity(PointId p) const;
  Vec2 acceleration(PointId p) const;
  // Body angle (rad, relative to the drawing), angular velocity and acceleration.
  double bodyAngle(BodyId b) const;
  double bodyOmega(BodyId b) const;
  double bodyAlpha(BodyId b) const;

  // BadModel or Underconstrained naming the first point whose motion the driver does not fix.
  Status checkDetermined(const std::vector<PointId>& points) const;

  // True when the motion is computed group by group in closed form.
  bool closedForm() const { return plan_.has_value(); }
  // True when the general solve factors J as a sparse matrix.
  bool sparseSolve() const { return newton_.sparse(); }

  // Raw state: q and its derivatives with respect to the driver angle (rad).
  const Eigen::VectorXd& q() const { return coordinates(cur()).q; }
  const Eigen::VectorXd& dq() const { return coordinates(cur()).dq; }
  const Eigen::VectorXd& ddq() const { return coordinates(cur()).ddq; }

 private:
  struct Snapshot : Motion {
    bool regular = false;
    // The same in coordinates (x, y, theta per body) for the general solve and the raw
    // accessors; a closed-form step leaves them to be made on demand (coordinates()).
    mutable Eigen::VectorXd q, dq, ddq;
    mutable bool coordinates = false;
  };

  Status prepare(const Mechanism& m, const Eigen::VectorXd* warm, double warmPhi);
  bool editInPlace(const Mechanism& m);
  Status moveToPhi(double phi);
  Status trackGeneral(double phi);
  // Closed-form steps towards phi; false where the plan cannot go on (reg_ is the last good).
  bool trackClosedForm(double phi);
  Status skipWholeTurns(double target);
  enum class StepResult { Accepted, Refused, Singular };
  StepResult tryStep(double phiNext, Snapshot& out);
  // Did a step stay on the branch it started from? (tryStep; see there.)
  bool sameBranch(const Snapshot& from, const Snapshot& to, double h) const;
  Status explainFailure(double phiFailed, bool crossing);
  std::string bodyList(const std::vector<int>& bodies) const;
  const PointLocation& locate(PointId p) const;
  const Snapshot& coordinates(const Snapshot& s) const;

  KinematicsOptions opt_;
  Mechanism mech_;
  System sys_;
  Structure structure_;
  AssemblyReport assembly_;
  NewtonSolver newton_;
  std::vector<std::string> notes_;
  // The current position: the last regular one (the predictor's base) or, after a step that
  // ended on a singular position, that position. A flag, not a copy: a step copies nothing.
  const Snapshot& cur() const { return atSingular_ ? singular_ : reg_; }
  Snapshot reg_, singular_;
  bool atSingular_ = false;
  Snapshot next_;  // scratch for closed-form steps
  std::optional<ClosedFormPlan> plan_;
  int regSign_ = 0;  // det J sign at reg_
  // tryStep refused a converged step as a crossing: det J changed sign, the velocities jumped
  // (another branch), or the position is too near singular to step from.
  bool lastRefusalCrossing_ = false;
  bool valid_ = false;
  int lastEditGroups_ = -1;
};

}  // namespace linkage
