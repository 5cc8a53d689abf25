// The element kinds a joint can be (pin, slider, pin-in-slot, gear), each described once, in
// its own files under solver/elements/ (equations on top), and registered in one table
// (elements/registry.cpp). Everything else asks this table; nothing else branches on the kind.
//
// A kind is: its file fields (which it reads, which it needs, and what it checks beyond the
// references), its rows (what it compiles to: elements/rows.h), what it says of the instant
// centre of the bodies it joins, its structural role and equation count, and the symbol it is
// drawn with. docs/solver.md says how to add one.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "linkage/model.h"

namespace linkage {

struct Row;    // elements/rows.h
class Frames;  // elements/frames.h: how the compiler places points in body frames

// Positions at a pose, as a drawing or the instant centres see them.
struct Pose {
  virtual ~Pose() = default;
  virtual Vec2 point(PointId p) const = 0;
  virtual Transform body(BodyId b) const = 0;
};

// How a pose changes along one dimension (linkage/sensitivity.h), for a kind's reactChange():
// the derivatives of each point's world position, of its drawn position, of a gear's ratio.
struct PoseChange {
  virtual ~PoseChange() = default;
  virtual Vec2 point(PointId p) const = 0;
  virtual Vec2 drawn(PointId p) const = 0;
  virtual double ratio(JointId j) const = 0;
};

// A field of a joint object in a file, as its kind declares it: the key, what it holds and where
// it goes in a Joint (points: a for index 0, b for 1; slot; carrier; numbers[index]; a flag,
// true or false, as numbers[index] 1 or 0; records: records[index], an array of objects whose
// members are numbers or strings, kept as written). The reader, the writer and the checks go by
// these alone, so a new kind needs no code of theirs. An optional number not given is NaN in
// numbers and not written; a flag is written only when true.
enum class FieldType : unsigned char { Point, Slot, Body, Number, Flag, Records };
struct FieldSpec {
  const char* key;
  FieldType type;
  unsigned char index;
  bool required;
};
// The joint's point of a Point field (a or b).
PointId pointField(const Joint& j, const FieldSpec& f);
PointId& pointField(Joint& j, const FieldSpec& f);

// What a kind does structurally. Revolute: two points are one (relative rotation free; the only
// role a driver can have). Prismatic: a block keeps its angle to a slot (drawn as a block).
// PointOnCurve: a point runs in a slot, rotation free. Coupling: the bodies' rotations are tied
// (gears, belts).
// Distance: two points keep their distance (a rod with a ball at each end).
// Contact: a higher pair, two bodies touching along a curve (a cam and its follower).
enum class Role : unsigned char { Revolute, Prismatic, PointOnCurve, Coupling, Distance, Contact };

// What a joint says by itself about the instant centre of two bodies, from sketch data: points
// p[k] fixed in body pBody[k], a direction n fixed in body nBody. At a pose (world coordinates):
//   AtPoint:     the centre is p[0].
//   AtInfinity:  the centre is at infinity in the direction n (relative translation normal to it).
//   LineAlong:   the centre is on the line through p[0] along n.
//   LineThrough: the centre is on the line through p[0] and p[1].
//   Weighted:    the centre is (p[0] - ratio p[1]) / (1 - ratio) (homogeneous: at infinity when
//                ratio = 1): where the two bodies' velocities are equal for a coupling.
//   PoseLine:    the centre is on a line that moves in both bodies (a cam's common normal): the
//                kind's centreLine() gives it at each pose.
enum class CentreRule : unsigned char {
  AtPoint,
  AtInfinity,
  LineAlong,
  LineThrough,
  Weighted,
  PoseLine
};
struct CentreData {
  CentreRule rule = CentreRule::AtPoint;
  BodyId bodies[2];  // the pair it is a centre of
  BodyId pBody[2];
  Vec2 p[2] = {Vec2::Zero(), Vec2::Zero()};
  BodyId nBody;
  Vec2 n = Vec2::Zero();
  double ratio = 0;
};

// A Line rule at a pose: a point of the line and its direction (z = 0), or two points
// (homogeneous, z = 1); false for the rules that give a point (and for PoseLine: see
// jointCentreLine()).
bool centreLineAt(const CentreData& c, const Pose& pose, Eigen::Vector3d through[2]);

// How a joint is drawn, in world millimetres at a pose: the kind's symbol() fills what does not
// move, its place() the rest at each pose.
struct JointSymbol {
  JointId joint;
  JointType type = JointType::Pin;
  BodyId bodies[2];  // the bodies it joins: of a and b, or of a and the slot
  BodyId carrier;    // a coupling's carrier (the ground's id when it has none)
  SlotId slot;
  bool groundPivot = false;  // one side is the ground
  Vec2 at = Vec2::Zero();    // the joint's point; a coupling: the centre of a
  Vec2 at2 = Vec2::Zero();   // a coupling: the centre of b
  // A block: along its slot where it is (an arc's tangent); a coupling: from a to b as drawn.
  Vec2 direction = Vec2::UnitX();
  double radius[2] = {0, 0};  // a coupling: pitch radii at a and b (pulleys for a belt)
  double angle[2] = {0, 0};   // a coupling: each body's rotation from the drawing (rad)
  bool belt = false;          // a coupling drawn as two pulleys and a belt
  // A cam: radius[0] its base circle's about `at` (its centre), radius[1] the roller's about
  // at2 (b); a flat face through at2 normal to `direction` as drawn (turned with angle[1]);
  // angle[0], angle[1] the cam's and the follower's rotations; `curve` its working surface in
  // its own frame about `at` (linkage/cam_geometry.h), to be turned by angle[0].
  bool face = false;
  std::vector<Vec2> curve;
  std::vector<Vec2> curve2;  // a cam with a roller: its pitch curve, in the same frame
};

// A joint's reaction at a pose (linkage/dynamics.h): the force on the body of its point a from
// the other side (N), where it acts (world mm) and the couple with it (N m, about `at`). Made
// from the joint's rows (a force at its point, a couple); a kind may state it otherwise
// (react(): a gear's couple as the tooth force at the pitch point).
//
// On a machine in space (linkage/space.h) `force` and `at` are in the frame of the joint's plane
// class, and a joint also carries what acts out of that plane (docs/dynamics.md, "Machines in
// space"): `normalN` along the class's normal and `tiltNm` about its x and y axes through `at`,
// from the out-of-plane load of the moving body it holds to the ground (a bearing); a ball rod
// its axial force `axialN` (tension positive); a gear the couple `transmittedNm` its rows put on
// a's body about its axis (a bevel pair: all it is computed with). A cam: the force on the cam
// from the follower along the common normal, at the cam's centre with its moment about it, and
// the contact force `contactN` (compression positive; elements/cam_row.h).
struct JointReaction {
  Vec2 force = Vec2::Zero();
  Vec2 at = Vec2::Zero();
  double coupleNm = 0;
  double normalN = 0;
  Vec2 tiltNm = Vec2::Zero();
  double axialN = 0;
  double transmittedNm = 0;
  double contactN = 0;
};

struct ElementKind {
  JointType type;     // its place in the table (set by the registry)
  const char* name;   // in files, messages and the command line
  const char* joins;  // what it joins, for messages: `joins points "a" and "b"`
  Role role;
  int equations;  // scalar equations (its rows)
  std::span<const FieldSpec> fields;

