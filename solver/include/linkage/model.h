// The mechanism document: what a user draws and what a .linkage.json file holds.
//
// Entities live in flat vectors and refer to each other by stable ids, never by index or pointer,
// so an editor can keep ids across edits (ids are never reused within one Mechanism). Geometry is
// in global sketch coordinates of one drawn configuration, in millimetres; a body is rigid, its
// points and slots as drawn are its geometry.
#pragma once

#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "linkage/geometry.h"

namespace linkage {

// An entity's id: a number never reused within one mechanism, and the mechanism that made it
// (copies of a Mechanism share it), so that an id from another mechanism is refused rather than
// taken for one of this mechanism's own.
template <class Tag>
struct Id {
  std::uint32_t value = 0;  // 0 is "none"
  std::uint32_t owner = 0;
  explicit operator bool() const { return value != 0; }
  friend bool operator==(Id a, Id b) { return a.value == b.value && a.owner == b.owner; }
  friend bool operator!=(Id a, Id b) { return !(a == b); }
  friend bool operator<(Id a, Id b) {
    return a.value != b.value ? a.value < b.value : a.owner < b.owner;
  }
};
using BodyId = Id<struct BodyTag>;
using PointId = Id<struct PointTag>;
using SlotId = Id<struct SlotTag>;
using JointId = Id<struct JointTag>;
using LoadId = Id<struct LoadTag>;

// Fields of a file object that this program does not know are kept, verbatim, as the text of a
// JSON object ("" when there were none), and written back on save.
using Extras = std::string;

// A point mass in sketch coordinates.
struct PointMass {
  double kg = 0;
  Vec2 at = Vec2::Zero();
  bool operator==(const PointMass&) const = default;
};

// A body's mass properties: its mass, its centre of mass in sketch coordinates (the drawing's
// pose, like its points) and its moment of inertia about that centre.
struct Mass {
  double kg = 0;
  Vec2 com = Vec2::Zero();
  double jKgMm2 = 0;
  Extras extras;
  // Of the mass above, the counterweights a balance added (already in kg, com and j: what an
  // editor draws as disks, and what a user may want to take out again).
  std::vector<PointMass> counterweights;
  bool operator==(const Mass&) const = default;
};

// The largest mass (kg) and moment of inertia (kg mm^2) a body or a counterweight may have: no
// link of a machine weighs a thousand tonnes, and the forces of a mass far beyond it are no
// machine's (1e300 kg on the slider-crank of grams: forces of 1e303 N with noise of 1e287 N
// where 0 is meant, the others' 0.1 N lost; 1e308 kg: they overflow).
inline constexpr double kMaxMassKg = 1e6;
inline constexpr double kMaxInertiaKgMm2 = 1e15;  // a thousand tonnes 31.6 m from its centre
// Why a value is no mass (no moment of inertia) a body can have, "" when it is one: not a
// number, negative, or beyond the largest. The file reader and the editor's fields both say it.
std::string massRefusal(double kg);
std::string inertiaRefusal(double kgMm2);

struct Body {
  BodyId id;
  std::string name;
  bool ground = false;
  std::string plane;          // the plane it moves in ("": the drawing plane; linkage/space.h)
  std::optional<int> number;  // textbook number for instant centres (ground is 1)
  std::optional<Mass> mass;   // none: massless (the ground's is not used)
  Extras extras;
};

struct Point {
  PointId id;
  BodyId body;
  std::string name;  // unique within its body
  Vec2 pos;          // in its body's plane (the ground's: the drawing plane)
  // A third number as written: a moving body's depth along its plane's normal (studs at several
  // depths of one shaft), the ground's world z. None: [x, y].
  std::optional<double> third;
};

// A slot: the straight line through p0 and p1 (which also bound its drawn length), or, with a
// point `mid` on the way, the circular arc from p0 through mid to p1 (elements/guide.h).
struct Slot {
  SlotId id;
  BodyId body;
  std::string name;  // unique within its body
  Vec2 p0, p1;
  std::optional<Vec2> mid;
  // The ground's slot ends in the world: their z as written, in the order p0, (mid,) p1; empty
  // for [x, y] ends.
  std::vector<double> z;
  bool arc() const { return mid.has_value(); }
};

// A plane placed in space (the file's "planes"): its (x, y) is origin + x xAxis + y yAxis in the
// world (mm), the axes unit and perpendicular; its normal n = xAxis x yAxis. A body of it moves
// in it, turning about n (linkage/space.h).
struct Plane {
  std::string name;
  Vec3 origin = Vec3::Zero();
  Vec3 xAxis = Vec3::UnitX();
  Vec3 yAxis = Vec3::UnitY();
  Extras extras;
  Vec3 normal() const { return xAxis.cross(yAxis); }
  Vec3 world(const Vec2& p, double depth = 0) const {
    return origin + p.x() * xAxis + p.y() * yAxis + depth * normal();
  }
};

// A joint's kind: its place in the element table (linkage/elements.h), where each kind describes
// itself once (its fields, equations, instant centre and symbol) and is registered once. The
// model knows no kinds; the constants name the table's first entries for the code that makes
// joints of them (a kind added later is found by its name: elementKindNamed()).
struct JointType {
  std::uint8_t index = 0;
  friend auto operator<=>(JointType, JointType) = default;
  static const JointType Pin, Slider, PinInSlot, Gear;
};
inline constexpr JointType JointType::Pin{0};
inline constexpr JointType JointType::Slider{1};
inline constexpr JointType JointType::PinInSlot{2};
inline constexpr JointType JointType::Gear{3};

// One member of an object of a structured field (FieldType::Records, a cam's motion programme)
// as written: its key and its value, a number or a string.
struct RecordMember {
  std::string key;
  std::variant<double, std::string> value;
  bool operator==(const RecordMember&) const = default;
};
// An object of a structured field: its members in the order written.
using Record = std::vector<RecordMember>;
// The member of a record with this key; nullptr when it has none.
const RecordMember* recordMember(const Record& r, std::string_view key);

// A joint of any kind. Its kind's fields (linkage/elements.h: FieldSpec) say which of these it
// reads and under what names: up to two points, a slot, a body, numbers (a flag too, as 1 or 0)
// and structured fields (arrays of records). What the records mean is the kind's; the file
// reader and writer carry them as data, so a kind with a table of its own (a cam's motion) needs
// no member here.
struct Joint {
  JointId id;
  JointType type = JointType::Pin;
  PointId a;                    // every kind: its first point
  PointId b;                    // a second point
  SlotId slot;                  // a slot it runs in
  BodyId carrier;               // a body it is carried by (none: the ground)
  std::vector<double> numbers;  // an optional number not given: NaN (no file holds NaN)
  Extras extras;
  std::vector<std::vector<Record>> records;  // structured fields, by their index
  double number(size_t k) const { return k < numbers.size() ? numbers[k] : 0.0; }
  // Whether number k was given (an optional one may not be).
  bool given(size_t k) const { return k < numbers.size() && !std::isnan(numbers[k]); }
  const std::vector<Record>& recordsAt(size_t k) const {
    static const std::vector<Record> none;
    return k < records.size() ? records[k] : none;
  }
  // The kind's fields equal, an optional number not given equal to another not given.
  bool sameFields(const Joint& o) const;
};

// An external load: a force on a point's body at the point (N, in sketch axes), or a torque on
// a body (N m, counter-clockwise positive); acting while the crank angle modulo 360 lies in the
// closed window [fromDeg, toDeg] (which may wrap past 360), or always without a window.
struct Load {
  PointId point;  // a force at this point
  BodyId body;    // or a torque on this body
  Vec2 forceN = Vec2::Zero();
  double torqueNm = 0;
  std::optional<double> fromDeg, toDeg;
  Extras extras;
  LoadId id;  // given by Mechanism::addLoad (last: a load can be written as {point, ...})
  bool activeAt(double crankDeg) const;
};

// How a file names, colours or hides one of the machine's mechanisms (linkage/mechanisms.h says
// which bodies make one). Known by its bodies rather than by an index or a name, so that it is
// found again after edits that add bodies to its mechanism or remove some of them: the
// mechanism that shares the most bodies with it takes it.
struct MechanismEntry {
  std::vector<BodyId> bodies;  // ids of bodies removed since are ignored
  std::string name;            // "": the default (its first body's name)
  std::string colour;          // "#rrggbb"; "": each body its own colour
  bool hidden = false;
  Extras extras;
  bool operator==(const MechanismEntry&) const = default;
};

// A scalar of the motion: a point's position along a unit direction (mm; the dot product of
// the position with the direction), or, with `body` set, a body's angle (degrees, relative to
// the drawing, counter-clockwise, whole turns counted). What limits, windows and the rows of a
// cycle diagram follow (linkage/limits.h, linkage/timing.h).
//
// On a machine in space (linkage/space.h) a point's position is the world's: along (dx, dy,
// dz), dz its third component. With `other`, the distance between the two points (mm; in the
// world, or in the plane of a planar machine).
struct LimitMeasure {
  PointId point;
  Vec2 direction = Vec2(0, 1);
  BodyId body;
  double dz = 0;
  PointId other;
  static LimitMeasure along(PointId p, Vec2 direction) { return {p, direction, {}, 0, {}}; }
  static LimitMeasure alongInSpace(PointId p, const Vec3& d) {
    return {p, Vec2(d.x(), d.y()), {}, d.z(), {}};
  }
  static LimitMeasure angleOf(BodyId b) { return {{}, Vec2(0, 1), b, 0, {}}; }
  static LimitMeasure distance(PointId p, PointId q) { return {p, Vec2(0, 1), {}, 0, q}; }
  Vec3 direction3() const { return Vec3(direction.x(), direction.y(), dz); }
  // The same with its direction (all three components) of length 1.
  LimitMeasure unit() const {
    if (body || other) return *this;
    const Vec3 d = direction3().normalized();
    return {point, Vec2(d.x(), d.y()), body, d.z(), other};
  }
  bool operator==(const LimitMeasure&) const = default;
};

// The machine's cycle (timing) diagram as the document keeps it (the file's optional "timing";
// linkage/timing_text.h reads and writes its parts as a user types them). By ids, so that a
// rename follows them and a removal takes them along, and undo puts them back.
struct TimingWindow {
  std::string name;  // unique among the windows; no ',', '+', ':', '<', '>' or spaces
  LimitMeasure output;
  bool below = true;  // output < level; else output > level
  double level = 0;
  bool operator==(const TimingWindow&) const = default;
};
// Two windows that must not overlap, by name.
struct TimingConflict {
  std::string first, second;
  bool operator==(const TimingConflict&) const = default;
};
// What a part of a machine is, for its clearance to another: a point; the segment between two
// points of one body (a needle or a blade between its ends: `point` to `end`); or a slot as
// drawn (between its ends, or along its arc).
struct ClearancePart {
  PointId point;
  PointId end;  // with point: the segment from point to end
  SlotId slot;
  static ClearancePart of(PointId p) { return {p, {}, {}}; }
  static ClearancePart of(SlotId s) { return {{}, {}, s}; }
  static ClearancePart segment(PointId a, PointId b) { return {a, b, {}}; }
  bool isPoint() const { return point && !end; }
  bool isSegment() const { return point && end; }
  bool isSlot() const { return static_cast<bool>(slot); }
  bool operator==(const ClearancePart&) const = default;
};
// A clearance watched over the cycle: from a point to another part (a point, a segment of
// another body, or another body's slot).
struct ClearanceWatch {
  PointId point;
  ClearancePart other;
  std::optional<double> minMm;  // the least allowed; none: only shown
  bool operator==(const ClearanceWatch&) const = default;
};
struct Timing {
  std::vector<LimitMeasure> outputs;  // rows of their own (a window's output is a row too)
  std::vector<TimingWindow> windows;
  std::vector<TimingConflict> conflicts;
  std::vector<ClearanceWatch> clearances;
  Extras extras;
  bool empty() const {
    return outputs.empty() && windows.empty() && conflicts.empty() && clearances.empty() &&
           extras.empty();
  }
  // Window i made `w`; the conflicts that named it follow a new name.
  void replaceWindow(size_t i, TimingWindow w);
  // Window i taken out with the conflicts that name it.
  void removeWindow(size_t i);
  bool operator==(const Timing&) const = default;
};

enum class Direction { Cw, Ccw };

struct Driver {
  JointId joint;  // a pin; the body of its b point turns relative to the body of its a point
  double rpm = 60;
  Direction direction = Direction::Ccw;
  double startDeg = 0;  // start offset from the sketch, counted in the driving direction
  Extras extras;
};

// What a removal took out of a mechanism, with the place of each entity in its vector, so that
// restore() puts it back exactly (the same ids, the same order, the same file).
struct Removal {
  template <class T>
  struct At {
    size_t index = 0;
    T value;
  };
  std::vector<At<Body>> bodies;  // ascending indices, as they were before the removal
  std::vector<At<Point>> points;
  std::vector<At<Slot>> slots;
  std::vector<At<Joint>> joints;
  std::vector<At<PointId>> outputs;
  std::vector<At<Load>> loads;
  std::optional<Driver> driver;  // set when the driver's joint was removed
  // The cycle diagram's parts on what went (a conflict goes with either of its windows).
  std::vector<At<LimitMeasure>> timingOutputs;
  std::vector<At<TimingWindow>> timingWindows;
  std::vector<At<TimingConflict>> timingConflicts;
  std::vector<At<ClearanceWatch>> clearances;
  bool empty() const { return bodies.empty() && points.empty() && slots.empty() && joints.empty(); }
};

struct Mechanism {
  std::string name;
  // The file's "planes" (none: no such key), in file order; the drawing plane is not among them.
  std::optional<std::vector<Plane>> planes;
  std::vector<Body> bodies;  // file order
  std::vector<Point>
      points;  // grouped by body in no particular order; order within a body = file order
  std::vector<Slot> slots;
  std::vector<Joint> joints;  // file order: the driver's "joint" index counts in it
  std::optional<Driver> driver;
  std::vector<PointId> outputs;
  // m/s^2: the world's x and y (a planar model's: the sketch's axes); none: no gravity.
  std::optional<Vec2> gravity;
  // Its third number as written ([gx, gy, gz], with gravity only): the world's z, along the
  // drawing's normal. None: [gx, gy].
  std::optional<double> gravityZ;
  std::vector<Load> loads;
  // The file's "mechanisms", in file order.
  std::vector<MechanismEntry> mechanismEntries;
  // The file's "timing": what the machine's cycle diagram shows.
  Timing timing;
  Extras extras;         // unknown top-level fields
  Extras unitsExtras;    // unknown fields of "units"
  Extras outputsExtras;  // unknown fields of "outputs"

