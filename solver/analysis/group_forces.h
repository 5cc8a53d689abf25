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
// 6 x 6 elimination. Any other group: Gaussian elimination with partial pivoting on its few rows.
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

 private:
  struct PlannedRow {
    int row = 0;                  // index in System::cons
    int local[3] = {-1, -1, -1};  // where each of its bodies is in the group, -1 outside it
  };
  struct Plan {
    int first = 0, count = 0;  // its rows in rows_; a dyad's: the first body's own, the shared,
                               // the second body's own
    int bodies[4] = {-1, -1, -1, -1};
    int nBodies = 0;      // more than 4: solve() fails (the caller solves J whole)
    int dyadShared = -1;  // a dyad: the index in its rows of the first shared row; else -1
    int dyadOwn2 = -1;    // a dyad: of the first row of the second body's own
  };
  using Block = Eigen::Matrix<double, 2, 9>;

  static int dyadPart(const PlannedRow& r);
  bool solveDyad(const System& sys, const Plan& p);
  template <int N>
  bool solveGroup(const System& sys, const Plan& p);
  void distribute(const System& sys, const Plan& p, const double* x);
  void jacobians(const System& sys, const std::vector<BodyView>& views, const Plan& p);

  std::vector<PlannedRow> rows_;
  std::vector<Plan> plans_;  // outermost group first
  std::vector<Block> blocks_;
  Eigen::VectorXd S_;                   // what the solved rows put on each body
  const Eigen::VectorXd* Q_ = nullptr;  // during solve()
  Eigen::VectorXd* lambda_ = nullptr;
};

}  // namespace linkage
