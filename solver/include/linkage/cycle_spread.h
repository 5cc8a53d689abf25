// The spread of a watched clearance's closest approach and of a timing window's ends under
// tolerances (issue 29: "timing windows' ends and clearance minima with their spread"). First
// order from their exact derivatives (linkage/clearance_sensitivity.h, window_sensitivity.h):
// worst case sum |d/dp_k| T_k and root sum of squares; Monte Carlo from the same samples as
// linkage/tolerance.h draws (toleranceSample: the seed and each sample's index), each sample
// solved exactly from the nominal's branches and measured as the nominal is (its own closest
// approach; its window's intervals, matched to the nominal's by order). Dimensions only: a pin's
// play is refused here (the point's band carries it).
#pragma once

#include <string>
#include <vector>

#include "linkage/tolerance.h"

namespace linkage {

struct Spread {
  double nominal = 0;
  double worst = 0, rss = 0;                // first order: half-widths
  double lo = 0, hi = 0, mean = 0, sd = 0;  // the samples' (none: lo = hi = nominal)
};

struct SpreadResult {
  Status status;
  std::vector<Spread> values;  // the closest approach; or each interval's start, then its end
  int samples = 0, used = 0;
  std::string firstFailure;  // the first sample that did not assemble, turn or match, and why
};

// spec.point is not read; spec.tolerances hold dimensions only; spec.samples, seed as there.
SpreadResult clearanceSpread(const Mechanism& m, const ToleranceSpec& spec,
                             const ClearanceWatch& w);
SpreadResult windowSpread(const Mechanism& m, const ToleranceSpec& spec, const std::string& name);

}  // namespace linkage
