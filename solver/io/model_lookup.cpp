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

std::string runningExecutable(const std::string& argv0) {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? argv0 : self.string();
}

std::vector<std::string> exampleDirectories(const std::string& executablePath) {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("LINKAGE_EXAMPLES_DIR"); env && *env) dirs.push_back(env);
  // Installed (<prefix>/bin/linkage-cli): the examples installed with it, before the source tree
  // it was built from, which may have moved on or be gone. A bare name (no directory) says
  // nothing of where the program is: never search the working directory's ../share for it.
  if (const fs::path bin = fs::path(executablePath).parent_path(); !bin.empty())
    dirs.push_back((bin / ".." / "share" / "linkage" / "examples").lexically_normal().string());
#ifdef LINKAGE_EXAMPLES_DIR
  dirs.push_back(LINKAGE_EXAMPLES_DIR);
#endif
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