  Mechanism();

  // The gravity in the world (m/s^2): (gx, gy, gz), gz 0 when not written; zero without one.
  Vec3 gravityWorld() const {
    return gravity ? Vec3(gravity->x(), gravity->y(), gravityZ.value_or(0)) : Vec3::Zero();
  }

  BodyId addBody(std::string name, bool ground = false);
  PointId addPoint(BodyId body, std::string name, Vec2 pos);
  SlotId addSlot(BodyId body, std::string name, Vec2 p0, Vec2 p1);
  // An arc slot from p0 through mid to p1.
  SlotId addArcSlot(BodyId body, std::string name, Vec2 p0, Vec2 mid, Vec2 p1);
  JointId addPin(PointId a, PointId b);
  JointId addSlider(PointId a, SlotId slot);
  JointId addPinInSlot(PointId a, SlotId slot);
  // theta_b - theta_c = ratio (theta_a - theta_c), c the carrier (none: the ground).
  JointId addGear(PointId a, PointId b, double ratio, BodyId carrier = {});
  // A joint with its fields as given (what a kind does not read is left unset by the caller).
  JointId addJoint(Joint j);
  // A load as given, with a new id.
  LoadId addLoad(Load l);

  // Removal cascades to what cannot stand without the entity: a joint takes the driver along if
  // it is the driver's; a point its joints and its place among the outputs; a slot its joints;
  // a body its points and slots (and so their joints) and the joints it carries; a point or a
  // body the loads on it and the cycle diagram's rows, windows and clearances that follow it
  // (and a window the conflicts that name it). Ids this mechanism
  // does not hold are ignored. The Removal undoes it exactly with restore(), as long as nothing
  // else changed in between (what an undo stack guarantees).
  Removal remove(const std::vector<BodyId>& bodies, const std::vector<PointId>& points = {},
                 const std::vector<SlotId>& slots = {}, const std::vector<JointId>& joints = {});
  // (Spelled out: remove({id}) would call this overload again.)
  Removal remove(BodyId id) { return remove(std::vector<BodyId>{id}); }
  Removal remove(PointId id) { return remove({}, {id}); }
  Removal remove(SlotId id) { return remove({}, {}, {id}); }
  Removal remove(JointId id) { return remove({}, {}, {}, {id}); }
  void restore(const Removal& r);

