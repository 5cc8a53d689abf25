// Replacing a file so that a crash, a full disk or a failed write never leaves a truncated or
// half-written file behind: readers see either the old contents or the new, whole.
#pragma once

#include <string>
#include <string_view>

namespace linkage {

struct WriteResult {
  bool ok = false;
  std::string error;  // "" when ok; otherwise names the path and the system's reason
};

// Writes `contents` to a temporary file next to `path`, flushes it to disk, gives it the permission
// bits of the file it replaces (or the usual 0666 minus umask for a new file) and renames it over
// `path`. If `path` is a symbolic link, the file it points to is replaced and the link kept.
// On failure the temporary file is removed and `path` is untouched.
WriteResult writeFileAtomically(const std::string& path, std::string_view contents);

}  // namespace linkage
