#include "linkage/io/model_lookup.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace linkage {

namespace fs = std::filesystem;

namespace {
constexpr const char* kSuffix = ".linkage.json";

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}
}  // namespace

std::vector<std::string> exampleDirectories(const std::string& executablePath) {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("LINKAGE_EXAMPLES_DIR"); env && *env) dirs.push_back(env);
#ifdef LINKAGE_EXAMPLES_DIR
  dirs.push_back(LINKAGE_EXAMPLES_DIR);
#endif
  if (!executablePath.empty())
    dirs.push_back(
        (fs::path(executablePath).parent_path() / ".." / "share" / "linkage" / "examples")
            .string());
  return dirs;
}

std::optional<std::string> resolveModel(const std::string& nameOrPath,
                                        const std::string& executablePath) {
  if (nameOrPath.empty()) return std::nullopt;
  if (isFile(nameOrPath)) return nameOrPath;
  // A name, not a path: never let "../x" escape the example directories.
  if (nameOrPath.find('/') != std::string::npos) return std::nullopt;
  for (const std::string& dir : exampleDirectories(executablePath)) {
    for (const std::string& candidate : {nameOrPath + kSuffix, nameOrPath}) {
      const fs::path p = fs::path(dir) / candidate;
      if (isFile(p)) return p.string();
    }
  }
  return std::nullopt;
}

std::vector<std::string> listExamples(const std::string& executablePath) {
  for (const std::string& dir : exampleDirectories(executablePath)) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      const std::string f = e.path().filename().string();
      if (f.size() > std::string(kSuffix).size() && f.ends_with(kSuffix))
        names.push_back(f.substr(0, f.size() - std::string(kSuffix).size()));
    }
    if (!names.empty()) {
      std::sort(names.begin(), names.end());
      return names;
    }
  }
  return {};
}

}  // namespace linkage
