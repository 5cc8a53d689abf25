#include "elements/slot_joint.h"

#include "elements/frames.h"

namespace linkage::slot_joint {

std::optional<Guide> guide(const Frames& f, const Joint& j, std::string& why) {
  return guideOf(*f.slot(j.slot), &why);
}

CentreData pair(const Mechanism& m, const Joint& j) {
  CentreData c;
  c.bodies[0] = m.point(j.a)->body;
  c.bodies[1] = m.slot(j.slot)->body;
  return c;
}

void symbol(const Mechanism& m, const Joint& j, JointSymbol& s) {
  const Point* a = m.point(j.a);
  const Slot* sl = m.slot(j.slot);
  s.bodies[0] = a ? a->body : BodyId{};
  s.bodies[1] = sl ? sl->body : BodyId{};
  s.slot = j.slot;
}

void place(const Mechanism& m, const Joint& j, const Pose& pose, JointSymbol& s) {
  s.at = pose.point(j.a);
  const Slot* sl = m.slot(j.slot);
  const std::optional<Guide> g = sl ? guideOf(*sl) : std::nullopt;
  if (!g) return;
  const Transform T = pose.body(sl->body);
  s.direction = T.R * g->tangentAt(T.inverse(s.at));
}

}  // namespace linkage::slot_joint
