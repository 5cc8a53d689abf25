// The one table of element kinds (linkage/elements.h), in JointType order.
#include <algorithm>

#include "elements/gear.h"
#include "elements/pin.h"
#include "elements/pin_in_slot.h"
#include "elements/slider.h"
#include "linkage/elements.h"

namespace linkage {

std::span<const ElementKind* const> elementKinds() {
  static const ElementKind* const kinds[] = {&pinElement(), &sliderElement(), &pinInSlotElement(),
                                             &gearElement()};
  return kinds;
}

const ElementKind& elementKind(JointType t) {
  return *elementKinds()[static_cast<size_t>(t)];
}

const ElementKind* elementKindNamed(std::string_view name) {
  for (const ElementKind* k : elementKinds())
    if (name == k->name) return k;
  return nullptr;
}

std::string elementKindNames() {
  std::string s;
  const auto kinds = elementKinds();
  const size_t n = kinds.size();
  for (size_t i = 0; i < n; ++i)
    s += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + "\"" + kinds[i]->name + "\"";
  return s;
}

const char* toString(JointType t) {
  return elementKind(t).name;
}

const char* fieldKey(JointField f) {
  static const char* const keys[] = {"a", "b", "slot", "carrier", "ratio"};
  return keys[static_cast<int>(f)];
}

bool ElementKind::reads(JointField f) const {
  return std::any_of(fields.begin(), fields.end(),
                     [&](const FieldSpec& s) { return s.field == f; });
}

bool sameFields(JointType a, JointType b) {
  const ElementKind &x = elementKind(a), &y = elementKind(b);
  if (x.fields.size() != y.fields.size()) return false;
  for (const FieldSpec& f : x.fields)
    if (!y.reads(f.field)) return false;
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

std::string jointName(const Mechanism& m, JointId id) {
  const Joint* j = m.joint(id);
  if (!j) return "unknown joint";
  const ElementKind& k = kindOf(*j);
  if (k.reads(JointField::Slot))
    return std::string(k.name) + " " + m.pointLabel(j->a) + " in " + m.slotLabel(j->slot);
  return std::string(k.name) + " " + m.pointLabel(j->a) + " - " + m.pointLabel(j->b);
}

std::string jointLabel(const Mechanism& m, JointId id) {
  if (!m.joint(id)) return "unknown joint";
  return "joints[" + std::to_string(m.jointIndex(id)) + "] (" + jointName(m, id) + ")";
}

namespace {

// The first field of j whose reference the mechanism does not hold.
std::string unresolved(const Mechanism& m, const Joint& j, JointField& where) {
  for (const FieldSpec& f : kindOf(j).fields) {
    where = f.field;
    const bool ok = f.field == JointField::A         ? m.contains(j.a)
                    : f.field == JointField::B       ? m.contains(j.b)
                    : f.field == JointField::Slot    ? m.contains(j.slot)
                    : f.field == JointField::Carrier ? !j.carrier || m.contains(j.carrier)
                                                     : true;
    if (!ok) return f.field == JointField::Carrier ? "unknown body" : "unknown reference";
  }
  return {};
}

}  // namespace

std::string checkJoints(const Mechanism& m, int* index) {
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const Joint& j = m.joints[i];
    JointField where = JointField::A;
    std::string why = unresolved(m, j, where);
    if (why.empty()) why = kindOf(j).check(m, j, where);
    if (why.empty()) continue;
    if (index) *index = static_cast<int>(i);
    return "joints[" + std::to_string(i) + "]." + fieldKey(where) + ": " + why;
  }
  return {};
}

}  // namespace linkage
