// The example mechanisms of resources/examples/, by name, for tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "linkage/io/model_file.h"

namespace linkage::test {

// The example loaded; an empty mechanism (and a failed expectation) when it cannot be.
inline Mechanism example(const std::string& name) {
  LoadResult r =
      loadMechanismFile(std::string(LINKAGE_EXAMPLES_DIR) + "/" + name + ".linkage.json");
  EXPECT_TRUE(r.mechanism.has_value()) << r.error;
  return r.mechanism ? *r.mechanism : Mechanism{};
}

}  // namespace linkage::test
