// Slot travel: how far each slider block and each pin in a slot runs along its slot over one
// turn of the crank, against the slot's drawn ends.
//
// The position along the slot is the arc length from the slot's first end (p0) of the joint's
// point, seen from the body that carries the slot (so a slot on a moving body works as one on
// the ground); for an arc slot, the angle about its centre times its radius. Its extremes are
// where its velocity along the slot vanishes: bracketed on samples of the exact relative
// velocity and refined to 1e-9 degree of crank by safeguarded Newton on the exact relative
// velocity and acceleration (analysis/crank_roots.h). The drawn slot runs from 0 to its length
// (an arc: its angular range times its radius).
#pragma once

#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

struct SlotTravel {
  JointId joint;
  SlotId slot;
  double min = 0, minDeg = 0;  // mm along the slot, and the crank angle (in [0, 360])
  double max = 0, maxDeg = 0;
  double slotFrom = 0, slotTo = 0;  // the drawn ends: 0 and the slot's length
  // min and max within the ends (to 1e-9 of the mechanism's size).
  bool inside = true;
  // How far beyond the ends the point runs (mm, 0 when inside): before the first end and past
  // the second.
  double before = 0, past = 0;
};

struct SlotTravels {
  // The solver's status where the crank cannot turn fully (then no travel is given), BadModel
  // for a mechanism that is not loaded.
  Status status;
  std::vector<SlotTravel> joints;  // every slider and pin-in-slot, in file order
  bool allInside() const;
};

struct SlotTravelOptions {
  int steps = 360;  // sampling intervals over the turn that bracket the extremes
};

// Over crank angles 0 to 360 on a copy of k (k does not move).
SlotTravels slotTravel(const Kinematics& k, const SlotTravelOptions& opt = {});

}  // namespace linkage
