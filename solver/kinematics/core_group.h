// A class-III-like group solved in reduced coordinates: one rigid "core" body held to known
// bodies by exactly three scalar conditions, each one of
//   - a pin to a known body (two conditions),
//   - a point of the core on the line of a known body's slot (pin-in-slot, one condition),
//   - a slider block pinned to the core and sliding in a known body's slot (one condition).
// A block keeps its slot body's angle, so its pin point runs on the slot's line shifted by the
// block's own offset (slot point minus pin point, fixed in the slot body's frame): the block
// disappears into a pin-in-slot condition and its pose follows from the core afterwards.
// The Wanzer needle bar is such a group (the triangle held by three blocks): 15 coordinates of
// the general solve become 3, solved by Newton on a 3 x 3 Jacobian, with the rows evaluated by
// the same joint functions (joint_pin.h, joint_pin_in_slot.h) as the general solve uses.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "kinematics/motion.h"
#include "system/system.h"

namespace linkage {

struct CoreLink {
  bool pin = false;       // pin to the known body (2 rows), else the point on its slot line (1 row)
  int known = -1;         // -1 ground
  Vec2 s = Vec2::Zero();  // the core's point
  Vec2 ks = Vec2::Zero();        // pin: the known body's point; line: a point of the (shifted) line
  Vec2 n = Vec2::Zero();         // line: its unit normal, in the known body's frame
  int block = -1;                // an eliminated block, or -1
  Vec2 blockPin = Vec2::Zero();  // the block's pin point, in its frame
};

struct CoreGroup {
  int core = -1;
  std::vector<CoreLink> links;  // three rows in all
  int detSign = 0;              // of the 3 x 3 Jacobian on the drawn branch
};

// Solves the core's pose, rates and accelerations (and its blocks') in next, from the known
// bodies already in next, starting from the core's pose in prev advanced along its rates to
// next.phi, or from `start` when given (a jump: whole turns then counted from prev's angle).
// False when Newton does not settle near the start or the group is (near) singular, or not on
// its branch (the sign of det J).
bool solveCore(const CoreGroup& g, const System& sys, const Motion& prev, Motion& next,
               const BodyState* start = nullptr);

// The core's poses on its branch (g.detSign) with the known bodies as they are in m, in closed
// form: the three rows are linear in (x, y, cos theta, sin theta) of the core's frame, a line in
// that space, which meets the circle cos^2 + sin^2 = 1 at most twice, one point on each branch
// (det J changes sign between the two roots). False where the line misses the circle, or the
// rows are dependent: no pose, or not one that the rows fix.
bool corePose(const CoreGroup& g, const Motion& m, BodyState& pose);

// Sign of det of the core's 3 x 3 Jacobian at the positions of m (0 if singular).
int coreDetSign(const CoreGroup& g, const Motion& m);

}  // namespace linkage
