// The mechanism document: what a user draws and what a .linkage.json file holds.
//
// Entities live in flat vectors and refer to each other by stable ids, never by index or pointer,
// so an editor can keep ids across edits (ids are never reused within one Mechanism). Geometry is
// in global sketch coordinates of one drawn configuration, in millimetres; a body is rigid, its
// points and slots as drawn are its geometry.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace linkage {

template <class Tag>
struct Id {
  std::uint32_t value = 0;  // 0 is "none"
  explicit operator bool() const { return value != 0; }
  friend bool operator==(Id a, Id b) { return a.value == b.value; }
  friend bool operator!=(Id a, Id b) { return a.value != b.value; }
  friend bool operator<(Id a, Id b) { return a.value < b.value; }
};
using BodyId = Id<struct BodyTag>;
using PointId = Id<struct PointTag>;
using SlotId = Id<struct SlotTag>;
using JointId = Id<struct JointTag>;

using Vec2 = Eigen::Vector2d;

// Fields of a file object that this program does not know are kept, verbatim, as the text of a
// JSON object ("" when there were none), and written back on save.
using Extras = std::string;

struct Body {
  BodyId id;
  std::string name;
  bool ground = false;
  std::optional<int> number;  // textbook number for instant centres (ground is 1)
  Extras extras;
};

struct Point {
  PointId id;
  BodyId body;
  std::string name;  // unique within its body
  Vec2 pos;
};

// A straight slot: the line through p0 and p1 (which also bound its drawn length).
struct Slot {
  SlotId id;
  BodyId body;
  std::string name;  // unique within its body
  Vec2 p0, p1;
};

enum class JointType { Pin, Slider, PinInSlot };

struct Joint {
  JointId id;
  JointType type = JointType::Pin;
  PointId a;    // all types
  PointId b;    // pin only
  SlotId slot;  // slider and pin-in-slot only
  Extras extras;
};

enum class Direction { Cw, Ccw };

struct Driver {
  JointId joint;  // a pin; the body of its b point turns relative to the body of its a point
  double rpm = 60;
  Direction direction = Direction::Ccw;
  double startDeg = 0;  // start offset from the sketch, counted in the driving direction
  Extras extras;
};

struct Mechanism {
  std::string name;
  std::vector<Body> bodies;  // file order
  std::vector<Point>
      points;  // grouped by body in no particular order; order within a body = file order
  std::vector<Slot> slots;
  std::vector<Joint> joints;  // file order: the driver's "joint" index counts in it
  std::optional<Driver> driver;
  std::vector<PointId> outputs;
  Extras extras;         // unknown top-level fields
  Extras unitsExtras;    // unknown fields of "units"
  Extras outputsExtras;  // unknown fields of "outputs"

  BodyId addBody(std::string name, bool ground = false);
  PointId addPoint(BodyId body, std::string name, Vec2 pos);
  SlotId addSlot(BodyId body, std::string name, Vec2 p0, Vec2 p1);
  JointId addPin(PointId a, PointId b);
  JointId addSlider(PointId a, SlotId slot);
  JointId addPinInSlot(PointId a, SlotId slot);

  // Lookups return nullptr when the id is unknown.
  const Body* body(BodyId id) const;
  const Point* point(PointId id) const;
  const Slot* slot(SlotId id) const;
  const Joint* joint(JointId id) const;
  Body* body(BodyId id);
  Point* point(PointId id);
  Slot* slot(SlotId id);
  Joint* joint(JointId id);

  const Body* bodyNamed(const std::string& name) const;
  const Point* pointNamed(BodyId body, const std::string& name) const;
  const Slot* slotNamed(BodyId body, const std::string& name) const;
  const Body* ground() const;  // nullptr when there is none

  // "body.point" as the file and the command line spell it.
  std::string pointLabel(PointId id) const;
  std::string slotLabel(SlotId id) const;
  // A short description for messages, e.g. `joints[2] (slider slider4.E in disk.B)`.
  std::string jointLabel(JointId id) const;
  int jointIndex(JointId id) const;  // -1 when unknown

  // Resolves "body.point"; nullopt when either name is unknown.
  std::optional<PointId> findPoint(const std::string& dotted) const;

 private:
  std::uint32_t nextId_ = 1;
};

const char* toString(JointType t);

// Whether b is a with other dimensions only: the same bodies, points, slots, joints and driver
// (ids, kinds, connections, start angle and direction), with points or slots moved. The bodies
// whose shape changed go to `reshaped`. Such an edit can be re-solved group by group from the
// current pose; anything else is a new mechanism.
bool sameTopology(const Mechanism& a, const Mechanism& b, std::vector<BodyId>& reshaped);

}  // namespace linkage
