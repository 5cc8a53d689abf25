// Shared by the benchmark files.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "linkage/io/model_file.h"

namespace linkage::bench {

// An example mechanism by name; a benchmark cannot run without it, so it aborts with the reason.
inline Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  if (!r.mechanism) {
    std::fprintf(stderr, "%s\n", r.error.c_str());
    std::abort();
  }
  return *r.mechanism;
}

}  // namespace linkage::bench
