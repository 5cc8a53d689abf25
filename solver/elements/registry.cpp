// The one table of element kinds (linkage/elements.h), in JointType order, and what every kind
// shares: lookups by name, the fields read and checked by their specs.
#include <algorithm>

#include "elements/ball_rod.h"
#include "elements/cam.h"
#include "elements/gear.h"
#include "elements/pin.h"
#include "elements/pin_in_slot.h"
#include "elements/slider.h"
#include "linkage/elements.h"
#include "linkage/space.h"

namespace linkage {

namespace {

// The table: one line a kind. A kind's place here is its JointType.
using Make = ElementKind (*)(JointType);
constexpr Make kMakers[] = {pinElement,  sliderElement,  pinInSlotElement,
                            gearElement, ballRodElement, camElement};

std::vector<ElementKind> makeTable() {
  std::vector<ElementKind> kinds;
  for (size_t i = 0; i < std::size(kMakers); ++i)
    kinds.push_back(kMakers[i](JointType{static_cast<std::uint8_t>(i)}));
  return kinds;
}

}  // namespace

std::span<const ElementKind> elementKinds() {
  static const std::vector<ElementKind> kinds = makeTable();
  return kinds;
}

std::span<const char* const> elementFieldKeys() {
  static const std::vector<const char*> keys = [] {
    std::vector<const char*> out;
    for (const ElementKind& k : elementKinds())
      for (const FieldSpec& f : k.fields)
        if (std::none_of(out.begin(), out.end(),
                         [&](const char* key) { return std::string_view(key) == f.key; }))
          out.push_back(f.key);
    return out;
  }();
  return keys;
}

const ElementKind& elementKind(JointType t) {
  const auto kinds = elementKinds();
  return kinds[t.index < kinds.size() ? t.index : 0];
}

const ElementKind* elementKindNamed(std::string_view name) {
  for (const ElementKind& k : elementKinds())
    if (name == k.name) return &k;
  return nullptr;
}

std::string elementKindNames() {
  std::string s;
  const auto kinds = elementKinds();
  const size_t n = kinds.size();
  for (size_t i = 0; i < n; ++i)
    s += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + "\"" + kinds[i].name + "\"";
  return s;
}

const char* toString(JointType t) {
  return elementKind(t).name;
}

PointId pointField(const Joint& j, const FieldSpec& f) {
  return f.index == 0 ? j.a : j.b;
}
PointId& pointField(Joint& j, const FieldSpec& f) {
  return f.index == 0 ? j.a : j.b;
}

bool ElementKind::reads(FieldType t, unsigned char index) const {
  return std::any_of(fields.begin(), fields.end(),
                     [&](const FieldSpec& s) { return s.type == t && s.index == index; });
}

const FieldSpec* ElementKind::field(std::string_view key) const {
  for (const FieldSpec& f : fields)
    if (key == f.key) return &f;
  return nullptr;
}

bool sameFields(JointType a, JointType b) {
  const ElementKind &x = elementKind(a), &y = elementKind(b);
  if (x.fields.size() != y.fields.size()) return false;
  for (const FieldSpec& f : x.fields) {
    const FieldSpec* g = y.field(f.key);
    if (!g || g->type != f.type || g->index != f.index) return false;
  }
  return true;
}

bool centreLineAt(const CentreData& c, const Pose& pose, Eigen::Vector3d through[2]) {
  if (c.rule != CentreRule::LineAlong && c.rule != CentreRule::LineThrough) return false;
  const Vec2 p = pose.body(c.pBody[0]) * c.p[0];
  through[0] = Eigen::Vector3d(p.x(), p.y(), 1);
  if (c.rule == CentreRule::LineThrough) {
    const Vec2 q = pose.body(c.pBody[1]) * c.p[1];
    through[1] = Eigen::Vector3d(q.x(), q.y(), 1);
  } else {
    const Vec2 n = pose.body(c.nBody).R * c.n;
    through[1] = Eigen::Vector3d(n.x(), n.y(), 0);
  }
  return true;
}

bool jointCentreLine(const Mechanism& m, const Joint& j, const Pose& pose,
                     Eigen::Vector3d through[2]) {
  const ElementKind& k = kindOf(j);
  const CentreData c = k.centre(m, j);
  if (c.rule != CentreRule::PoseLine) return centreLineAt(c, pose, through);
  Vec2 p, n;
  if (!k.centreLine || !k.centreLine(m, j, pose, p, n)) return false;
  through[0] = Eigen::Vector3d(p.x(), p.y(), 1);
  through[1] = Eigen::Vector3d(n.x(), n.y(), 0);
  return true;
}

std::string jointName(const Mechanism& m, JointId id) {
  const Joint* j = m.joint(id);
  if (!j) return "unknown joint";
  const ElementKind& k = kindOf(*j);
  if (k.reads(FieldType::Slot))
    return std::string(k.name) + " " + m.pointLabel(j->a) + " in " + m.slotLabel(j->slot);
  return std::string(k.name) + " " + m.pointLabel(j->a) + " - " + m.pointLabel(j->b);
}

std::string jointLabel(const Mechanism& m, JointId id) {
  if (!m.joint(id)) return "unknown joint";
  return "joints[" + std::to_string(m.jointIndex(id)) + "] (" + jointName(m, id) + ")";
}

namespace {

// The first field of j whose reference the mechanism does not hold.
std::string unresolved(const Mechanism& m, const Joint& j, const char*& where) {
  for (const FieldSpec& f : kindOf(j).fields) {
    where = f.key;
    switch (f.type) {
      case FieldType::Point:
        if (!m.contains(pointField(j, f))) return "unknown reference";
        break;
      case FieldType::Slot:
        if (!m.contains(j.slot)) return "unknown reference";
        break;
      case FieldType::Body:
        if (j.carrier && !m.contains(j.carrier)) return "unknown body";
        break;
      case FieldType::Number:
      case FieldType::Flag:
      case FieldType::Records:
        break;
    }
  }
  return {};
}

std::string planeLabel(const Mechanism& m, BodyId b) {
  const Body* body = m.body(b);
  return body && !body->ground && !body->plane.empty() ? body->plane : "drawing";
}

// Whether a ground slot lies parallel to a plane of normal n: each of its written ends (an arc's
// middle too) seen from its first along a direction within 1e-9 of the plane. Ends written
// [x, y] are in the drawing plane, z = 0, which a block in a plane across it does not run along.
bool groundSlotParallel(const Slot& s, const Vec3& n) {
  std::vector<Vec2> at{s.p0};
  if (s.mid) at.push_back(*s.mid);
  at.push_back(s.p1);
  auto end = [&](size_t i) {
    return Vec3(at[i].x(), at[i].y(), s.z.size() == at.size() ? s.z[i] : 0.0);
  };
  for (size_t i = 1; i < at.size(); ++i) {
    const Vec3 d = end(i) - end(0);
    if (d.norm() > 0 && std::abs(d.normalized().dot(n)) > 1e-9) return false;
  }
  return true;
}

// A kind of parallel planes: the bodies it joins are of parallel planes, the ground's slot
// parallel to them; "" when they are, else why, with the key of the field at fault.
std::string planesOf(const Mechanism& m, const Joint& j, const char*& where) {
  const ElementKind& k = kindOf(j);
  std::vector<std::pair<BodyId, const char*>> sides;
  for (const FieldSpec& f : k.fields) {
    if (f.type == FieldType::Point) sides.push_back({m.point(pointField(j, f))->body, f.key});
    if (f.type == FieldType::Slot) sides.push_back({m.slot(j.slot)->body, f.key});
  }
  const Body* g = m.ground();
  auto moving = [&](BodyId b) { return !g || b != g->id; };
  BodyId first;  // the body whose plane the joint is written in
  for (const auto& [b, key] : sides)
    if (!first && moving(b)) first = b;
  if (!first) return {};
  const Plane& plane = planeOf(m, first);
  for (const auto& [b, key] : sides) {
    if (!moving(b) || parallel(planeOf(m, b), plane)) continue;
    where = key;
    return std::string("a ") + k.name + " joins bodies of parallel planes only: \"" +
           m.body(first)->name + "\" moves in plane \"" + planeLabel(m, first) + "\", \"" +
           m.body(b)->name + "\" in \"" + planeLabel(m, b) + "\" (a ball rod joins any planes)";
  }
  const Slot* s = k.reads(FieldType::Slot) ? m.slot(j.slot) : nullptr;
  if (s && m.body(s->body)->ground && !groundSlotParallel(*s, plane.normal())) {
    where = "slot";
    return "the ground's slot " + m.slotLabel(s->id) + " is not parallel to plane \"" +
           planeLabel(m, first) + "\" of its block (to 1e-9)";
  }
  return {};
}

}  // namespace

std::string checkJoint(const Mechanism& m, const Joint& j, const char*& where) {
  std::string why = kindOf(j).anyPlanes ? std::string() : planesOf(m, j, where);
  return why.empty() ? kindOf(j).check(m, j, where) : why;
}

std::string checkJoints(const Mechanism& m, int* index) {
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    const char* where = "a";
    std::string why = unresolved(m, j, where);
    if (why.empty()) why = checkJoint(m, j, where);
    if (why.empty()) continue;
    if (index) *index = static_cast<int>(i);
    return "joints[" + std::to_string(i) + "]." + where + ": " + why;
  }
  return {};
}

}  // namespace linkage
