// The example mechanisms (resources/examples) by name, for tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "linkage/io/model_file.h"
#include "linkage/timing.h"

namespace linkage::test {

// The example's mechanism; a failure of the test (and an empty mechanism) when it cannot be read.
inline Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

// The example with a timing window as `linkage-cli timing --window` types it ("low=P:z>6").
inline Mechanism exampleWithWindow(const std::string& name, const std::string& window) {
  Mechanism m = example(name);
  std::string why;
  const std::optional<CycleWindow> w = parseWindow(m, window, &why);
  EXPECT_TRUE(w) << why;
  if (w) m.timing.windows.push_back({w->name, w->output.measure, w->below, w->level});
  return m;
}

}  // namespace linkage::test
