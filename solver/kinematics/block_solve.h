// The solve of a block edit (KinematicsState::editBlocks): Newton on the coordinates of a set S
// of bodies only, over the active rows that touch S, every other body held where it is (read,
// never written, so it keeps its motion to the bit). With exactly 3 |S| such rows, the rows
// outside have no S columns and J is block lower-triangular, [[A, 0], [B, J_SS]]: the solve, its
// velocities and accelerations (J_SS x_S = rhs_S - J_S,rest x_rest) and the branch (det J =
// +-det A det J_SS, A untouched) are those of the whole system.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "kinematics/newton.h"
#include "system/dense_lu.h"
#include "system/system.h"

namespace linkage {

struct Block {
  std::vector<int> bodies;  // system body indices, ascending
  std::vector<int> cols;    // their coordinates, three per body
  std::vector<int> rowMap;  // full row -> block row, -1 outside
  int rows = 0;
};

// The active rows (activeRowMap >= 0, holds included) touching `bodies`; none unless there are
// three per body (else the rows outside would not leave S alone, or S would be under-determined).
std::optional<Block> makeBlock(const System& sys, const std::vector<int>& activeRowMap,
                               std::vector<int> bodies);

class BlockSolver {
 public:
  // The sign of det J_SS at q (scaled as Newton scales J), 0 where it is singular.
  int signAt(const System& sys, const Block& b, const Eigen::VectorXd& q);
  // Newton on q's block coordinates, a fresh factorisation each iteration (blocks are small).
  NewtonResult solve(const System& sys, const Block& b, Eigen::VectorXd& q, double phi,
                     const NewtonOptions& opt);
  // The block's q' and q'' given the others' in dq and ddq. False near singular.
  bool derivatives(const System& sys, const Block& b, const Eigen::VectorXd& q, Eigen::VectorXd& dq,
                   Eigen::VectorXd& ddq);
  // Of the last factorisation.
  int detSign() const { return lu_.detSign(); }

 private:
  bool factor(const System& sys, const Block& b, const Eigen::VectorXd& q);
  // Solves J_SS x = rhs - J_S,all known (known's S entries ignored) into out's S entries.
  void solveInto(const Block& b, double L, Eigen::VectorXd& rhs, const Eigen::VectorXd& known,
                 Eigen::VectorXd& out);

  std::vector<BodyView> views_;
  Eigen::MatrixXd Jrows_, Jss_;
  DenseLU lu_;
  Eigen::VectorXd res_;
};

}  // namespace linkage
