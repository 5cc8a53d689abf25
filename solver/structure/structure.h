// Structural analysis of a compiled system at one configuration: Gruebler count, rank of the
// joint equations, redundant joints, whether the driver moves anything, and freedoms the driver
// leaves (with the coordinates held to remove idle ones).
//
// Rank is decided on J with its theta columns divided by the mechanism size, so that every entry
// is O(1), by Gram-Schmidt over the rows in file order: a row that lies in the span of the rows
// before it is dependent, so the later of two joints that say the same thing is the one named.
// That is dense and cubic in the number of coordinates; from `sparseFrom` coordinates on, the
// common case (joint rows and driver row all independent, as many as coordinates) is proved by a
// sparse test first (independent_rows.h), which gives the same Structure the Gram-Schmidt would;
// anything else (a redundant joint, a freedom left, a borderline position) takes the dense path.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "system/sparse_lu.h"
#include "system/system.h"

namespace linkage {

struct Structure {
  int coordinates = 0;
  int jointEquations = 0;
  int gruebler = 0;  // coordinates - joint equations (Gruebler-Kutzbach mobility)
  int rank = 0;      // rank of the joint equations
  int mobility = 0;  // coordinates - rank: the real number of degrees of freedom
  std::vector<int> dependentRows;
  std::vector<int> redundantJoints;  // indices into Mechanism::joints, file order
  bool driverMoves = false;          // the driver row is independent of the joints
  int freeAfterDriver = 0;           // freedoms the driver leaves
  std::vector<int> freeBodies;       // body indices that move with the crank held
  Eigen::MatrixXd nullBasis;         // orthonormal basis (scaled) of motions with the crank held
  std::vector<int> holdCoordinates;  // one coordinate per free freedom that removes it
  std::vector<int> activeRows;       // independent joint rows, then the driver row

  // Does this point move under some motion the driver does not determine?
  bool pointDetermined(const System& sys, const Eigen::VectorXd& q, const PointLocation& p) const;
};

Structure analyzeStructure(const System& sys, const Eigen::VectorXd& q,
                           int sparseFrom = kSparseFrom);

// A one-sentence summary for reports: "6 bodies, 15 coordinates, 14 joint equations, ...".
std::string describe(const Structure& s);

}  // namespace linkage
