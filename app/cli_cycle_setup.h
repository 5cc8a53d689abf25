// What `linkage-cli timing` and its figure (linkage-plot cycle-diagram) work on: the windows
// and conflicts the command line gives, or, when it gives no window, the file's "timing" (its
// rows, windows and conflicts), with any --conflict added.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "linkage/timing.h"

namespace linkage::cli {

struct CycleSetup {
  std::vector<CycleOutput> outputs;
  std::vector<CycleWindow> windows;
  std::vector<std::pair<std::string, std::string>> conflicts;
};

// nullopt when a part does not parse or there is no window at all (the error printed, naming
// the option or the file's field).
std::optional<CycleSetup> cycleSetup(const Mechanism& m, const std::vector<std::string>& windows,
                                     const std::vector<std::string>& conflicts);

}  // namespace linkage::cli
