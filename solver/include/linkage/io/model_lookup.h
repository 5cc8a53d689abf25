// Finding a mechanism by path or by example name ("wanzer-inversion-2"), for every front end.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace linkage {

// Directories searched for examples, in order: $LINKAGE_EXAMPLES_DIR, the source tree's
// resources/examples (compiled in), and ../share/linkage/examples next to the executable.
std::vector<std::string> exampleDirectories(const std::string& executablePath = "");

// An existing file as given, else <dir>/<name>.linkage.json (or <dir>/<name>) in the example
// directories. nullopt when nothing matches.
std::optional<std::string> resolveModel(const std::string& nameOrPath,
                                        const std::string& executablePath = "");

// Example names (file names without .linkage.json), sorted, from the first directory that has any.
std::vector<std::string> listExamples(const std::string& executablePath = "");

}  // namespace linkage
