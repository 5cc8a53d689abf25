// Exact sensitivities of a mechanism's motion to its dimensions (issue 29): how far a point moves
// at a crank angle per mm of a link, per mm of a ground pivot, per degree of a slot, per unit of a
// gear ratio. From the constraints, never by finite differences: at a pose where Phi(q, p) = 0,
// dq/dp = -J_q^-1 J_p, with J_p the rows' partial derivatives with respect to their local
// vectors and constants (derived per primitive in analysis/sensitivity.cpp), and the
// velocities' and accelerations' from J q' + Phi_phi = 0 and J q'' = gamma differentiated the
// same way.
//
// A dimension is a change of the drawing with every body's frame held: the points of one body
// (or one slot) move in that body's frame, nothing pinned to them moves with them (unlike a typed
// dimension in the editor, which moves the pinned points of other bodies too: here each body's
// dimensions are its own), and the solve closes the joints again. Crank angles are counted from
// the drawing, as everywhere, so a dimension that keeps the crank's drawn direction (its P0-P1)
// keeps what crank angle 0 means.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/geometry.h"
#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "linkage/status.h"

namespace linkage {

// What a dimension is and what it moves per unit (the derivative of the drawing with respect to
// it). The dimensions of a mechanism (dimensions() below), named as the editor names them:
// - a moving body of points P0, P1, ... (file order, as linkage/edits.h's sideLengths):
//   `body.P0-P1` (P0 stays, P1 keeps its direction from P0); each later point Pk by its
//   distances from the first two, `body.P1-Pk` then `body.P0-Pk` (for three points: the
//   triangle's three sides in sideLengths' order), Pk keeping its side of the line P0P1. A
//   point on the line P0P1 (to 1e-3 rad seen from it) or on P0 or P1, which two distances do
//   not place, is given by its coordinates along and across P0->P1 from P0 instead:
//   `body.Pk.along`, `body.Pk.across`. A body whose P0 and P1 coincide: each later point's
//   `body.Pk.x`, `body.Pk.y`.
// - each ground point: `ground.O.x`, `ground.O.y` (the ground's own name).
// - each straight slot: `body.slot.offset` (moved along its normal, mm; its value the line's
//   signed distance from the body's first point, the ground's from the drawing's origin) and
//   `body.slot.angle` (turned about its first end, degrees).
// - each arc slot of a planar machine: `body.slot.centre.x`, `.y` (the arc moved, its three
//   points with it; the value from the body's first point, the ground's from the drawing's
//   origin) and `body.slot.radius` (about its centre, its three points along their radii).
// - each gear: `A-B.ratio` (the bodies of its points a and b).
// - each cam (named by its follower's point b, as `cam:follower.R`): each segment's rise with a
//   law, `cam:follower.R.segmentK.rise` (K from 1, the Cam dock's rows; mm, or degrees for an
//   oscillating follower), the next segment moving the other way round the turn taking the
//   difference (the dock's rule: linkage/cam_edits.h, withCamRise), the base circle's radius
//   `cam:follower.R.base` (the follower moved to its new lowest position, as setCamBase moves
//   it) and a roller's `cam:follower.R.roller` (the same cam: the base kept, the follower moved
//   out as far; the motion sees base + roller, the pitch curve's, alone).
// In space (linkage/space.h; docs/sensitivity.md, "In space") a body's dimensions are in its
// plane's coordinates, and there are besides (after all of the above):
// - each ground point's `ground.O.z`; each moving point with a third number or at a ball rod's
//   end: `body.P.depth` (along its plane's normal);
// - each ball rod's `ball-rod:A.P.length` (named by its end a, as its force column is);
// - each plane's `planes.NAME.origin.x`, `.y`, `.z` (its bodies move with it in the world);
// - a ground slot's offset and angle are taken in the plane of the block running in it (moved
//   along its normal in that plane, turned about that plane's normal).
struct Dimension {
  enum class Unit { Mm, Deg, Ratio };
  std::string name;
  double value = 0;  // as drawn: mm, degrees or a ratio
  Unit unit = Unit::Mm;
  std::vector<std::pair<PointId, Vec2>> points;  // d(sketch position) per unit
  struct SlotMove {
    SlotId slot;
    Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();  // d(its ends) per unit
    double z0 = 0, z1 = 0;                      // d(the ground's ends' z) per unit, in space
    std::optional<Vec2> mid = std::nullopt;     // an arc's: d(its point on the way) per unit
    double zm = 0;                              // d(the ground's arc's z on the way), in space
  };
  std::vector<SlotMove> slots;
  JointId ratioOf;  // a gear whose ratio it is
  // In space: d(a moving point's depth along its plane's normal, a ground point's z) per unit.
  std::vector<std::pair<PointId, double>> depths;
  JointId lengthOf;  // a ball rod whose length it is
  // A plane's origin: its bodies' centres of mass move with their points (every other dimension
  // leaves each centre where it is drawn in its body).
  bool carriesMasses = false;
  // A cam's: d(each segment's rise, the file's unit) and d(its base, mm) per unit; its roller
  // (camBase then d(base + roller), the base kept).
  JointId camOf;
  std::vector<double> camRises;
  double camBase = 0;
  bool camRoller = false;
};

std::vector<Dimension> dimensions(const Mechanism& m);
// Whether a body's later point c is measured along and across its P0->P1 (a, b) rather than by
// its distances from them (dimensions() names it Pk.along, Pk.across): seen from c, a and b
// (nearly) on one line, or c at one of them. A change of P0-P1 keeps such a point's along and
// across.
bool measuredAlongAcross(const Vec2& a, const Vec2& b, const Vec2& c);

namespace internal {
// A cam row's constants as one dimension moves the drawing (per unit): the follower's b in its
// own frame; the lowest position of b and the rise direction u in the guide's frame
// (translating), or the follower's turn to its lowest position (oscillating). From the drawing
// alone, so worked out once (Sensitivity::prepare).
struct CamMove {
  Vec2 b = Vec2::Zero(), lowest = Vec2::Zero(), along = Vec2::Zero();
  double turn = 0;
  // An oscillating flat face's normal (CamRow::face, unit(b - a) at the lowest position), turned
  // in the follower's frame: what the contact row reads (linkage/force_sensitivity.h).
  double faceTurn = 0;
};
}  // namespace internal

// The derivatives of the motion at a Kinematics' current pose with respect to dimensions.
// prepare() refuses (BadModel, naming the joint or the reason) what it cannot differentiate yet:
// a kind it does not know, a cam on a machine in space or whose follower's slot is on the
// follower, and a spatial model (planes) or a ball rod unless the caller
// reads the world's x, y, z (point3() and the rest: Space::World; point() and the rest give a
// spatial model's point in its plane class's frame, which a caller of the drawing's x and y
// would misread). At a singular position (no derivativesValid()) at() fails: the motion's
// derivatives are unbounded there.
class Sensitivity {
 public:
  enum class Space { Refuse, World };
  Status prepare(const Kinematics& k, std::vector<Dimension> dims, Space space = Space::Refuse);
  // dq/dp at k's current pose: one column a dimension (x, y, theta per moving body).
  Status at(const Kinematics& k);
  const Eigen::MatrixXd& dq() const { return dq_; }
  const std::vector<Dimension>& dims() const { return dims_; }
  // d(position of p)/d(dimension k), mm per unit, at the pose of the last at().
  Vec2 point(const Kinematics& k, PointId p, int dim) const;
  // d(position)/d(dimension k) of the point of body b drawn at sketch position `at`, which the
  // dimension moves by `own` in the drawing (per unit): a point of a slot (linkage/
  // slot_sensitivity.h). A planar model's.
  Vec2 point(const Kinematics& k, BodyId b, const Vec2& at, const Vec2& own, int dim) const;
  // d(velocity of p)/d(dimension k), mm/s per unit at the driver's speed (from dq'/dp: J q' +
  // Phi_phi = 0 differentiated along dq/dp), and d(acceleration)/d(dimension k), mm/s^2 per unit
  // (from dq''/dp: J q'' = gamma differentiated along dq/dp and dq'/dp; NaN when the Kinematics
  // computes no accelerations).
  Vec2 velocity(const Kinematics& k, PointId p, int dim) const;
  Vec2 acceleration(const Kinematics& k, PointId p, int dim) const;
  // d(acceleration)/d(dimension k) of a point fixed in body b's frame at sketch position `at`,
  // which no dimension moves (a centre of mass, a counterweight): mm/s^2 per unit. A planar
  // model's.
  Vec2 acceleration(const Kinematics& k, BodyId b, const Vec2& at, int dim) const;
  // d(body b's angle)/d(dimension k), radians per unit (0 for the ground).
  double angle(const Kinematics& k, BodyId b, int dim) const;
  // d(its angular velocity), rad/s per unit, and d(its angular acceleration), rad/s^2 per unit,
  // at the driver's speed (Kinematics::bodyOmega, bodyAlpha); 0 for the ground.
  double angularVelocity(const Kinematics& k, BodyId b, int dim) const;
  double angularAcceleration(const Kinematics& k, BodyId b, int dim) const;
  // dq'/dp and dq''/dp at the pose of the last at(): one column a dimension (q' = dq/dphi).
  const Eigen::MatrixXd& dqd() const { return dqd_; }
  const Eigen::MatrixXd& dqdd() const { return dqdd_; }
  // d(J w)/d(dimension k) with w held (a vector of coordinates), J the constraint Jacobian at the
  // pose of the last at(), by the kinematics' independent rows (their row map): through it a
  // multiplier's derivative (linkage/force_sensitivity.h).
  Eigen::VectorXd jacobianChange(const Kinematics& k, const Eigen::VectorXd& w, int dim) const;
  // The moves of cam joint `joint`'s row's constants along dimension dim (by Mechanism::joints
  // index; zero for other joints).
  const internal::CamMove& camRowMove(int dim, int joint) const { return camMove_[dim][joint]; }
  // The same in the world (mm, mm/s, mm/s^2 per unit): on a planar model (x, y, 0).
  Vec3 point3(const Kinematics& k, PointId p, int dim) const;
  Vec3 velocity3(const Kinematics& k, PointId p, int dim) const;
  Vec3 acceleration3(const Kinematics& k, PointId p, int dim) const;

 private:
  Vec2 acceleration(const Kinematics& k, int body, const Vec2& s, const Vec2& own, int dim) const;
  std::vector<Dimension> dims_;
  // By dimension, by PointId value: a moving point's move in its class frame and along its
  // normal; a ground point's in the world (x, y, z; the drawing's x, y and 0 on a planar model).
  std::vector<std::vector<Vec3>> pointMove_;
  Eigen::MatrixXd dq_, dqd_, dqdd_;  // dq/dp, dq'/dp, dq''/dp (q' = dq/dphi)
  // By dimension, by joint index: a cam row's constants' moves (analysis/sensitivity.cpp).
  std::vector<std::vector<internal::CamMove>> camMove_;
};

}  // namespace linkage
