// The search's variables on a design: see optimize/variables.h.
#include <algorithm>

#include "optimize/variables.h"

#include <cmath>
#include <optional>

#include "analysis/sensitivity_space.h"
#include "linkage/guide.h"
#include "linkage/space.h"

namespace linkage::opt {

Vec2 Variables::moment(const std::vector<double>& x, size_t k) const {
  Vec2 s = Vec2::Zero();
  for (size_t v = 0; v < cw.size(); ++v)
    if (cw[v] == static_cast<int>(k)) s[axis[v]] = x[v];
  return s;
}

double Variables::kg(const std::vector<double>& x, size_t k) const {
  return moment(x, k).norm() / counterweights[k].maxRadiusMm;
}

bool counterweightName(const std::string& name, std::string& body, int& axis) {
  static const std::string tail = ".counterweight.";
  const size_t at = name.rfind(tail);
  if (at == std::string::npos || at == 0 || name.size() != at + tail.size() + 1) return false;
  const char a = name.back();
  if (a != 'x' && a != 'y') return false;
  body = name.substr(0, at);
  axis = a == 'x' ? 0 : 1;
  return true;
}

namespace {

Status addCounterweight(const Mechanism& base, const std::string& name, const std::string& body,
                        int axis, Variables& out) {
  const Body* b = base.bodyNamed(body);
  if (!b) return Status::badModel("'" + name + "': no body '" + body + "' in the design");
  size_t k = 0;
  while (k < out.counterweights.size() && out.counterweights[k].body != b->id) ++k;
  if (k == out.counterweights.size()) {
    Counterweight c;
    if (Status s = counterweightOn(base, b->id, c); !s.ok())
      return Status::badModel("'" + name + "': " + s.message);
    out.counterweights.push_back(c);
  }
  for (size_t v = 0; v < out.cw.size(); ++v)
    if (out.cw[v] == static_cast<int>(k) && out.axis[v] == axis)
      return Status::badModel("'" + name + "' is given twice");
  out.dim.push_back(-1);
  out.cw.push_back(static_cast<int>(k));
  out.axis.push_back(axis);
  return Status::success();
}

// A straight slot's angle varied with its offset: setDimensions turns the slot about its first
// end and then gives the offset back its value (optimize_apply.cpp), so the design moves as the
// turn less the offset's change, k = perp(n) . (p0 - from) per radian (n turns with the slot;
// `from` as dimensions() measures the offset): both ends go back along n by it, the direction
// the gradient must be of.
// On a machine in space a ground slot turns about its first end w0 in its block's plane (normal
// n; analysis/dimension_change_space.cpp), and its offset across . w0 (across = n x t, t along
// the slot) changes by -(t . w0) per radian as across turns to -t: both ends go along across by
// (t . w0) per radian to give it back.
void holdOffsetInSpace(const Mechanism& design, Dimension& angle) {
  const Slot* slot = design.slot(angle.slots[0].slot);
  if (!slot || slot->arc() || !design.body(slot->body)->ground) return;
  const PlaneClasses pc = planeClasses(design);
  const int cls = internal::groundSlotClass(design, pc, *slot);
  if (cls < 0) return;
  const Vec3 w0(slot->p0.x(), slot->p0.y(), slot->z.size() > 0 ? slot->z[0] : 0.0);
  const Vec3 w1(slot->p1.x(), slot->p1.y(), slot->z.size() > 1 ? slot->z[1] : 0.0);
  const Vec3 n = pc.frames[cls].normal(), t = (w1 - w0).normalized(), across = n.cross(t);
  const Vec3 back = t.dot(w0) * (M_PI / 180) * across;
  Dimension::SlotMove& move = angle.slots[0];
  move.p0 += back.head<2>();
  move.p1 += back.head<2>();
  move.z0 += back.z();
  move.z1 += back.z();
}

void holdOffset(const Mechanism& design, Dimension& angle) {
  if (angle.slots.size() != 1) return;
  if (isSpatial(design)) return holdOffsetInSpace(design, angle);
  const Slot* slot = design.slot(angle.slots[0].slot);
  const std::optional<Guide> g = slot ? guideOf(*slot) : std::nullopt;
  if (!g || g->arc) return;
  Vec2 from = Vec2::Zero();
  if (!design.body(slot->body)->ground)
    for (const Point& q : design.points)
      if (q.body == slot->body) {
        from = q.pos;
        break;
      }
  const Vec2 back = perp(g->normal).dot(slot->p0 - from) * (M_PI / 180) * g->normal;
  angle.slots[0].p0 -= back;
  angle.slots[0].p1 -= back;
}

}  // namespace

Status mapVariables(const Mechanism& base, const Mechanism& design, const OptimizeSpec& spec,
                    Variables& out) {
  out = Variables{};
  const std::vector<Dimension> all = dimensions(design);
  for (const OptVariable& v : spec.variables) {
    std::string body;
    int axis = 0;
    if (counterweightName(v.name, body, axis)) {
      if (Status s = addCounterweight(base, v.name, body, axis, out); !s.ok()) return s;
      continue;
    }
    auto it =
        std::find_if(all.begin(), all.end(), [&](const Dimension& d) { return d.name == v.name; });
    if (it == all.end()) return Status::badModel("no dimension '" + v.name + "' in the design");
    out.dim.push_back(static_cast<int>(out.dims.size()));
    out.cw.push_back(-1);
    out.axis.push_back(0);
    out.dims.push_back(*it);
  }
  for (Dimension& d : out.dims) {
    if (!d.name.ends_with(".angle") || d.slots.empty()) continue;
    const std::string offset = d.name.substr(0, d.name.size() - 6) + ".offset";
    if (std::any_of(spec.variables.begin(), spec.variables.end(),
                    [&](const OptVariable& v) { return v.name == offset; }))
      holdOffset(design, d);
  }
  return Status::success();
}

}  // namespace linkage::opt
