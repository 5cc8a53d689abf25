// The example mechanisms (resources/examples) by name, for tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "linkage/io/model_file.h"

namespace linkage::test {

// A test that cannot load the example fails here, with the reader's message.
inline Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

}  // namespace linkage::test
