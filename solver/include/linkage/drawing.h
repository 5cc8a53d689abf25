// What to paint of a mechanism at its current pose, as a textbook draws it, in a list any front
// end can draw (the editor's canvas, an SVG writer, a test): bodies as bars, plates or slider
// blocks, every joint by its kind's symbol (linkage/elements.h: pins, blocks, pins in slots,
// gear pairs and belts), slots as channels, the driver, output points, and optionally the
// instant centres with the Kennedy lines that found them. Geometry only, in millimetres (sketch
// coordinates for a body's own outline, world coordinates at the pose for everything else): line
// widths, colours and symbol sizes are the front end's, so that it can keep them constant on screen
// at any zoom.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "linkage/elements.h"
#include "linkage/instant_centres.h"
#include "linkage/kinematics.h"

namespace linkage {

struct Drawing {
  enum class Shape : unsigned char {
    Ground,  // the frame: its pivots are hatched, its slots are fixed channels
    Bar,     // two distinct points (and slots along them): a bar with rounded ends
    Plate,   // three or more points, or a slot beside a point: a rigid plate (convex hull)
    Disc,    // slots whose ends all lie on a circle about one of the body's points (a slotted
             // disk, as the Wanzer's): that circle
    Block,   // one point that slides in a slot: drawn as the slider block of that joint
    Dot,     // a single point, no slot: a small disc
  };
  struct Body {
    BodyId id;
    int number = 0;  // textbook number: ground 1, the others as instant centres number them
    std::string name;
    Shape shape = Shape::Dot;
    Transform pose;  // sketch -> world at the current pose
    // Sketch coordinates: Bar its two ends, Plate its convex hull (counter-clockwise), Disc its
    // centre, Dot and Block the point, Ground its points.
    std::vector<Vec2> outline;
    double radius = 0;  // Disc
  };
  struct Channel {
    SlotId slot;
    BodyId body;
    Vec2 p0 = Vec2::Zero(), p1 = Vec2::Zero();  // the slot's ends now
    // An arc slot: its centre now, radius, the angle of p0 about the centre now and the signed
    // sweep to p1 (radians, counter-clockwise positive).
    bool arc = false;
    Vec2 centre = Vec2::Zero();
    double radius = 0, a0 = 0, sweep = 0;
  };
  struct Driver {
    JointId joint;
    BodyId crank;  // the body that turns (the pin's b side)
    Vec2 at = Vec2::Zero();
    bool ccw = true;  // seen with x right, y up
    double crankDeg = 0;
  };
  struct Output {
    PointId point;
    std::string label;  // "body.point"
    Vec2 at = Vec2::Zero();
  };
  // A line one centre was found from: through the two centres `through` (homogeneous as in
  // InstantCentre::h: a direction with z = 0 for a centre at infinity), or, for a pin-in-slot's
  // own line (k = 0), through the pin along the normal of the slot (through[1] a direction).
  struct KennedyLine {
    int k = 0;
    Eigen::Vector3d through[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  };
  struct Centre {
    int i = 0, j = 0;
    bool determined = false;
    bool atInfinity = false;
    Vec2 at = Vec2::Zero();  // the point, or the unit direction at infinity
    CentreStatus status = CentreStatus::Velocity;
    std::vector<KennedyLine> lines;  // Kennedy: the two lines that found it
    // A machine in space: none between bodies of planes that are not parallel; else `at` is
    // in the frame of plane class `planeClass` (InstantCentre's).
    bool across = false;
    int planeClass = 0;
  };

  std::vector<Body> bodies;  // ground first, then file order
  // Every joint whose references resolve, in file order, as its kind draws it.
  std::vector<JointSymbol> joints;
  std::vector<int> jointIndex;  // of each symbol, in Mechanism::joints
  std::vector<Channel> channels;
  std::vector<Driver> drivers;  // none or one
  std::vector<Output> outputs;
  std::vector<Centre> centres;  // when asked for
  // The extent of everything above but the centres, mm (for "fit to view").
  Vec2 min = Vec2::Zero(), max = Vec2::Zero();
  std::uint64_t revision = 0;  // Kinematics::revision() it was made from
};

class PlaneView;

// The mechanism k holds at its current pose; with centres, also every instant centre of `ics`
// (computed for k at this pose). An invalid k gives an empty drawing. With a view (a machine in
// space seen on one of its planes, linkage/plane_view.h) every position is in that plane's
// coordinates, the ground's projected along its normal, and the centres are only those of its
// plane class (none across planes that are not parallel), mapped into it.
Drawing describeDrawing(const Kinematics& k, const InstantCentres* ics = nullptr,
                        const PlaneView* view = nullptr);

// A design as drawn (every body at its sketch pose, revision 0), for one the solver cannot
// take (yet): what a user is drawing, or an edit that does not assemble.
Drawing describeSketch(const Mechanism& m, const PlaneView* view = nullptr);

// Only the parts that move, for a drawing of the same revision made before: every pose,
// position and centre updated in place, nothing allocated. False when `d` was not made from
// k's mechanism (it must then be described afresh).
bool updateDrawing(Drawing& d, const Kinematics& k, const InstantCentres* ics = nullptr,
                   const PlaneView* view = nullptr);

}  // namespace linkage
