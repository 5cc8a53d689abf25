// The Python model's optimiser: linkage-cli optimize's search and its text for targets
// (linkage/optimize_text.h).
#include "linkage/optimize_text.h"
#include "py_model.h"

namespace linkage::py {

Model::Optimized Model::optimize(const std::vector<Bounds>& vary,
                                 const std::vector<std::string>& targets, int starts,
                                 std::uint64_t seed, int steps, bool apply) {
  OptimizeSpec spec;
  spec.starts = starts;
  spec.seed = seed;
  spec.steps = steps;
  for (const Bounds& b : vary) spec.variables.push_back({b.name, b.lo, b.hi});
  Optimized out;
  for (const std::string& text : targets) {
    OptTarget t;
    std::string why;
    if (!parseOptTarget(design_, text, t, why)) throw BadInput(why);
    spec.targets.push_back(t);
    out.targetNames.push_back(optTargetName(design_, t));
  }
  out.result = linkage::optimize(base_, spec);
  if (!out.result.status.ok()) throw BadInput("optimize: " + out.result.status.message);
  if (apply) commit(out.result.design);
  return out;
}

}  // namespace linkage::py
