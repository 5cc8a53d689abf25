// The inside of a Kinematics (linkage/kinematics.h): the compiled system, its analysis, the
// solvers and the tracked state. Internal: the solver's own analyses (instant centres), tests
// and benchmarks reach it through internal::state().
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "kinematics/assembly.h"
#include "kinematics/closed_form.h"
#include "kinematics/motion.h"
#include "kinematics/newton.h"
#include "linkage/kinematics.h"
#include "structure/decomposition.h"
#include "structure/structure.h"
#include "system/system.h"

namespace linkage {

struct KinematicsState {
  struct Snapshot : Motion {
    bool regular = false;
    // The same in coordinates (x, y, theta per body) for the general solve and the raw
    // accessors; a closed-form step leaves them to be made on demand (coordinates()).
    mutable Eigen::VectorXd q, dq, ddq;
    mutable bool coordinates = false;
  };

  explicit KinematicsState(const KinematicsOptions& o) : opt(o) {}

  // Loading: compile, analyse (structure, notes), the Newton solver for the independent rows
  // (and holds), assembly, then the start (derivatives, closed-form plan).
  Status load(const Mechanism& m);
  Status prepare(const Mechanism& m, const Eigen::VectorXd* warm, double warmPhi);
  Status analyse(const Mechanism& m, const Eigen::VectorXd& q);
  void resetSolver(const Eigen::VectorXd& q);
  Status start(const Eigen::VectorXd& q, double phi);
  bool assembleOffLine(const Eigen::VectorXd& drawn, Eigen::VectorXd& q, double phi, Status& s);
  // Edits of an already valid state, cheapest first; each changes nothing when it fails.
  // Dimensions only, on the closed-form path: the groups the edit touches (load.cpp).
  bool editInPlace(const Mechanism& m, const std::vector<BodyId>& reshaped);
  // Dimensions only, off that path: the groups the edit touches, by Newton on their bodies.
  bool editBlocks(const Mechanism& m);
  // Its solve of `bodies` in q, dq and ddq (the others read) on the same branch, joints closed.
  bool solveBlock(const Mechanism& m, const System& edited, const std::vector<int>& bodies,
                  double phi, Eigen::VectorXd& q, Eigen::VectorXd& dq, Eigen::VectorXd& ddq) const;
  // Dimensions only: the analysis and the Newton solver kept, re-assembled from the current
  // pose.
  bool editKeepingAnalysis(const Mechanism& m);
  // Closes the joints from q (near a solution) at phi, then starts there; false where it
  // cannot (q is then the last iterate).
  bool reassemble(Eigen::VectorXd& q, double phi);
  // Anything (into a new state): a warm start from old's pose, else the drawing turned to the
  // crank angle old was at.
  Status editFrom(const KinematicsState& old, const Mechanism& m);

  Status moveToPhi(double phi);
  // Kinematics::dragTo (drag.cpp).
  Kinematics::DragResult drag(PointId p, const Vec2& target);
  // Kinematics::flipBranch (flip.cpp): the plan's group on its other assembly; `what` names it
  // in messages.
  Status flip(int group, const std::string& what, Mechanism* redrawn);
  std::vector<BodyId> flippableBodies() const;
  // The design drawn at the pose `at`: each body that is not at its drawn pose there (beyond
  // rounding) drawn where it is; the others as they were, to the bit.
  Mechanism drawnAt(const Motion& at) const;
  Status trackGeneral(double phi);
  // Closed-form steps towards phi; false where the plan cannot go on (reg is the last good).
  bool trackClosedForm(double phi);
  Status skipWholeTurns(double target);
  enum class StepResult { Accepted, Refused, Singular };
  StepResult tryStep(double phiNext, Snapshot& out);
  // Did a step stay on the branch it started from? (tryStep; see there.)
  bool sameBranch(const Snapshot& from, const Snapshot& to, double h) const;
  Status explainFailure(double phiFailed, bool crossing);
  // At a singular position q: the bodies and joints there, added to s (and its message).
  void namePlace(const Eigen::VectorXd& q, Status& s) const;
  std::string bodyList(const std::vector<int>& bodies) const;
  const Snapshot& coordinates(const Snapshot& s) const;
  double crankDeg() const;

  KinematicsOptions opt;
  Mechanism mech;
  System sys;
  Structure structure;
  Decomposition decomposition;  // of the joints' rows (no holds): what the plan solves
  AssemblyReport assembly;
  NewtonSolver newton;
  std::vector<Note> notes;
  // The current position: the last regular one (the predictor's base) or, after a step that
  // ended on a singular position, that position. A flag, not a copy: a step copies nothing.
  const Snapshot& cur() const { return atSingular ? singular : reg; }
  Snapshot reg, singular;
  bool atSingular = false;
  Snapshot next;  // scratch for closed-form steps
  std::optional<ClosedFormPlan> plan;
  int regSign = 0;  // det J sign at reg
  // tryStep refused a converged step as a crossing: det J changed sign, the velocities jumped
  // (another branch), or the position is too near singular to step from.
  bool lastRefusalCrossing = false;
  bool valid = false;
  int lastEditGroups = -1;
  // How the last edit was solved (for tests and benchmarks): in place by the closed-form groups,
  // by Newton on the touched groups' bodies, re-assembled with the analysis kept, or whole
  // (analysed again).
  enum class EditPath { None, InPlace, Blocks, KeptAnalysis, Whole };
  void noteEdit(int groups, EditPath path);  // the bookkeeping of an edit that kept the analysis
  EditPath lastEdit = EditPath::None;
  std::uint64_t revision = 0;
};

namespace internal {
// The solver's own view of a Kinematics: for analyses inside solver/, tests and benchmarks.
const KinematicsState& state(const Kinematics& k);
inline const System& system(const Kinematics& k) {
  return state(k).sys;
}
inline const Structure& structure(const Kinematics& k) {
  return state(k).structure;
}
}  // namespace internal

}  // namespace linkage