  // What the references alone do not check (a ratio of 0, a gear not on its carrier's pins):
  // the key of the field it is about and why, or an empty string when the joint is sound. The
  // references are known to resolve when it is called.
  std::string (*check)(const Mechanism& m, const Joint& j, const char*& where);
  // Its rows (elements/rows.h), appended to `rows`; false with `why` where it cannot have any.
  bool (*compile)(const Mechanism& m, const Joint& j, const Frames& f, std::vector<Row>& rows,
                  std::string& why);
  CentreData (*centre)(const Mechanism& m, const Joint& j);
  void (*symbol)(const Mechanism& m, const Joint& j, JointSymbol& s);
  void (*place)(const Mechanism& m, const Joint& j, const Pose& pose, JointSymbol& s);
  // The columns of its reaction in `linkage-cli dynamics`, after "<name>:<a>." (fx_N, ...),
  // and a restatement of its reaction (nullptr: as its rows make it), which may also adjust
  // others' (`all`, in Mechanism::joints order; `index` its own).
  std::span<const char* const> reactionColumns;
  void (*react)(const Mechanism& m, int index, const Pose& pose, std::vector<JointReaction>& all);
  // Whether it may join bodies of planes that are not parallel (linkage/space.h: a ball rod, a
  // bevel pair); the others join bodies of parallel planes only, which checkJoints() holds.
  bool anyPlanes;
  // A PoseLine centre (a cam's common normal) at a pose: a point of the line and its direction
  // (world mm); false where there is none. nullptr for the kinds whose rule is another.
  bool (*centreLine)(const Mechanism& m, const Joint& j, const Pose& pose, Vec2& through,
                     Vec2& along) = nullptr;
  // react() with its derivative along a dimension (linkage/force_sensitivity.h): `all` holds the
  // reactions as their rows make them and `change` their derivatives; both are restated as
  // react() restates `all`. nullptr where react() is.
  void (*reactChange)(const Mechanism& m, int index, const Pose& pose, const PoseChange& dpose,
                      std::vector<JointReaction>& all,
                      std::vector<JointReaction>& change) = nullptr;

