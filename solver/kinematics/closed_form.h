// Closed-form kinematics for mechanisms built from a driven crank, gear-coupled bodies, cams'
// followers and dyads (Assur groups of class II), solved one group after another from the ground
// outwards, in the order of the structural decomposition (structure/decomposition.h), as a designer
// does by hand. The same equations as the general solve, ordered into a block-triangular sequence:
//
//   crank  body B pinned to a known body K at the driver:  theta_B = theta_K +- sigma phi,
//          r_B from the pin.
//   geared body B pinned to a known body K, its angle fixed by a coupling's row (a gear or belt)
//          over known bodies: theta_B = (value - sum of c_k theta_k over the others) / c_B, and
//          likewise its rates; r_B from the pin.
//   RRR    bodies B1, B2: B1 pinned to known K1 at P1, B2 to known K2 at P2, B1-B2 pinned at C.
//          C = intersection of circles (P1, d1) and (P2, d2), on the side the drawing chose.
//          Velocities: w1 perp(C - P1) - w2 perp(C - P2) = v_P2 - v_P1 (2 x 2), and likewise
//          for accelerations with the centripetal terms on the right.
//   RRP    rod B1 pinned to known K1 at P1, block B2 pinned to B1 at C and sliding in a slot of
//          known K2 (angle of B2 = angle of K2): C = intersection of circle (P1, d1) with the
//          slot's line shifted by the block's offset; w1 perp(C - P1) - s' dir = V0 - v_P1.
//   RP     body B1 pinned to known K1 at P1 with a point C in a slot of known K2 (pin-in-slot):
//          the RRP equations without a block.
//   RC     the same in an arc slot: C on the circle (centre P2 on K2, radius d2), the RRR
//          equations with the radius as the second link (its angle is not a body's).
//   PR     body B1 pinned to known K1 at P1 whose straight slot (point u, normal n in B1's
//          frame) holds a point C of known K2: with D = C - P1 and k = n . (u - p1), the slot's
//          normal N = R n keeps N . D = k, so N = (k D + sigma sqrt(|D|^2 - k^2) perp D) / |D|^2;
//          omega = -N . D' / (perp N . D), and alpha from the second derivative.
//   RS     body B1 pinned to known K1 at P1 whose point C (u = C - P1 on B1, depth z1 along
//          its class's normal) a ball rod of length l keeps from a known body's point W2, in
//          space (an RSSR's rocker). With B1's class axes X, Y, O and normal N,
//          E1 = ux X + uy Y, E2 = -uy X + ux Y and Q = O + P1x X + P1y Y + z1 N - W2:
//          |Q + cos t E1 + sin t E2|^2 = l^2, i.e. a cos t + b sin t = c with a = 2 Q . E1,
//          b = 2 Q . E2, c = l^2 - |Q|^2 - |u|^2: t = atan2(b, a) +- acos(c / sqrt(a^2 + b^2)),
//          the drawn sign kept. With D = W1 - W2 and g = (D . X, D . Y):
//          omega g . perp(R u) = D . (V2 - E vP1), and alpha from D' . D' + D . D'' = 0.
//   cam    follower F moved by a cam's row (elements/cam_row.h) over the known cam C and guide
//          G, held to G by its own joint; theta = angle(R_G^T R_C), theta' = w_C - w_G, and the
//          programme's s, s', s'' at theta give s' theta' and s'' theta'^2 + s' theta''.
//          Oscillating (F pinned to G, turning by sign s): theta_F = theta_G + sign s,
//          w_F = w_G + sign s' theta', alpha_F likewise; r_F from the pin. Translating (a
//          slider: F keeps G's angle): r_F from two lines turning with G, the cam's (normal
//          N1 = R u along the slot: N1 . (r_F + R b_F - Q1) = s) and the slot's (normal N2:
//          N2 . (r_F + R a - Q2) = 0), a 2 x 2 solve; their first and second derivatives
//          (N' = w_G perp N) give v_F and a_F by the same matrix. No branch: it has no mirror.
//   core   one body held by three scalar conditions to known bodies, its slider blocks
//          eliminated (core_group.h): a 3 x 3 Newton, the one group here that iterates.
// Every group's unknowns follow from known bodies, so no factorisation of the whole system is
// needed: a step costs a few dozen flops per body. The branch (which of the two
// intersections) is the drawn one and never changes: where a group cannot close (a negative
// discriminant) or its 2 x 2 system is singular, the plan reports failure and the general solver
// takes over and explains it.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "kinematics/core_group.h"
#include "kinematics/motion.h"
#include "linkage/model.h"
#include "structure/decomposition.h"
#include "system/system.h"

