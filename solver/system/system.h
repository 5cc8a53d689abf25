// A Mechanism compiled to numbers: body frames, the rows every element compiles to
// (elements/rows.h, as its kind says: linkage/elements.h), and evaluation of the constraint
// equations Phi(q, phi), their Jacobian J and the acceleration right-hand side gamma.
//
// Coordinates: three per moving body, q = (x, y, theta) of a frame whose origin is the centroid of
// the body's drawn geometry and whose angle is 0 as drawn. A point's local vector is its sketch
// position minus that centroid. Centroid frames keep the theta columns of J of the size of the
// body, not of its distance from the sketch origin, which keeps J well scaled for rank decisions
// and makes "move as little as possible" a meaningful weighted norm.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <vector>

#include "elements/body_view.h"
#include "elements/rows.h"
#include "linkage/model.h"
#include "linkage/status.h"

namespace linkage {

struct System {
  std::uint32_t owner = 0;  // Mechanism::owner(): ids of other mechanisms are unknown here
  int nBodies = 0;          // moving bodies; coordinates are 3 * nBodies
  std::vector<BodyId> bodyIds;
  BodyId groundId;
  std::vector<Vec2> frameOrigin;     // sketch position of each moving body's frame
  std::vector<double> bodyWeightXY;  // weights of the "move as little as possible" norm
  std::vector<double> bodyWeightTheta;
  std::vector<Row> cons;          // joint rows in file order, then the driver, then holds
  std::vector<JointId> jointIds;  // Mechanism::joints order
  int nRows = 0;
  int nJointRows = 0;  // rows from joints only (no driver, no holds)
  int driverRow = -1;
  // Some rows react otherwise than their equations say (a cam's: by its contact; rowJacobian(),
  // rowForce()): the forces cannot reuse the kinematics' factors of J.
  bool contactRows = false;
  double size = 1;  // L: diagonal of the drawing's bounding box, the length scale of everything
  // The frames of the plane classes (linkage/space.h): a body's q is planar in its class's;
  // frames[0] is the drawing plane's class. classOf[k]: body k's class.
  std::vector<Plane> frames{Plane{"drawing", Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), {}}};
  std::vector<int> classOf;
  std::vector<double> pointDepth;  // by PointId value: along its class's normal (in space only)

  bool hasDriver = false;
  double sigma = 1;  // +1 ccw, -1 cw
  double rpm = 0;
  double startRad = 0;  // start offset, in the driving direction

  int nCoords() const { return 3 * nBodies; }
  int bodyIndex(BodyId id) const;  // -1 for ground or unknown
  const PointLocation* point(PointId id) const;

  // Indexed by PointId value (ids are small and dense): a lookup per query, no hashing.
  std::vector<PointLocation> points;
  std::vector<char> hasPoint;
  std::vector<int> bodyIndexById;  // likewise by BodyId value; -1 for ground and unknown ids
};

// Compiles the mechanism; a reference the model cannot resolve ends in BadModel with its place.
std::optional<System> compile(const Mechanism& m, Status& status);

// Adds a row holding coordinate `col` at `value` (used for idle freedoms).
void addHold(System& sys, int col, double value);

// Body poses (and velocities, when v is given) as the joints see them.
void makeViews(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd* v,
               std::vector<BodyView>& views);

// Sets the velocities of views made by makeViews (no sin or cos evaluated again).
void setVelocities(const System& sys, const Eigen::VectorXd& v, std::vector<BodyView>& views);

// Rows are written through `rowMap` (full row -> output row, -1 to skip), so that a solve can use
// the independent rows only without copying. phi is the driver angle (crank angle + start).
void evalResidual(const System& sys, const std::vector<BodyView>& views, double phi,
                  const std::vector<int>& rowMap, Eigen::VectorXd& out);
void evalJacobian(const System& sys, const std::vector<BodyView>& views,
                  const std::vector<int>& rowMap, Eigen::MatrixXd& J);
