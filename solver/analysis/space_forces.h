// What a machine in space adds to the planar forces of linkage/dynamics.h (docs/dynamics.md,
// "Machines in space").
//
// Every body moves in its plane, so its in-plane dynamics are the planar ones in its plane
// class's frame: its mass, centre of mass (mapped from its plane into the class frame) and
// moment of inertia about the normal as in the plane; gravity's component in the class frame
// (the world's gravity, up to three components) acts on it, and a load in its plane turned into
// that frame. The ball rod's row (distance3.h)
// enters J^T lambda = Q as any row does; its multiplier is the rod's tension:
//
//   Phi = (D . D - l^2) / (2 l),  grad_i Phi = D / l (end i),  -grad_j Phi (end j)
//
// and the constraint forces are -J^T lambda, so the rod pulls end i by -lambda D / l (towards
// j) and end j by +lambda D / l: a pull inwards for lambda > 0, the tension.
//
// Out of its plane a body takes the normal components of the forces on it (gravity's at its
// centre of mass, the rods' at their ends) and the moments about the plane's axes of every force
// on it that acts at a depth (the rods' ends, joints at several depths): its mass and loads act
// at the body's depth, the mean of its points' depths (no product of inertia). That out-of-plane
// load is taken wholly by the body's bearing: its one joint with the ground (pin, slider, pin in a
// slot), reported there as the force along the class normal and the moments about the class's x and
// y axes through the joint's point at its depth. A body with such a load and no joint, or several,
// with the ground is named
// (`unsupported`): its load is in no reaction.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "elements/body_view.h"
#include "linkage/dynamics.h"
#include "linkage/space.h"
#include "system/system.h"

namespace linkage {

class SpaceForces {
 public:
  // The in-plane part of a body's mass, gravity and loads in its class frame (prepare()).
  struct BodyMass {
    double kg = 0, j = 0;   // kg, kg mm^2
    Vec2 c = Vec2::Zero();  // the centre of mass in the body's frame (class axes)
  };

  // Whether the machine is in space; then the mapping of every body, its gravity and bearing.
  // gravity: the world's (m/s^2), three components.
  void prepare(const Mechanism& m, const System& sys,
               const std::vector<std::optional<BodyMass>>& mass, const Vec3& gravity);
  bool on() const { return on_; }
  // Each body's mass as the forces take it (by system body index; none where the file gives
  // none): its centre of mass in its class frame's axes from its frame origin.
  static std::vector<std::optional<BodyMass>> masses(const Mechanism& m, const System& sys);
  const PlaneInClass& placing(int body) const { return placing_[body]; }
  Vec2 gravityIn(int body) const { return gravityIn_[body]; }
  const std::vector<BodyId>& unsupported() const { return unsupported_; }

  // What reactions() reads of body k (analysis/bearing_change.h differentiates it): its bearing
  // (a joint index, -1: none); where the bearing holds it (class frame) and at what depth along
  // the class normal; the depth its mass and loads act at; gravity along the normal (m/s^2);
  // the depth joint j's force on it acts at (its point's there, else its plane's).
  int bearing(int k) const { return bearing_[k]; }
  void bearingPlace(const Mechanism& m, const System& sys, const std::vector<BodyView>& views,
                    int k, Vec2& at, double& depth) const;
  double depth(int k) const { return depth_[k]; }
  double gravityOut(int k) const { return gravityOut_[k]; }
  double depthOn(const Mechanism& m, const System& sys, const Joint& j, int k) const;

  // The shaking force and moment in the world (N, N m about the world's origin), from Q (3 a
  // body: force, moment about its frame origin, in its class frame) and the bodies' normal
  // weights.
  void shaking(const System& sys, const std::vector<BodyView>& views, const Eigen::VectorXd& Q,
               const std::vector<std::optional<BodyMass>>& mass, Vec3& force, Vec3& moment) const;

  // Each ball rod's axial force and each bearing's out-of-plane reaction into out.joints (the
  // in-plane parts already there), from the multipliers at the views' pose; Q as above.
  void reactions(const Mechanism& m, const System& sys, const std::vector<BodyView>& views,
                 const Eigen::VectorXd& lambda, const Eigen::VectorXd& Q,
                 const std::vector<std::optional<BodyMass>>& mass, Forces& out) const;

 private:
  bool on_ = false;
  std::vector<PlaneInClass> placing_;  // by body
  std::vector<Vec2> gravityIn_;        // by body, m/s^2, class frame
  std::vector<double> gravityOut_;     // by body, along the class normal
  std::vector<double> depth_;          // by body: where its mass and loads act, along the normal
  std::vector<int> bearing_;           // by body: its one joint with the ground, or -1
  // By body: its bearing's ground point in its class frame, where the bearing has no point on
  // the body (a ground pin in the body's slot).
  std::vector<Vec2> groundAt_;
  std::vector<BodyId> unsupported_;
};

}  // namespace linkage
