// Any bytes: the reader must not crash, must either load or explain, and whatever it loads must
// survive a save and a reload unchanged.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "linkage/io/model_file.h"

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail, const std::string& text) {
  std::fprintf(stderr, "fuzz_model_reader: %s: %s\n--- serialized ---\n%s\n", what, detail.c_str(),
               text.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view input(reinterpret_cast<const char*>(data), size);
  linkage::LoadResult first = linkage::parseMechanism(input);
  if (first.mechanism.has_value() == !first.error.empty())
    fail("exactly one of mechanism and error must be set", first.error, "");
  if (first.error.rfind("internal error", 0) == 0) fail("reader bug", first.error, "");
  if (!first.mechanism) return 0;

  std::string text = linkage::serializeMechanism(*first.mechanism);
  linkage::LoadResult second = linkage::parseMechanism(text);
  if (!second.mechanism) fail("a saved file does not load", second.error, text);
  std::string diff = linkage::mechanismDifference(*first.mechanism, *second.mechanism);
  if (!diff.empty()) fail("round trip changed the mechanism", diff, text);
  // Ids are assigned in file order, so a reload must reproduce their numbers too (each
  // mechanism tags its ids with its own owner, so only the numbers can be compared).
  const auto& a = *first.mechanism;
  const auto& b = *second.mechanism;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    if (a.points[i].id.value != b.points[i].id.value ||
        a.points[i].body.value != b.points[i].body.value)
      fail("round trip changed point ids", std::to_string(i), text);
  std::string again = linkage::serializeMechanism(b);
  if (again != text) fail("saving is not stable", again, text);
  return 0;
}
