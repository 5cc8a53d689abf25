// Whether the tests run under a sanitizer or without optimisation, where the tests that try
// many random cases try fewer.
#pragma once

namespace linkage::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__OPTIMIZE__) == 0
constexpr bool kSlowBuild = true;
#else
constexpr bool kSlowBuild = false;
#endif

}  // namespace linkage::test
