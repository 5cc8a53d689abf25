#include "cycle/clearance_selection.h"

#include <utility>
#include <vector>

#include "tools/selection.h"

namespace linkage::ui {

QString clearanceOfSelection(const Mechanism& m, const Selection& s) {
  std::vector<std::vector<PointId>> things;
  for (PointId p : s.points) things.push_back({p});
  for (JointId j : s.joints)
    if (const Joint* joint = m.joint(j)) {
      things.push_back({joint->a});
      if (joint->b) things.back().push_back(joint->b);
    }
  const size_t n = things.size();
  const Slot* slot = s.slots_.size() == 1 ? m.slot(s.slots_[0]) : nullptr;
  if (!s.bodies.empty() || s.slots_.size() != (slot ? 1u : 0u)) return {};
  if (slot ? n != 1 : n < 2 || n > 3) return {};
  auto body = [&](PointId p) { return m.point(p) ? m.point(p)->body : BodyId{}; };
  auto name = [&](PointId p) { return m.pointLabel(p); };
  // Every choice of one point per thing, in order.
  std::vector<std::vector<PointId>> choices{{}};
  for (const std::vector<PointId>& t : things) {
    std::vector<std::vector<PointId>> next;
    for (const std::vector<PointId>& c : choices)
      for (PointId p : t) {
        next.push_back(c);
        next.back().push_back(p);
      }
    choices = std::move(next);
  }
  for (const std::vector<PointId>& c : choices) {
    if (slot && body(c[0]) != slot->body)
      return QString::fromStdString(name(c[0]) + " " + m.slotLabel(slot->id));
    if (n == 2 && c[0] != c[1] && body(c[0]) != body(c[1]))
      return QString::fromStdString(name(c[0]) + " " + name(c[1]));
    for (size_t lone = 0; n == 3 && lone < 3; ++lone) {
      const PointId p = c[lone], a = c[lone == 0 ? 1 : 0], b = c[lone == 2 ? 1 : 2];
      if (a != b && body(a) == body(b) && body(p) != body(a))
        return QString::fromStdString(name(p) + " " + m.partLabel(ClearancePart::segment(a, b)));
    }
  }
  // None as it should be: what was asked, for the entry to say what is wrong with it (two
  // points of one body keep their distance, but may be watched).
  if (slot) return QString::fromStdString(name(things[0][0]) + " " + m.slotLabel(slot->id));
  if (n == 2 && things[0][0] != things[1][0])
    return QString::fromStdString(name(things[0][0]) + " " + name(things[1][0]));
  return {};
}

}  // namespace linkage::ui
