// A slot's move with a dimension (linkage/slot_sensitivity.h).
#include "linkage/slot_sensitivity.h"

#include <Eigen/LU>

#include "linkage/guide.h"

namespace linkage {

SlotChange slotChange(const Mechanism& m, SlotId id, const Dimension& d) {
  SlotChange out;
  const Slot* slot = m.slot(id);
  const std::optional<Guide> g = slot ? guideOf(*slot) : std::nullopt;
  if (!g) return out;
  for (const Dimension::SlotMove& s : d.slots) {
    if (s.slot != id) continue;
    out.p0 += s.p0;
    out.p1 += s.p1;
    if (!g->arc || !s.mid) continue;
    Eigen::Matrix3d A;
    Eigen::Vector3d b;
    const Vec2 p[3] = {slot->p0, *slot->mid, slot->p1}, dp[3] = {s.p0, *s.mid, s.p1};
    for (int i = 0; i < 3; ++i) {
      const Vec2 r = p[i] - g->centre;
      A.row(i) << r.x(), r.y(), g->radius;
      b[i] = r.dot(dp[i]);
    }
    const Eigen::Vector3d x = A.partialPivLu().solve(b);
    out.centre += x.head<2>();
    out.radius += x[2];
  }
  return out;
}

}  // namespace linkage