// J in compressed sparse storage, for large systems: its pattern is fixed by the joints alone,
// and the joints' Jacobian functions write their entries in the same order at every
// evaluation, so the storage slot of each write is found once and an evaluation is a sequence
// of indexed additions (no search, no pattern change under a factorisation that analysed it).
struct SparseJacobian {
  Eigen::SparseMatrix<double> J;
  std::vector<int> slot;  // value index of each write, in write order
};
// The pattern of the mapped rows of J (`rows` of them), zeros included.
SparseJacobian sparseJacobian(const System& sys, const std::vector<int>& rowMap, int rows);
void evalJacobian(const System& sys, const std::vector<BodyView>& views,
                  const std::vector<int>& rowMap, SparseJacobian& J);
// One row block's Jacobian at the views: its rows() rows, three columns (x, y, theta) for each of
// body[0..2] in order, zero for the ground and unused bodies (forces: the general path). A Cam
// row's is its contact's (elements/cam_row.h): what its reaction is made of.
Eigen::Matrix<double, 2, 9> rowJacobian(const System& sys, const std::vector<BodyView>& views,
                                        const Row& r);

// The same row block's J^T as forces, per unit multiplier, at a pose where the row holds (forces,
// group by group: a force at a point is cheaper to form and to apply than a 2 x 9 block). A
// Coincident, OnLine or OnCircle row's scalar row e is the force u[e] at P on body[0] and -u[e]
// at P on body[1] (its virtual work is the row's gradient); an Angles row is the couple
// couple[k] (N mm) on body[k]; a Cam row its contact's force u[0] at the contact P on the
// follower body[0], -u[0] there on the cam body[1], nothing on its guide body[2].
struct RowForce {
  Vec2 P = Vec2::Zero();
  Vec2 u[2] = {Vec2::Zero(), Vec2::Zero()};
  double couple[3] = {0, 0, 0};
  bool isCouple = false;
  // A Distance3 row: its two ends are two points, each in its own class frame: the force u[0]
  // at P on body[0], -u[1] at P1 on body[1].
  bool twoEnds = false;
  Vec2 P1 = Vec2::Zero();
  // Scalar row e's generalized force on body[k] (whose frame origin is at r): x, y, the moment
  // about r.
  Eigen::Matrix<double, 1, 3> on(int k, int e, const Vec2& r) const {
    if (isCouple) return Eigen::Matrix<double, 1, 3>(0, 0, couple[k]);
    if (k > 1) return Eigen::Matrix<double, 1, 3>::Zero();  // a cam's guide
    if (twoEnds) {
      const Vec2 f = k == 0 ? u[0] : Vec2(-u[1]);
      return Eigen::Matrix<double, 1, 3>(f.x(), f.y(), cross((k == 0 ? P : P1) - r, f));
    }
    const Vec2 f = k == 0 ? u[e] : Vec2(-u[e]);
    return Eigen::Matrix<double, 1, 3>(f.x(), f.y(), cross(P - r, f));
  }
};
// (Not for a Hold row, which no group holds.)
void rowForce(const System& sys, const std::vector<BodyView>& views, const Row& r, RowForce& f);

// gamma with the views' velocities; J qdd = gamma.
void evalGamma(const System& sys, const std::vector<BodyView>& views,
               const std::vector<int>& rowMap, Eigen::VectorXd& out);

// Global position of a point, and its velocity and acceleration given body velocities (v) and
// accelerations (a) in q layout.
Vec2 pointPosition(const System& sys, const Eigen::VectorXd& q, const PointLocation& p);
Vec2 pointVelocity(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   const PointLocation& p);
Vec2 pointAcceleration(const System& sys, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& a, const PointLocation& p);

// Each body's rotation (cos and sin of its angle) at q.
std::vector<Rot> rotations(const System& sys, const Eigen::VectorXd& q);

// The sketch configuration: every body at its drawn pose.
Eigen::VectorXd sketchCoordinates(const System& sys);

}  // namespace linkage
