// Transmission angles: at every joint where a link drives another body through the joint, how
// well it does, over a turn of the crank (seed 001's mu_1, mu_2, mu_3 and its band of 30 to 150
// degrees).
//
// The joints are found from the topology (analysis/assur_groups.h), in the groups a designer
// would solve from the ground outwards, so every mechanism gets them, not only the examples:
// - Dyad: a pin-pin-pin group, links B1 and B2 with a middle pin C and outer pins P1 and P2 to
//   bodies known before them: the angle between C->P1 and C->P2, 0 to 180 degrees (mu_1, mu_2
//   of the paper, formula 4). 0 and 180 are the group's toggle positions.
// - RodSlider: a rod pinned to a known body at P1 and to a slider block at C, the block in a
//   slot: 90 degrees minus the angle between the rod and the slot's line (mu_3, formula 11).
// - RodInSlot: the same with the rod's own point C in a known body's slot (pin-in-slot).
// In an arc slot the slot's line is its radius: a block in a curved guide turns about the arc's
// centre as a rocker would (a Dyad whose second line runs from the block to the centre), and a
// pin in an arc slot makes a Dyad with the radius from the arc's centre to the pin, as the
// four-bar it is equivalent to.
// Other groups (the Wanzer triangle's class-III group, a block sliding along a rotating link)
// have no such joint and are not reported.
//
// Each angle is read from the solved pose, and its rate from the lines' (the angle between two
// lines changes at the difference of their rates, each from its ends' exact velocities),
// so its extremes and its crossings of the band are found by root finding to 1e-9 degree of
// crank, as limit positions are (linkage/limits.h): the minimum and maximum are exact, not
// the best of the samples.
#pragma once

#include <string>
#include <vector>

#include "linkage/kinematics.h"

namespace linkage {

enum class TransmissionKind { Dyad, RodSlider, RodInSlot };
const char* toString(TransmissionKind k);  // "dyad", "rod-slider", "rod-in-slot"

// A point fixed in a body, read from the mechanism as it is (a study moves points): a point of
// the mechanism; or an arc slot's centre, on the slot's body; or, with both, the point of the
// point's body that stays at that centre (a block in a curved guide turns about it).
struct Anchor {
  PointId point;
  SlotId arc;
  Kinematics::PointMotion motion(const Kinematics& k) const;
  Vec2 at(const Kinematics& k) const { return motion(k).position; }
  bool operator==(const Anchor&) const = default;
};

struct TransmissionJoint {
  TransmissionKind kind = TransmissionKind::Dyad;
  JointId joint;  // the middle pin (Dyad), the rod-block pin, or the pin-in-slot
  BodyId link;    // B1, or the rod
  BodyId other;   // B2 (Dyad) or the body that holds the slot
  // The link's line: from its pin to a known body to its point at the joint.
  Anchor linkOuter, linkAt;
  // Dyad: the second line, from its end at the joint to its outer end (on `other`; for a pin in
  // an arc slot, the radius: from the pin to the arc's centre).
  Anchor otherAt, otherOuter;
  SlotId slot;        // RodSlider, RodInSlot; the arc slot of an arc's Dyad
  std::string label;  // "mu:" and the joint's `a` point as in the file
};

// In the order the structure solves the groups (the paper's mu_1, mu_2, mu_3 for its mechanism).
std::vector<TransmissionJoint> transmissionJoints(const Mechanism& m);

// The plane class (linkage/space.h) a joint's angle lies in: its link's; 0 on a planar machine.
int transmissionClass(const Mechanism& m, const TransmissionJoint& t);
// A rod's slot as drawn (p1 - p0) in the frame the rod's angle is read in: the drawing's on a
// planar machine; on a machine in space its plane class's, as the solver places the slot (a
// ground slot seen along the class's normal, its ends' z with it; a body's slot turned from its
// plane into the class's frame). Zero for a dyad.
Vec2 slotLine(const Mechanism& m, const TransmissionJoint& t);

// The angle at k's pose, in degrees, with its first and second derivatives per degree of crank
// (NaN where k's velocities or accelerations are not known).
struct TransmissionReading {
  double deg = 0, perDeg = 0, perDeg2 = 0;
};
TransmissionReading transmissionAngle(const Kinematics& k, const TransmissionJoint& t);

struct TransmissionBand {
  double lo = 30, hi = 150;
};

// A stretch of crank angle where the angle is outside the band: from fromDeg (in [0, 360)) to
// toDeg > fromDeg, which passes 360 when the stretch wraps past crank angle 0.
struct TransmissionStretch {
  double fromDeg = 0, toDeg = 0;
  bool below = true;  // below lo, else above hi
};

struct TransmissionExtreme {
  bool max = false;
  double crankDeg = 0;
  double deg = 0;
};

struct TransmissionSummary {
  double min = 0, minDeg = 0;  // the smallest angle over the turn and its crank angle
  double max = 0, maxDeg = 0;
  std::vector<TransmissionExtreme> extremes;  // every local extreme, crank order
  std::vector<TransmissionStretch> outside;   // crank order of fromDeg
  bool inBand() const { return outside.empty(); }
};

struct TransmissionOptions {
  int steps = 360;  // samples over the turn (at least 4)
  TransmissionBand band;
  double toleranceDeg = 1e-9;
};

struct TransmissionSweep {
  // BadModel (options), or the solver's status where the crank cannot turn fully; then
  // crankDeg and values hold the samples reached and summaries is empty.
  Status status;
  TransmissionBand band;
  std::vector<TransmissionJoint> joints;
  std::vector<double> crankDeg;                // 0, 360/steps, ..., 360
  std::vector<std::vector<double>> values;     // [joint][sample], degrees
  std::vector<TransmissionSummary> summaries;  // [joint]
  bool inBand() const;
};

// Sweeps a copy of k over crank angles 0 to 360 (k itself does not move).
TransmissionSweep sweepTransmission(const Kinematics& k, const TransmissionOptions& opt = {});

}  // namespace linkage
