// Finding a mechanism by path or by example name ("wanzer-inversion-2"), for every front end.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace linkage {

// The running program's path (/proc/self/exe), else argv0: a program started through PATH has
// no directory in its argv[0].
std::string runningExecutable(const std::string& argv0);

// Directories searched for examples, in order: $LINKAGE_EXAMPLES_DIR, ../share/linkage/examples
// next to the executable (an installed program: <prefix>/bin and <prefix>/share/linkage/examples),
// and the source tree's resources/examples (compiled in, for programs run from the build tree).
std::vector<std::string> exampleDirectories(const std::string& executablePath = "");

// An existing file as given, else <dir>/<name>.linkage.json (or <dir>/<name>) in the example
// directories. nullopt when nothing matches.
std::optional<std::string> resolveModel(const std::string& nameOrPath,
                                        const std::string& executablePath = "");

// Example names (file names without .linkage.json), sorted, from the first directory that has any.
std::vector<std::string> listExamples(const std::string& executablePath = "");

}  // namespace linkage
