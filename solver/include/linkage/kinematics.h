// The kinematic model of one mechanism at one crank angle, and the way to move it: the API the
// command line and the editor drive. It owns its state (no global state); every failure comes
// back as a Status naming the joint, body and crank angle, and a failed load or edit leaves the
// last good state as it was.
//
// Moving to a crank angle tracks the motion continuously from the current one, in steps of at
// most `maxStepDeg`. Group by group in closed form where the mechanism decomposes (a step the
// groups cannot take, because a group does not close or its joint would land on the other side
// of its branch line, is left to the general solve from the last position reached). Else a
// predictor (second-order Taylor from the last regular position) and Newton on the independent
// equations. A step is refused, and the next try cut to a quarter of it (after an accepted step
// the step doubles again, up to `maxStepDeg`), when Newton does not converge from the predictor
// (J singular there, no contraction, or a first correction farther than
// `NewtonOptions::maxFirstStep` of the size: another branch), when the sign of det J changes (the
// path crossed a singular position, where the other branch can be picked up), when the velocities
// at its end do not follow from those at its start (a change point crossed with det J of the same
// sign), or when its end is too near a singular position to be the base of the next step. A step
// that ends on a singular position is refused too, unless it ends at the angle asked for: moveTo
// then stops there with Singular (positions known, velocities not). Refused down to
// `minStepDeg`, the reason is reported: a limit position (the mechanism locks), a singular
// crossing, or a position solve that fails.
//
// Ids: every query takes the ids of the Mechanism that was loaded (or a copy of it). An id the
// mechanism does not hold, or one from another mechanism, is refused: queries answer NaN and
// contains() false, commands return BadModel. Nothing is undefined.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "linkage/geometry.h"
#include "linkage/model.h"
#include "linkage/options.h"
#include "linkage/status.h"

namespace linkage {

struct KinematicsState;
class Kinematics;
namespace internal {
const KinematicsState& state(const Kinematics& k);
}

// What the structure analysis found (Gruebler's count against the rank of the joint equations).
struct StructureReport {
  int coordinates = 0;     // 3 per moving body
  int jointEquations = 0;  // scalar equations of the joints
  int gruebler = 0;        // coordinates - joint equations (Gruebler-Kutzbach mobility)
  int rank = 0;            // rank of the joint equations
  int mobility = 0;        // coordinates - rank: the real number of degrees of freedom
  bool driverMoves = false;
  int freeAfterDriver = 0;               // freedoms the driver leaves (held where drawn)
  std::vector<JointId> redundantJoints;  // file order; the later of two that say the same thing
  std::vector<BodyId> freeBodies;        // bodies that can move with the crank held
};

// How far the drawing had to move to close.
struct AssemblyReport {
  double maxMove = 0;  // mm: largest displacement of any point or slot end of a body
  BodyId body;         // the body that moved most
  int iterations = 0;
  bool moved = false;  // by more than rounding (1e-9 of the mechanism's size)
};

// Something a user should know that is not a failure.
struct Note {
  // CrankMoved: an edit that the crank could not follow to the angle it was at (it stopped at
  // the last angle it reached).
  enum class Kind { AssemblyMoved, RedundantJoints, FreedomsHeld, CrankMoved };
  Kind kind = Kind::AssemblyMoved;
  std::string text;  // one sentence, for people
  std::vector<JointId> joints;
  std::vector<BodyId> bodies;
  bool operator==(const Note&) const = default;
};

class Kinematics {
 public:
  explicit Kinematics(KinematicsOptions opt = {});
  ~Kinematics();
  Kinematics(const Kinematics& other);
  Kinematics& operator=(const Kinematics& other);
  Kinematics(Kinematics&&);
  Kinematics& operator=(Kinematics&&);

  // Compiles, analyses and assembles the mechanism, then moves to crank angle 0 (the drawing
  // turned by the driver's start offset). On failure the previous state, if there was one, is
  // kept whole: valid(), mechanism() and every query answer as before the call.
  Status load(const Mechanism& m);