namespace linkage {

class ClosedFormPlan {
 public:
  // A plan when every group of the decomposition `d` of `sys` is of these kinds (no redundant
  // joints, no held coordinates), with branches taken from the assembled configuration `at`
  // (its positions); nullopt otherwise (closed_form_build.cpp). `joints`: Mechanism::joints'
  // size.
  static std::optional<ClosedFormPlan> build(const Decomposition& d, const System& sys, int joints,
                                             const Motion& at);

  // The motion at driver angle phi (positions, d/dphi and d2/dphi2 of every coordinate) from the
  // previous one (whole turns are counted from it, branch crossings and core groups predicted
  // from its rates). False where a group cannot close or is singular; next is then partial and
  // must be discarded.
  // With accelerations false, the groups' acceleration solves are left out (NaN instead).
  bool solve(const System& sys, const Motion& prev, double phi, Motion& next,
             bool accelerations = true) const;

  // After an edit of dimensions (the same topology, so the same groups in the same order) whose
  // plan before the edit was `before`: the groups whose geometry changed, and those that
  // depend on one, are solved again at prev.phi from prev (the pose before the edit, in the
  // new body frames), on the branches of `before`; every other group keeps its bodies'
  // motion from prev exactly. Returns the number of groups solved; -1 where the plans differ
  // in their groups, or a group cannot close or is singular there.
  // `reframed` marks the bodies (system indices) whose frames moved: their groups are solved
  // again whatever their geometry.
  int resolveEdited(const System& sys, const ClosedFormPlan& before, const Motion& prev,
                    Motion& next, const std::vector<char>& reframed);

  int groups() const { return static_cast<int>(groups_.size()); }
  // The group that solves body b (a system body index), -1 for none; the group a joint (an
  // index in Mechanism::joints) belongs to.
  int groupOfBody(int b) const { return b >= 0 ? bodyGroup_[b] : -1; }
  int groupOfJoint(int j) const { return j >= 0 ? jointGroup_[j] : -1; }
  // Whether a group has a second assembly (its mirror closure): every kind but the crank, a
  // geared body and a cam's follower. A
  // dyad's joint C is the other intersection of its two circles (RRR) or of its circle and line
  // (RRP, RP); a core's pose the other root of its rows (core_group.h: corePose).
  bool hasMirror(int g) const {
    return g >= 0 && groups_[g].kind != Kind::Crank && groups_[g].kind != Kind::Geared &&
           groups_[g].kind != Kind::Cam;
  }
  // The group's unknown bodies.
  std::vector<int> bodiesOf(int g) const;

  // Puts group g on its other assembly at prev.phi: g is solved again on the other branch, and
  // every group that depends on it on its own branch, from prev (the motion now); other bodies
  // keep prev's motion. The plan keeps the new branch. False, with the plan unchanged, where
  // g has no mirror, or a group cannot close or is singular on the other assembly there.
  bool flip(int g, const System& sys, const Motion& prev, Motion& next);

