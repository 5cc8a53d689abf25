// Assembly of a drawn mechanism that does not close exactly: find the nearby configuration that
// satisfies every joint with the crank at its drawn angle, keeping each body's geometry (bodies
// move rigidly), and report how far it moved. With the crank held the closed configuration near
// the drawing is locally unique, so damped Newton from the drawing finds the nearest one, on the
// drawn assembly branch. When it cannot close, a least-squares fit names the joints that stay
// open and by how much.
#pragma once

#include <Eigen/Core>

#include "kinematics/newton.h"
#include "linkage/kinematics.h"
#include "linkage/model.h"
#include "structure/structure.h"
#include "system/system.h"

namespace linkage {

// q: in, the start (the drawing); out, the assembled configuration.
Status assemble(const Mechanism& m, const System& sys, const Structure& st, NewtonSolver& newton,
                Eigen::VectorXd& q, double phi, AssemblyReport& report);

// After assembly: a redundant joint whose equations do not hold conflicts with the others.
Status checkRedundant(const Mechanism& m, const System& sys, const Structure& st,
                      const Eigen::VectorXd& q, double phi);

// Largest displacement of any point of each body between two configurations.
double largestMove(const Mechanism& m, const System& sys, const Eigen::VectorXd& from,
                   const Eigen::VectorXd& to, BodyId* body);

}  // namespace linkage
