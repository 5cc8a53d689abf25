// A slot's move with a dimension (linkage/slot_sensitivity.h).
#include "linkage/slot_sensitivity.h"

#include <Eigen/LU>

namespace linkage {

SlotChange slotChange(const Mechanism& m, SlotId id, const Dimension& d) {
  SlotChange out;
  const Slot* slot = m.slot(id);
  // The ends' moves whatever the drawing's x, y are (the ground's arc in a plane square to the
  // drawing has no circle in them: its centre and radius here are a planar machine's).
  const std::optional<Guide> g = slot ? guideOf(*slot) : std::nullopt;
  for (const Dimension::SlotMove& s : d.slots) {
    if (s.slot != id) continue;
    out.p0 += s.p0;
    out.p1 += s.p1;
    if (!g || !g->arc || !s.mid) continue;
    Vec2 dc;
    double drho;
    arcChange(*g, {slot->p0, *slot->mid, slot->p1}, {s.p0, *s.mid, s.p1}, dc, drho);
    out.centre += dc;
    out.radius += drho;
  }
  return out;
}

void arcChange(const Guide& g, const Vec2 (&p)[3], const Vec2 (&dp)[3], Vec2& dc, double& drho) {
  Eigen::Matrix3d A;
  Eigen::Vector3d b;
  for (int i = 0; i < 3; ++i) {
    const Vec2 r = p[i] - g.centre;
    A.row(i) << r.x(), r.y(), g.radius;
    b[i] = r.dot(dp[i]);
  }
  const Eigen::Vector3d x = A.partialPivLu().solve(b);
  dc = x.head<2>();
  drho = x[2];
}

}  // namespace linkage
