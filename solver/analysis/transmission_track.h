// One transmission angle followed over a sweep of the crank (linkage/transmission.h): its
// samples and the root channels of its extremes. Shared by sweepTransmission and the parameter
// study, which follows several in one sweep.
//
// The angle is kept signed (theta, continuous between toggles): for a dyad mu = |theta| in
// (-180, 180], for a rod mu = 90 - |theta| with theta the angle from the slot's line to the rod
// folded into (-90, 90]. Its extremes are the stationary points of theta (the channel of its
// derivative, smooth) and, for a rod, the crank angles where the rod lies along the slot (theta
// = 0, where mu = 90 has a corner): the channel sin(2 theta), smooth through the fold, whose
// roots at |theta| = 90 are toggles and are dropped.
#pragma once

#include <vector>

#include "analysis/crank_roots.h"
#include "linkage/transmission.h"

namespace linkage {

class TransmissionTrack {
 public:
  TransmissionTrack(const Mechanism& m, const TransmissionJoint& t);
  void sample(const Kinematics& k);
  void closePeriod();
  std::vector<RootChannel*> channels();
  // After findRoots: the extremes, minimum and maximum (no stretches).
  TransmissionSummary summary(bool periodic) const;

  std::vector<double> mu;  // degrees, one per sample

 private:
  TransmissionJoint t_;
  Vec2 slot_ = Vec2::Zero();  // a rod's slot as drawn, on its body (slotLine)
  RootChannel stationary_, along_;
};

}  // namespace linkage
