// Rotary driver at a pin: body b turns relative to body a at constant speed.
//
//   Phi     = L (theta_b - theta_a - sigma phi)     sigma = +1 ccw, -1 cw; phi = crank angle +
//   start J       = [ 0, 0, -L | 0, 0, L ]                (joint_slider.h angle row with i = b, j =
//   a) Phi_phi = -L sigma          so J q' = L sigma e_row, with q' = dq/dphi gamma   = 0 (constant
//   speed: J q'' = gamma of the other joints only)
// Kinematics are solved in the crank angle phi: q' and q'' do not depend on the speed, and
// qdot = omega q', qddot = omega^2 q'' for omega = 2 pi rpm / 60.
#pragma once

namespace linkage {

inline double driveSign(bool clockwise) {
  return clockwise ? -1.0 : 1.0;
}

}  // namespace linkage