  // Lookups return nullptr when the id is unknown (or another mechanism's).
  const Body* body(BodyId id) const;
  const Point* point(PointId id) const;
  const Slot* slot(SlotId id) const;
  const Joint* joint(JointId id) const;
  Body* body(BodyId id);
  Point* point(PointId id);
  Slot* slot(SlotId id);
  Joint* joint(JointId id);
  const Load* load(LoadId id) const;
  Load* load(LoadId id);
  bool contains(BodyId id) const { return body(id) != nullptr; }
  bool contains(PointId id) const { return point(id) != nullptr; }
  bool contains(SlotId id) const { return slot(id) != nullptr; }
  bool contains(JointId id) const { return joint(id) != nullptr; }

  const Body* bodyNamed(const std::string& name) const;
  const Point* pointNamed(BodyId body, const std::string& name) const;
  const Slot* slotNamed(BodyId body, const std::string& name) const;
  const Body* ground() const;  // nullptr when there is none

  // "body.point" as the file and the command line spell it.
  std::string pointLabel(PointId id) const;
  std::string slotLabel(SlotId id) const;
  // "body.point", "body.P-Q" (a segment), "body.slot".
  std::string partLabel(const ClearancePart& part) const;
  // "the point hook.K", "the segment needlebar.N-G", "the slot ground.plate".
  std::string partDescription(const ClearancePart& part) const;
  // (A joint's label names its kind: jointLabel() in linkage/elements.h.)
  int jointIndex(JointId id) const;  // -1 when unknown

  // Resolves "body.point"; nullopt when either name is unknown.
  std::optional<PointId> findPoint(const std::string& dotted) const;

  // The tag every id made here carries (copies share it).
  std::uint32_t owner() const { return owner_; }

 private:
  template <class IdT>
  IdT make() {
    return IdT{nextId_++, owner_};
  }
  std::uint32_t owner_;
  std::uint32_t nextId_ = 1;
};

// Whether b is a with other dimensions only: the same bodies, points, slots, joints and driver
// (ids, kinds, connections, start angle and direction), with points or slots moved. The bodies
// whose shape changed go to `reshaped`. Such an edit can be re-solved group by group from the
// current pose; anything else is a new mechanism.
bool sameTopology(const Mechanism& a, const Mechanism& b, std::vector<BodyId>& reshaped);

}  // namespace linkage