 private:
  class Builder;
  enum class Kind { Crank, Geared, RRR, RRP, RP, RC, PR, RS, Cam, Core };
  // Cam: b1 the follower, k1 its guide, k2 the cam; p1k, p1 the oscillating follower's pin (on
  // k1, on b1); c2, p2 the cam row's points (b on b1, as drawn on k1); translating, c1 and p2k
  // the slot row's points on b1 and on k1 (either may be the slot's), n its normal.
  struct Group {
    Kind kind = Kind::Crank;
    int b1 = -1, b2 = -1;  // unknown bodies (b2 only for RRR and RRP)
    int k1 = -1, k2 = -1;  // known bodies they attach to (-1 ground)
    int k3 = -1;           // Geared: k2, k3 the other bodies of the coupling's row
    int angles = -1;       // Geared: the coupling's row (System::cons)
    Vec2 p1k = Vec2::Zero(), p1 = Vec2::Zero();  // pin to k1: on k1, on b1
    Vec2 c1 = Vec2::Zero(), c2 = Vec2::Zero();   // the joint C: on b1 (and on b2 for RRR, RRP)
    Vec2 p2 = Vec2::Zero(), p2k = Vec2::Zero();  // RRR: pin to k2: on b2, on k2 (RC: centre)
    Vec2 u = Vec2::Zero(), n = Vec2::Zero(),
         d = Vec2::Zero();   // RRP, RP: slot point, unit normal and direction on k2 (PR: on b1)
    Vec2 q2 = Vec2::Zero();  // RRP: the block's point on the slot line
    Rot rot1, rot2;          // directions of (c1 - p1) and (c2 - p2) on their bodies
    double d1 = 0, d2 = 0;   // and their lengths (RS: d2 the rod's)
    double sign = 1;         // Crank: +-sigma; RRR, RRP, RP, RC, RS: the drawn branch
    int f1 = 0, f2 = 0;      // RS: the plane classes (System::frames) of C and of W2's body
    double z1 = 0, z2 = 0;   // RS: their depths along those classes' normals
    int core = -1;           // Core: index into cores_
    std::shared_ptr<const CamRow> cam;  // Cam: the programme, follower and slot direction
  };
  // Solves one group into next from prev (h radians of crank later, crank rotation `crank`).
  // A jump (h = 0, another assembly of it or of a group it depends on): no continuity with
  // prev is asked for; whole turns are the nearest to prev's angles.
  bool solveGroup(const Group& g, const System& sys, const Motion& prev, double h, const Rot& crank,
                  Motion& next, bool jump = false) const;
  // The dyads' joint C from the pin P1 on k1 (p1: its position, velocity, acceleration) and
  // `Cpred` (where the motion carries C; refused when it is on the other side of the branch
  // line): on two circles (RRR, RC) or a circle and a line (RRP, RP). b1's motion follows
  // from out; the second body's, when there is one, is set here.
  struct Dyad {
    Vec2 u1 = Vec2::Zero();  // C - P1
    double w1 = 0, al1 = 0;
  };
  // (Inlined into solveGroup: a call each would cost the slider-crank's step 5%.)
  [[gnu::always_inline]] inline bool circles(const Group& g, const Motion& prev, const Vec2& Cpred,
                                             const PointState& p1, Motion& next, bool jump,
                                             Dyad& out) const;
  [[gnu::always_inline]] inline bool line(const Group& g, const Vec2& Cpred, const PointState& p1,
                                          Motion& next, bool jump, Dyad& out) const;
  // RS: b1 from its pin and the ball rod to a known body.
  bool rocker(const Group& g, const System& sys, const Motion& prev, double h, const PointState& p1,
              Motion& next, bool jump) const;
  // RS: the side (+-1) of the branch line that b1's rotation R is on, 0 on it.
  double rockerSide(const Group& g, const System& sys, const Motion& m, const Rot& R) const;
  // Cam: the follower from its guide and its cam (closed_form_cam.cpp).
  bool follower(const Group& g, const Motion& prev, Motion& next, bool jump) const;
  // PR: b1 from its pin and the known point in its slot.
  bool slotted(const Group& g, const Motion& prev, double h, const PointState& p1, Motion& next,
               bool jump) const;
  // Solves again, at prev.phi, the groups from `first` on that are `first` or depend on a body
  // marked in `moved` (which gets their bodies); the others keep next's motion. The number of
  // groups solved, -1 where one cannot be.
  int resolveFrom(size_t first, const System& sys, const Motion& prev, Motion& next,
                  std::vector<char>& moved, bool jump, const ClosedFormPlan* before = nullptr,
                  const std::vector<char>* reframed = nullptr) const;
  static bool sameGeometry(const Group& a, const Group& b, const ClosedFormPlan& pa,
                           const ClosedFormPlan& pb);
  // The group's unknown bodies, then the known bodies it reads (-1 for ground).
  void bodiesOf(const Group& g, std::vector<int>& unknown, std::vector<int>& known) const;
  // Geared: theta, its rate and acceleration from the coupling's row over the known bodies.
  static void coupledAngle(const Group& g, const System& sys, const Motion& next, double& theta,
                           double& w, double& al);

  std::vector<Group> groups_;
  std::vector<CoreGroup> cores_;
  std::vector<int> bodyGroup_, jointGroup_;
};

}  // namespace linkage