  // Replaces the mechanism by an edited version of it and re-solves at the current crank angle,
  // starting from the current pose of every body that is still there (matched by id).
  // An edit of dimensions only (points or slots moved; see sameTopology) re-solves only the
  // groups whose geometry changed and those that depend on them, on the same assembly
  // branches: in closed form on that path, else by Newton on those groups' bodies alone; other
  // edits, or one that the groups cannot follow, are solved whole.
  // On failure the previous state is kept, as for load().
  Status edit(const Mechanism& m);
  // Groups (or, off the closed-form path, parts no group reached) the last edit solved again,
  // or -1 when it was solved whole.
  int lastEditGroups() const;

  // Tracks the motion to the given crank angle (degrees, from the start, in the driving
  // direction). On failure the state stays at the last position reached.
  Status moveTo(double crankDeg);

  // Drag: moves the mechanism along its freedom so that point p comes as close as it can to
  // `target` (world mm), as a hand pushing it would: a local descent of the distance from the
  // current pose (Newton steps on the crank angle from the exact velocity and acceleration of
  // the point), every step tracked by moveTo, so that it stays on its assembly branch however
  // far the target is. Bounded work per call (at most 8 steps of at most 15 degrees of crank):
  // an editor calls it once per mouse move and a far target is reached over a few calls.
  struct DragResult {
    // Ok; or Unreachable (atLimit) where the motion stopped at a limit position of the crank on
    // the way down, Singular or NotConverged where it stopped short of a singular position (the
    // message says where; the mechanism stays there, valid); BadModel for a point the driver
    // does not move (on the ground, on a body held where it is), an unknown point or a target
    // that is not finite, with nothing moved.
    Status status;
    double crankDeg = 0;     // the crank angle now
    double distance = 0;     // |position(p) - target| now, mm
    bool atLimit = false;    // stopped at a limit position (the distance would fall beyond it)
    bool converged = false;  // as near as the motion goes (a local minimum, or the stop); false
                             // when the call's work ran out first: call again
  };
  DragResult dragTo(PointId p, const Vec2& target);

  // Branch flip: puts the group that solves `body` (a dyad, RRR, RRP or RP, or a core group of
  // the closed-form solve; closedForm()) on its other assembly at the current crank angle: a
  // dyad's joint to the other intersection of its two circles (or circle and line), a core on
  // the other root of its equations. The groups that depend on it are solved again on their
  // own branches; the others do not move. By a joint: the group the joint belongs to (the
  // joint between a dyad's two links, or one of its pins to the bodies it hangs from).
  // The mechanism() is not changed: a later load of it assembles the drawing on the branch it
  // is drawn on. `redrawn`, when given, gets the design redrawn on the new branch (every body
  // the flip moves, drawn where it is at driver angle 0, the drawing's, exactly; the same ids):
  // loading or editing to it gives the flipped motion, and saving it keeps the flip.
  // Refused, with nothing changed: BadModel off the closed-form path (no mirror assembly is
  // known), for the crank, the ground or an unknown id; Singular at a singular position, where
  // the two assemblies meet; AssemblyFailed where a group that depends on it cannot close on
  // the new branch; the tracker's status when the new branch cannot be turned back to the
  // drawing's crank angle for `redrawn`.
  Status flipBranch(BodyId body, Mechanism* redrawn = nullptr);
  Status flipBranch(JointId joint, Mechanism* redrawn = nullptr);
  // The bodies flipBranch takes (file order): the bodies of the closed-form groups that have a
  // mirror assembly; empty off the closed-form path. What an editor greys its command by.
  std::vector<BodyId> flippableBodies() const;

