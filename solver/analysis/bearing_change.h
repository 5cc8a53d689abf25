// A bearing's out-of-plane reaction on a machine in space (analysis/space_forces.h) and its
// derivative with respect to a dimension (linkage/force_sensitivity.h). The bearing of body k
// takes the body's load W = sum over the forces F on it (class frame: x, y, along the normal)
// at rel = (P - B, d - d_B) from the bearing's place B at its depth d_B:
//
//   W  = (F_n, (rel x F)_x, (rel x F)_y)                         N, N mm
//   dW = (dF_n, (drel x F + rel x dF)_x, (drel x F + rel x dF)_y)
//
// The forces, as SpaceForces::reactions() sums them: the body's in-plane generalized force Q_k
// at its depth (the mean of its points'), its weight's normal part at its centre of mass, each
// other joint's row's in-plane force -lambda_r J_r at the depth of that joint's point on it, a
// ball rod's pull -+lambda D / l at its end. Their changes: dQ, the multipliers' whole change
// dlambda = J^-T (dQ - dJ^T lambda) (every row's force on the body moves the load, not only the
// bearing's own), the rows' turn dJ, the points' moves in the class frames (held by the
// sensitivities: a dimension moves the world in them), the body's depth with its points', a
// plane's origin carrying the centres of mass, a rod's length (d(D / l) = dD / l - D dl / l^2).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <optional>
#include <vector>

#include "analysis/space_forces.h"
#include "linkage/kinematics.h"
#include "linkage/sensitivity.h"

namespace linkage::internal {

// The joints' balance at a pose: J (forcesJacobian, by the kinematics' independent rows), its
// factors, the multipliers (J^T lambda = Q) and the generalized forces.
struct Balance {
  const Eigen::MatrixXd& J;
  const Eigen::PartialPivLU<Eigen::MatrixXd>& lu;
  const Eigen::VectorXd& lambda;
  const Eigen::VectorXd& Q;
};

// Its change along one dimension: J's (a column a coordinate), Q's and the multipliers'.
struct BalanceChange {
  int dim = 0;
  Eigen::MatrixXd dJ;
  Eigen::VectorXd dQ, dlambda;
};

BalanceChange balanceChange(const Kinematics& k, const Sensitivity& s, const Balance& b, int dim,
                            const Eigen::VectorXd& dQ);

// A weight on a body as the load reads it: its mass (kg) and its first moment about the body's
// frame origin (kg mm, the class frame's axes), and that moment's change along a dimension.
struct BodyWeight {
  double kg = 0;
  Vec2 moment = Vec2::Zero(), dMoment = Vec2::Zero();
};

class BearingChange {
 public:
  // Joint ji, if on a machine in space it is a body's bearing (else bears() is false).
  BearingChange(const Kinematics& k, int ji);
  bool bears() const { return body_ >= 0; }
  // The derivatives of its normalN and tiltNm (as linkage/dynamics.h reports them) along c's
  // dimension into out's.
  void change(const Kinematics& k, const Sensitivity& s, const Balance& b, const BalanceChange& c,
              JointReaction& out) const;
  // A share of it at a held pose (a counterweight's, linkage/force_sensitivity.h): what the
  // forces b.Q alone, balanced by b.lambda, and a weight w on body `body` put on the bearing;
  // and that share's change along c's dimension (w.dMoment the weight's).
  void share(const Kinematics& k, const Balance& b, int body, const BodyWeight& w,
             JointReaction& out) const;
  void shareChange(const Kinematics& k, const Sensitivity& s, const Balance& b,
                   const BalanceChange& c, int body, const BodyWeight& w, JointReaction& out) const;

 private:
  struct Moves;
  struct Load;
  void load(const Kinematics& k, const Balance& b, const BalanceChange* c, const Moves* mv,
            const BodyWeight& w, Load& out) const;
  void put(const Vec3& W, JointReaction& out) const;
  void rowLoads(const Kinematics& k, const std::vector<BodyView>& views, const Balance& b,
                const BalanceChange* c, const Moves* mv, const Vec3& at, const Vec3& dAt,
                Load& out) const;
  void rodLoad(const Kinematics& k, const std::vector<BodyView>& views, const Balance& b,
               const BalanceChange* c, const Moves* mv, const Row& r, int e, const Vec3& at,
               const Vec3& dAt, Load& out) const;
  std::vector<std::optional<SpaceForces::BodyMass>> mass_;
  SpaceForces space_;
  int joint_ = -1, body_ = -1;
  double sign_ = 1;  // -1 where the joint's point a is on the body (the reaction on it is -W)
};

}  // namespace linkage::internal
