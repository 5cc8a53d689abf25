// The constraint forces of a mechanism solved group by group (the closed-form path of
// linkage/dynamics.h): J^T lambda = Q taken from the outermost group to the crank, each group's
// rows from its own bodies' balance less what the groups after it put on them, as a designer
// does by hand.
//
// A dyad (two bodies, RRR or RRP: the rows that touch only its first body, those that join the
// two, those that touch only its second, two scalar rows each) is solved as by hand too: each
// body's balance of moments about its outer joint (the null vector n of that joint's 2 x 3 block,
// the cross product of its two rows, removes the outer joint's unknowns) gives two equations in
// the middle joint's two unknowns,
//
//   (C1 n1) . lambda_mid = n1 . b1,   (C2 n2) . lambda_mid = n2 . b2,
//
// then each outer joint's from the two of its body's three equations whose 2 x 2 minor is the
// largest (the largest component of n: the best conditioned pair). Two 2 x 2 solves instead of a
// 6 x 6 elimination. A single body held by a two-row joint and one more row (a crank and its
// driver) likewise: its moments about that joint give the other row's, then the joint's. Any
// other group: Gaussian elimination with partial pivoting on its few rows.
//
// Rows enter as forces at points (system/system.h, RowForce), not as Jacobian blocks: a row's
// column of J^T on a body is formed only where it is used.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "elements/body_view.h"
#include "structure/decomposition.h"
#include "system/system.h"

namespace linkage {

class GroupForces {
 public:
  // For the system's decomposition (closed-form: every body in a group).
  void prepare(const System& sys, const Decomposition& d);
  // lambda (sys.nRows) from Q (3 per body: force N, moment N mm at the frame origin) at the
  // views' pose; false at a singular group (lambda then holds nothing meaningful).
  bool solve(const System& sys, const std::vector<BodyView>& views, const Eigen::VectorXd& Q,
             Eigen::VectorXd& lambda);
  // After solve(): row r's (index in System::cons) forces at that pose; nullptr for a row no
  // group holds.
  const RowForce* force(int r) const {
    return plannedOf_[r] >= 0 ? &forces_[plannedOf_[r]] : nullptr;
  }

 private:
  using Row3 = Eigen::Matrix<double, 1, 3>;
  // One scalar row of a planned row's J^T on one of its bodies, found once in prepare().
  struct Use {
    int row = 0;    // planned row (index in rows_ and forces_)
    int e = 0;      // its scalar row
    int k = 0;      // the body's slot in the row
    int body = 0;   // the system body (moving: the ground's share is not needed)
    int local = 0;  // the body's place in the group (-1 outside it)
    int o = 0;      // the scalar row's place among the group's
  };
  struct PlannedRow {
    int row = 0;                  // index in System::cons
    int local[3] = {-1, -1, -1};  // where each of its bodies is in the group, -1 outside it
  };
  struct Plan {
    int first = 0, count = 0;  // its rows in rows_; a dyad's: the first body's own, the shared,
                               // the second body's own
    int bodies[4] = {-1, -1, -1, -1};
    int nBodies = 0;  // more than 4: solve() fails (the caller solves J whole)
    int scalars = 0;  // its scalar rows; their system rows from lambdaRow_[firstScalar]
    int firstScalar = 0;
    int firstUse = 0, uses = 0;      // in uses_: on its own bodies, in scalar order
    int firstSpill = 0, spills = 0;  // in spills_: on the bodies of the groups solved later
    bool dyad = false;      // two bodies, two scalar rows each own and two shared (that order)
    bool heldBody = false;  // one body, a two-row joint first and one more row
  };

  static int dyadPart(const PlannedRow& r);
  void plan(const System& sys, Plan& p);
  Row3 on(const Use& u) const { return forces_[u.row].on(u.k, u.e, (*views_)[u.body + 1].r); }
  Row3 remaining(int body) const;  // Q - S of a body
  bool solveDyad(const Plan& p);
  bool solveHeldBody(const Plan& p);
  template <int N>
  bool solveGroup(const Plan& p);
  void distribute(const Plan& p, const double* x);

  std::vector<PlannedRow> rows_;
  std::vector<Plan> plans_;  // outermost group first
  std::vector<Use> uses_, spills_;
  std::vector<int> lambdaRow_;                    // by scalar row in plan order: its system row
  std::vector<RowForce> forces_;                  // by planned row
  std::vector<int> plannedOf_;                    // by row of System::cons: its planned row
  const std::vector<BodyView>* views_ = nullptr;  // during solve()
  Eigen::VectorXd S_;                             // what the solved rows put on each body
  const Eigen::VectorXd* Q_ = nullptr;            // during solve()
  Eigen::VectorXd* lambda_ = nullptr;
};

}  // namespace linkage
