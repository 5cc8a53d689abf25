#include "joints/registry.h"

#include <iterator>

namespace linkage {

namespace {

// Indexed by JointType.
constexpr JointKind kKinds[] = {
    {JointType::Pin, "pin", false, {RowKind::Pin}, 1, CentreRule::AtPoint},
    {JointType::Slider, "slider", true, {RowKind::Line, RowKind::Angle}, 2, CentreRule::AtInfinity},
    {JointType::PinInSlot, "pin-in-slot", true, {RowKind::Line}, 1, CentreRule::OnNormal},
};

}  // namespace

const JointKind& jointKind(JointType t) {
  return kKinds[static_cast<int>(t)];
}

const JointKind* jointKindNamed(std::string_view name) {
  for (const JointKind& k : kKinds)
    if (name == k.name) return &k;
  return nullptr;
}

std::string jointKindNames() {
  std::string s;
  const size_t n = std::size(kKinds);
  for (size_t i = 0; i < n; ++i)
    s += std::string(i == 0 ? "" : i + 1 == n ? " or " : ", ") + "\"" + kKinds[i].name + "\"";
  return s;
}

// Each entry in its type's place.
constexpr bool inTypeOrder() {
  for (size_t i = 0; i < std::size(kKinds); ++i)
    if (static_cast<size_t>(kKinds[i].type) != i) return false;
  return true;
}
static_assert(inTypeOrder());

}  // namespace linkage
