#include "tools/selection.h"

namespace linkage::ui {

void Selection::prune(const Mechanism& m) {
  const int before = size();
  auto keep = [&](auto& v) {
    v.erase(std::remove_if(v.begin(), v.end(), [&](auto id) { return !m.contains(id); }), v.end());
  };
  keep(points);
  keep(bodies);
  keep(joints);
  keep(slots_);
  if (size() != before) emit changed();
}

}  // namespace linkage::ui
