// Edits of a mechanism as the drawing tools make them, on a copy of the design, in sketch
// coordinates (the tools convert from the view). Names follow the textbook: links `link2`,
// `link3`... by their number, points by letters shared by the two points of a pin, slots `s1`...
// Each returns what it made, or an empty id with `why` set when the edit makes no sense.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/model.h"

namespace linkage {

// A fresh, unique name of each kind.
std::string newBodyName(const Mechanism& m, const std::string& stem = "link");
std::string newPointName(const Mechanism& m, BodyId body);
std::string newSlotName(const Mechanism& m, BodyId body);
// Is `name` free for a body (other than `self`)? Names are what the file refers to.
bool bodyNameFree(const Mechanism& m, const std::string& name, BodyId self = {});
bool pointNameFree(const Mechanism& m, BodyId body, const std::string& name, PointId self = {});
bool slotNameFree(const Mechanism& m, BodyId body, const std::string& name, SlotId self = {});

// A link through the given points, at `at` (where it is drawn now), each pinned to an existing
// point of another body when `pinTo` is set (drawn where that point is now).
struct LinkVertex {
  Vec2 at = Vec2::Zero();
  PointId pinTo;
};
// In a machine in space, `plane` names the plane it moves in ("": the drawing plane), and the
// vertices are in that plane's coordinates; refused with `why` for a plane the machine has not.
BodyId addLink(Mechanism& m, const std::vector<LinkVertex>& vertices, std::string* why = nullptr,
               const std::string& plane = {});

// A ground point at `at`, pinned to `point` when one is given (a ground pivot; `at` is where
// the point is now). `at` in the coordinates of `plane` ("": the drawing plane): off the drawing
// plane the ground point is written in the world, [x, y, z]. None for an unknown plane.
PointId addGroundPoint(Mechanism& m, const Vec2& at, PointId point = {},
                       const std::string& plane = {});
// A point added to a body (a bar becomes a plate).
PointId addBodyPoint(Mechanism& m, BodyId body, const Vec2& at);
SlotId addBodySlot(Mechanism& m, BodyId body, const Vec2& p0, const Vec2& p1);
// A slider block at `point` (drawn at `at`, where the point is now) sliding in `slot`: a body
// of its own with its point pinned to `point` and a slider joint in the slot, in the plane of
// the slot's body (of the point's, for a ground slot): a slider joins bodies of one plane.
BodyId addBlock(Mechanism& m, PointId point, SlotId slot, const Vec2& at,
                std::string* why = nullptr);
JointId addPinInSlot(Mechanism& m, PointId point, SlotId slot, std::string* why = nullptr);
// A gear or belt between two bodies pivoted on one body, the carrier (the ground preferred):
// b's body turns `ratio` times as fast as a's relative to it (negative: gears in mesh, positive:
// a belt), with the centres at their pivots. The pivots: the points where each is pinned to
// the carrier. Refused with `why` when they share no carrier or are one body.
JointId addCoupling(Mechanism& m, BodyId a, BodyId b, double ratio, std::string* why = nullptr);
// The bodies `body` is pinned to (its possible carriers), the ground first.
std::vector<BodyId> pivotsOf(const Mechanism& m, BodyId body);
// An arc slot from p0 through mid to p1 on a body; none when the three points are on a line.
SlotId addBodyArcSlot(Mechanism& m, BodyId body, const Vec2& p0, const Vec2& mid, const Vec2& p1);
// A straight slot bent into an arc through a point a quarter of its length off its middle, in
// the plane it lies in (the ground's written in the world: its block's plane, the first joint
// running in it); refused with `why` when that leaves no bend (a chord along the plane's
// normal). And an arc made straight between its ends. Each keeps a z for every point written
// with one.
bool bendSlot(Mechanism& m, SlotId id, std::string* why = nullptr);
void straightenSlot(Mechanism& m, SlotId id);
// Makes a pin the driver (its ground side, if it has one, becomes `a`, so the body turns
// relative to the frame); keeps the rpm and direction of a previous driver.
bool setDriver(Mechanism& m, JointId pin, std::string* why = nullptr);
// Toggles a point among the outputs.
void toggleOutput(Mechanism& m, PointId p);
// Planes of a machine in space (linkage/space.h). A plane added to the file's planes, checked
// as a file's are (a name not empty, not "drawing", not taken; axes unit and perpendicular to
// 1e-9): false with `why` naming the field otherwise, and `m` as it was.
bool addPlane(Mechanism& m, const Plane& p, std::string* why = nullptr);
// A fresh plane name: "plane2", "plane3"...
std::string newPlaneName(const Mechanism& m);
// The plane inclined by `rhoDeg` about the world's x through `origin`: x (1, 0, 0), y (0, cos
// rho, sin rho) (seed 004's rocker plane, rho = 23 degrees).
Plane planeInclinedAboutX(const std::string& name, const Vec3& origin, double rhoDeg);
// The plane square to the shaft at ground point `pivot` (a pin of the ground to a moving body:
// the shaft is along that body's plane's normal), `along` mm from the pivot along the shaft, its
// axes the body's plane's: where another crank on the same shaft turns. None when `pivot` is not
// a ground point pinned to a moving body.
std::optional<Plane> planeOnShaft(const Mechanism& m, const std::string& name, PointId pivot,
                                  double along);
// The ground points that are shafts (pinned to a moving body), file order.
std::vector<PointId> shafts(const Mechanism& m);

// A ball rod from point a to point b (any planes): they keep their drawn distance in space.
// Refused with `why` for one point twice, two points of one body (both on the ground
// included), or ends closer than 1e-9 mm as drawn.
JointId addBallRod(Mechanism& m, PointId a, PointId b, std::string* why = nullptr);

// A slider becomes a pin-in-slot and back.
bool changeJointType(Mechanism& m, JointId j, JointType type, std::string* why = nullptr);
// An edit drawn on the mechanism as it is shown, at the current crank angle, where a user
// draws: new links, pivots and joints placed where they are now. The file holds one drawing, at
// the pose of the sketch (crank angle -start_deg), so when the crank is elsewhere the edited
// mechanism is solved here first (from `current`, the solver before the edit), turned back
// along its motion to the sketch's pose, and every body redrawn where it is there (bodies that
// did not move keep their numbers to the last bit); at the sketch's pose, the bodies the solve
// moved to assemble the edit are redrawn where they are, so that the drawing closes (a typed
// dimension that no longer fits moves its bodies, as a file that does not close is assembled
// when it loads). Where the sketch's pose cannot be reached
// any more, the drawing becomes the current pose, and so does crank angle 0 (start offset 0: a
// file must reach its crank angle 0 to load). Not solved: `design` is the edit as given, for
// the caller to keep with the solver's reason.
struct PoseEdit {
  Mechanism design;
  Kinematics kinematics;  // solved at the current crank angle (when `solved`)
  bool solved = false;
};
PoseEdit editAtPose(const Kinematics& current, Mechanism next);

// The points pinned to `p` (and theirs, transitively), `p` included: one place in the drawing.
std::vector<PointId> pinnedTogether(const Mechanism& m, PointId p);

// Typed dimensions (the drawing, sketch coordinates; the points pinned to a moved point move
// with it). A body's side lengths: a bar's one, a triangle's three (its points in file order
// P0, P1, P2: |P0P1|, |P1P2|, |P0P2|). P0 stays, P1 keeps its direction from P0, P2 keeps its
// side of the line P0P1; refused with `why` when a length is not positive and finite or the
// three do not make a triangle, or the body has not two or three points.
bool setSideLengths(Mechanism& m, BodyId body, const std::vector<double>& lengths,
                    std::string* why = nullptr);
// The sides as setSideLengths takes them (empty for a body of another number of points).
std::vector<double> sideLengths(const Mechanism& m, BodyId body);
// Point p placed `distance` from point `from` at `angleDeg` (counter-clockwise from +x); refused
// for a distance not positive and finite, an angle not finite, or p == from.
bool setPolar(Mechanism& m, PointId p, PointId from, double distance, double angleDeg,
              std::string* why = nullptr);

}  // namespace linkage