  // Whether it has a field of this type (a slot, a second point, ...).
  bool reads(FieldType t, unsigned char index = 0) const;
  const FieldSpec* field(std::string_view key) const;
};

const ElementKind& elementKind(JointType t);
// nullptr for a name no kind has.
const ElementKind* elementKindNamed(std::string_view name);
// A joint's centre line at a pose, whatever its rule (a line through a point, through two, or
// one its kind computes at the pose), as centreLineAt() gives it; false for a point.
bool jointCentreLine(const Mechanism& m, const Joint& j, const Pose& pose,
                     Eigen::Vector3d through[2]);
// Every kind, in JointType order (the registry's table: elements/registry.cpp).
std::span<const ElementKind> elementKinds();
// Every key any kind reads, once each, in table order.
std::span<const char* const> elementFieldKeys();
// The names for a message: "pin", "slider", ... or "gear" (quoted).
std::string elementKindNames();
const char* toString(JointType t);
inline const ElementKind& kindOf(const Joint& j) {
  return elementKind(j.type);
}

// A joint as a person sees it, for messages about the mechanism (the solver's, the editor's):
// its kind and what it joins, "pin coupler.A - rocker.A", "slider slider4.E in disk.B".
std::string jointName(const Mechanism& m, JointId id);
// The same with its place in the file, for what names the file's entries (the command line's
// listings): `joints[2] (slider slider4.E in disk.B)`.
std::string jointLabel(const Mechanism& m, JointId id);
// A joint's rules beyond its references (which resolve): the planes of what it joins, for the
// kinds of parallel planes, and its kind's check(); "" when they hold, else why, with the key of
// the field at fault in `where`.
std::string checkJoint(const Mechanism& m, const Joint& j, const char*& where);
// Checks every joint's kind-specific rules (check()) in file order: "" when all hold, else the
// first problem as `joints[3].ratio: ...`, with the joint's index in `index`.
std::string checkJoints(const Mechanism& m, int* index = nullptr);
// Whether two kinds read the same fields (a joint can change from one into the other).
bool sameFields(JointType a, JointType b);

}  // namespace linkage
