// The reference closed form (reference/four_bar.h) of the four-bars test::fourBar draws.
#pragma once

#include <cmath>

#include "reference/four_bar.h"

namespace linkage::test {

// Ground 0 -> (d, 0); crank r2 drawn at crankDeg, coupler r3, rocker r4; coupler point (px, py);
// counter-clockwise at omega rad/s.
inline linkref::FourBarParams<double> fourBarReference(double d, double r2, double r3, double r4,
                                                       double crankDeg, bool open, double px,
                                                       double py, double omega = 1) {
  linkref::FourBarParams<double> p;
  p.O2 = {0, 0};
  p.O4 = {d, 0};
  p.r2 = r2;
  p.r3 = r3;
  p.r4 = r4;
  p.theta20 = crankDeg * M_PI / 180;
  p.omega = omega;
  p.branch = open ? linkref::FourBarBranch::kOpen : linkref::FourBarBranch::kCrossed;
  p.px = px;
  p.py = py;
  return p;
}

}  // namespace linkage::test