  bool valid() const;
  // Changes with every successful load or edit (unique across all Kinematics objects): what a
  // derived object (InstantCentreSolver) records, to refuse working on a mechanism it has not
  // seen.
  std::uint64_t revision() const;
  double crankDeg() const;
  double rpm() const;
  void setRpm(double rpm);
  // Switches accelerations on or off (see KinematicsOptions); switched on, they are computed at
  // once for the current position.
  void setAccelerations(bool on);
  bool accelerations() const;
  double omega() const;  // rad/s of the driver

  const Mechanism& mechanism() const;
  StructureReport structure() const;
  const AssemblyReport& assembly() const;
  // Things a user should know that are not failures (assembly moves, idle freedoms held).
  const std::vector<Note>& notes() const;
  // L: the diagonal of the drawing's bounding box, the length scale of every tolerance (mm).
  double size() const;

  // Whether the loaded mechanism holds this id.
  bool contains(BodyId id) const;
  bool contains(PointId id) const;
  bool contains(SlotId id) const;
  bool contains(JointId id) const;

  // False at a singular position, where positions are known but velocities are not.
  bool derivativesValid() const;

  // mm, mm/s, mm/s^2 at the driver's speed. Where derivativesValid() is false (moveTo returned
  // Singular) velocities and accelerations are not determined and come back as NaN; so does
  // everything asked of an id the mechanism does not hold.
  Vec2 position(PointId p) const;
  // All three at once (one lookup, one rotation of the point): what a motion table or a plot
  // of a point needs at each angle.
  struct PointMotion {
    Vec2 position, velocity, acceleration;
  };
  PointMotion motion(PointId p) const;
  // The same in the world (mm, linkage/space.h): the planar motion of the point's body lifted
  // from its plane class's frame, at its depth; a ground point where it is, at rest. NaN for an
  // unknown point. With no planes, motion() with z = 0.
  struct PointMotion3 {
    Vec3 position, velocity, acceleration;
  };
  PointMotion3 motionInSpace(PointId p) const;
  // The same of any point fixed in a body, given in the body's sketch coordinates (an arc
  // slot's centre, a point being drawn); NaN for an unknown body.
  PointMotion motionOf(BodyId b, const Vec2& sketch) const;
  Vec2 velocity(PointId p) const;
  Vec2 acceleration(PointId p) const;
  // Body angle (rad, relative to the drawing, whole turns counted), angular velocity and
  // acceleration. The ground is at rest; an unknown id gives NaN.
  double bodyAngle(BodyId b) const;
  double bodyOmega(BodyId b) const;
  double bodyAlpha(BodyId b) const;

  // Each body's rigid motion from the drawing to the current pose (identity for the ground;
  // NaN for an unknown id): what a canvas applies to a body drawn in sketch coordinates.
  Transform bodyTransform(BodyId b) const;
  // Sketch coordinates of a body to the world at the current pose, and back.
  Vec2 toWorld(BodyId b, const Vec2& sketch) const;
  Vec2 toSketch(BodyId b, const Vec2& world) const;
  // A slot's two ends where they are now.
  struct Segment {
    Vec2 p0, p1;
  };
  Segment slotEnds(SlotId s) const;

  // BadModel or Underconstrained naming the first point whose motion the driver does not fix.
  Status checkDetermined(const std::vector<PointId>& points) const;

  // True when the motion is computed group by group in closed form.
  bool closedForm() const;
  // True when the general solve factors J as a sparse matrix.
  bool sparseSolve() const;

  // Raw state: q (x, y, theta of each moving body's frame, at the centroid of its drawn
  // geometry) and its derivatives with respect to the driver angle (rad).
  const Eigen::VectorXd& q() const;
  const Eigen::VectorXd& dq() const;
  const Eigen::VectorXd& ddq() const;

 private:
  friend const KinematicsState& internal::state(const Kinematics& k);
  std::unique_ptr<KinematicsState> d_;
};

// The structure of a mechanism as it is drawn, without assembling it: what `info` reports even
// for a mechanism that cannot be loaded. `status` is BadModel when it does not compile.
StructureReport analyzeDrawing(const Mechanism& m, Status& status);

}  // namespace linkage
