// Exact finite changes of a mechanism's dimensions (issue 29, tolerances): the design with its
// dimensions changed by given amounts, drawn exactly, for a Monte Carlo sample to be solved as
// it is rather than linearised. The dimensions are linkage/sensitivity.h's (dimensions()): a
// change of each moves what that dimension's derivative moves, so a change h gives the position
// its derivative predicts to O(h^2).
//
// - A body's P0-P1: P1 along P0->P1 (its direction kept), the later points placed by their
//   distances from P0 and P1 again (their side of P0P1 kept); P1-Pk and P0-Pk: Pk on the new
//   circles on its side; Pk.along, Pk.across: Pk's coordinates along and across P0->P1 from
//   P0; Pk.x, Pk.y: its coordinates. Every changed length reads back exactly.
// - A ground point's x and y: the point.
// - A straight slot's angle (degrees): both ends turned about its first end; then its offset:
//   both ends moved along the (turned) normal. The angle reads back exactly; so does the offset
//   when the angle is unchanged (a turn about the first end changes the offset measured from
//   elsewhere, as its derivative says).
// - An arc slot's radius: its three points along their radii from its centre; its centre: the
//   arc moved. Both read back exactly.
// - A gear's ratio.
// - A cam's rises: the segment's and the one taking the difference (the dimension's change of
//   the programme: the Cam dock's for a rise that keeps its way), refused where the programme
//   is not one (a partial sum below 0); its base: the follower moved to its new lowest position
//   (setCamBase); its roller: the same cam (the base kept), the follower moved as far. Any
//   other change that takes a follower off its lowest position (the cam's centre, its slot, b
//   or its pivot moved) puts it back there, along its slot or about its pivot, as the
//   derivatives do.
// - In space (analysis/dimension_change_space.h): a depth or a ground point's z, its third
//   number; a plane's origin, the plane (its bodies with it); a ground slot's angle and offset
//   in its block's plane, as a planar slot's, its ends' z with them.
// - Ball rods, last: the file keeps a rod's length as its ends' drawn distance, which a rod's own
//   change and any change that moves an end (a depth, a plane's origin, a body's dimension)
//   alter; every derivative holds the other dimensions, the rods' lengths among them. So each
//   rod is given its drawn length plus its own change: the machine is solved at the drawing's
//   crank angle with those lengths and every body that moves is redrawn there, rigidly (its
//   shape kept), so that each rod reads back its length (analysis/dimension_change_space.h).
// Nothing pinned to a moved point moves with it: loading (or Kinematics::edit) closes the joints.
#pragma once

#include <vector>

#include "linkage/model.h"
#include "linkage/sensitivity.h"
#include "linkage/status.h"

namespace linkage {

// `delta[k]` is the change of dims[k], in its unit; dims must be dimensions(m) of this m (names
// and order), delta of the same size. BadModel when a body's point cannot be placed (the new
// distances do not meet: the triangle cannot close), naming the body and point, or when the
// machine does not close with a rod's changed length, naming it; m is then left partly changed
// (work on a copy).
Status changeDimensions(Mechanism& m, const std::vector<Dimension>& dims,
                        const std::vector<double>& delta);

// A pin's radial play (pin clearance): which of its two points moves with its play (the one no
// other joint uses, so the play opens only this pin), and the two dimensions (that point moved by
// x and y of its body's frame, mm) whose derivatives give the play's first-order effect.
struct PinPlay {
  JointId joint;
  PointId point;
  Dimension x, y;
};
// `pin` names the pin by its two points, "body.P-body.Q" (either order). BadModel naming it when
// there is no such pin joint, or both its points serve other joints too.
Status pinPlay(const Mechanism& m, const std::string& pin, PinPlay& out);

}  // namespace linkage
