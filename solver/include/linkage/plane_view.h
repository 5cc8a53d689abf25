// A machine in space seen on one of its planes (the canvas's plane chooser, docs/editor.md):
// everything in that plane's (x, y), as the tools that edit it read and write coordinates.
//
// The solver reports a moving body's positions and transform in its plane CLASS's frame (the
// first plane parallel to it, linkage/space.h), not in the body's own plane's coordinates: for a
// plane shifted and turned against its class's frame the two differ. The ground's points and
// slots are written in the world. The view maps each into the chosen plane:
// - bodies of the chosen plane's class (that plane's and its parallels'): from the class frame
//   into the chosen plane (PlaneInClass::fromClass), i.e. seen along its normal;
// - the ground: projected along the chosen plane's normal into its coordinates;
// - bodies of planes that are not parallel (drawn faint, never edited here): in their own
//   plane's coordinates, as the plane chooser would show them.
// A planar machine, or no plane chosen on one, maps nothing: every number is the solver's.
#pragma once

#include <string>
#include <vector>

#include "linkage/kinematics.h"
#include "linkage/space.h"

namespace linkage {

// (a o b)(x) = a(b(x)).
Transform compose(const Transform& a, const Transform& b);

class PlaneView {
 public:
  PlaneView() = default;  // maps nothing
  // Plane `plane` ("" or "drawing": the drawing plane) of m; an unknown name is the drawing
  // plane.
  PlaneView(const Mechanism& m, const std::string& plane);

  // Nothing to map: a planar machine (every position is the drawing plane's).
  bool mapsNothing() const { return identity_; }
  int planeClass() const { return view_.cls; }
  // The view's distance scale: the machine's extent in the world (mm).
  double size() const { return size_; }

  // The mechanism as the view draws its shapes: the ground's points and slots in the view's
  // coordinates (their third numbers dropped), every moving body as it is (its own plane's
  // sketch coordinates, which pose() maps). m itself when mapsNothing().
  const Mechanism& seen(const Mechanism& m) const { return identity_ ? m : seen_; }

  // A position the solver gives for body b (its class frame) in the view. The ground's:
  // unchanged (ground positions are seen().point()->pos).
  Vec2 fromSolver(BodyId b, const Vec2& classPos) const;
  // The solver's point, transform and slot ends, in the view.
  Vec2 point(const Kinematics& k, PointId p) const;
  Transform pose(const Kinematics& k, BodyId b) const;
  Kinematics::Segment slotEnds(const Kinematics& k, SlotId s) const;
  // A design as drawn (no solver): a point and a body's sketch -> view.
  Vec2 sketchPoint(const Mechanism& m, PointId p) const;
  Transform sketchPose(BodyId b) const;
  // A point of the view to the class frame of the chosen plane (what the solver takes: a drag
  // target) and back.
  Vec2 toClass(const Vec2& v) const { return view_.toClass(v); }
  Vec2 fromClass(const Vec2& c) const { return view_.fromClass(c); }
  // A direction (a centre at infinity) from the class frame into the view.
  Vec2 directionFromClass(const Vec2& d) const {
    return view_.identity ? d : Vec2(view_.rot.inverse() * d);
  }

  // A point of the world seen along the chosen plane's normal, as the ground's are.
  Vec2 worldInView(const Vec3& w) const;
  // A ground point's distance from the chosen plane along its normal (mm); 0 for the others.
  double groundDepth(PointId p) const;
  // A ground point moved to `at` of the view, its distance from the plane kept: its numbers as
  // the file writes them ([x, y] in the drawing plane, [x, y, z] in the world).
  void placeGround(Point& p, const Vec2& at) const;
  // A ground slot whose ends are written in the view's coordinates (the Slot tool's), written
  // in the world: [x, y] and z of every end on the chosen plane. Nothing when mapsNothing().
  void placeGround(Slot& s) const;

 private:
  // Class frame -> view for a body of this plane placing: fromClass of the chosen plane for its
  // class, of its own plane otherwise.
  Transform outOf(const PlaneInClass& own) const;
  const PlaneInClass& placingOf(BodyId b) const;

  bool identity_ = true;
  PlaneInClass view_;
  Plane plane_;
  Plane frame_;                        // the chosen plane's class's
  std::vector<PlaneInClass> placing_;  // by BodyId value (the ground's: the view's)
  std::vector<double> groundDepth_;    // by PointId value
  Mechanism seen_;
  double size_ = 1;
};

}  // namespace linkage
