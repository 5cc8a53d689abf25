// Where a mechanism's planes put its parts in space (the file's "planes": spatial machines).
//
// Every body moves in its plane; bodies of parallel planes (normals equal to 1e-9) share one
// planar frame, their plane class's: the first of them in the order drawing, then the file's
// planes. Within a class the joints are the planar ones; ball rods and bevel pairs join classes.
// A mechanism with no planes is one class, the drawing plane, and nothing here changes a number
// of it.
#pragma once

#include <string>
#include <vector>

#include "linkage/model.h"

namespace linkage {

// The plane "drawing": origin 0, x (1, 0, 0), y (0, 1, 0).
const Plane& drawingPlane();
// A plane by name ("" and "drawing": the drawing plane); nullptr when the mechanism has none
// of that name.
const Plane* planeNamed(const Mechanism& m, const std::string& name);
// The plane of a body (the ground's: the drawing plane); the drawing plane for an unknown id or
// plane name.
const Plane& planeOf(const Mechanism& m, BodyId body);

// Whether tables give x, y, z: the file has "planes" or a point with three numbers.
bool isSpatial(const Mechanism& m);

// "" when the machine is planar as the analyses below the kinematics take it (no "planes", no
// third number); else that `what` is not yet computed for a machine in space, naming why
// (docs/spatial.md says what is). The motion table and the kinematics take every machine.
std::string notInSpaceYet(const Mechanism& m, const std::string& what);

// Normals equal to 1e-9 (opposite ones are not parallel).
bool parallel(const Plane& a, const Plane& b);

// A drawn point in the world (mm): a moving body's in its plane at its depth; the ground's at
// (x, y, z), z 0 when not written.
Vec3 worldOf(const Mechanism& m, const Point& p);
// A ground slot's points in the world: p0, (an arc's mid,) p1 at their z (0 where written
// [x, y]).
std::vector<Vec3> slotInWorld(const Slot& s);
// The circle through three points in space: false when they are on one line.
bool circleThrough(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& centre, double& radius);
// A slot's curve through slotInWorld's points in order, for drawing: its two ends, or an arc's
// points from the first through the middle to the last every 5 degrees or less (its ends
// exact). A moving body's slot: in its sketch's x, y at z 0.
std::vector<Vec3> slotCurveInWorld(const Slot& s);

// Why the planes are not as the file format requires, "" when they are: axes not unit or not
// perpendicular, "drawing" redefined, two of one name, a body on an unknown plane; named as the
// file names the place (`planes.rocker.y_axis: ...`, `bodies[3].plane: ...`).
std::string planesProblem(const Mechanism& m);

// The plane classes: class k's frame (a plane: its origin and axes), and each plane's place in
// its class's frame: (x, y) of the plane is rot * (x, y) + shift of the class frame, at the
// class frame's depth `depth` (the plane's origin along the class normal).
struct PlaneInClass {
  int cls = 0;
  Rot rot;
  Vec2 shift = Vec2::Zero();
  double depth = 0;
  bool identity = true;  // the class frame itself: nothing to map
  Vec2 toClass(const Vec2& p) const { return identity ? p : Vec2(rot * p + shift); }
  Vec2 fromClass(const Vec2& p) const { return identity ? p : Vec2(rot.inverse() * (p - shift)); }
};
struct PlaneClasses {
  std::vector<Plane> frames;          // one a class; frames[0] the drawing plane's class
  std::vector<std::string> names;     // every plane by name ("drawing" first), and
  std::vector<PlaneInClass> placing;  // its place in its class
  const PlaneInClass& of(const std::string& plane) const;  // "" is the drawing plane
  // A world point in class k's frame: (x, y) in it and the depth along its normal.
  Vec2 project(int k, const Vec3& w, double* depth = nullptr) const;
};
PlaneClasses planeClasses(const Mechanism& m);

// Where class `cls`'s frame sees a point or a slot: a moving body's mapped from its plane (its
// class is `cls` for this to mean anything), the ground's projected along the class's normal
// (its z as written). Slot: its ends; the copy has no z.
Vec2 inClassFrame(const Mechanism& m, const PlaneClasses& pc, const Point& p, int cls);
Slot inClassFrame(const Mechanism& m, const PlaneClasses& pc, const Slot& s, int cls);
// The mechanism as class `cls`'s frame sees it: every point and slot so mapped, the ids kept,
// every body in the drawing plane. What works on planar positions (a joint's instant centre)
// works on it for the joints of that class.
Mechanism flattenedTo(const Mechanism& m, const PlaneClasses& pc, int cls);
// The class of the plane a joint with this point and slot is written in: the point's body's,
// or the slot's body's when the point is on the ground.
int jointClass(const Mechanism& m, const PlaneClasses& classes, const Point& a, const Slot& s);

}  // namespace linkage
