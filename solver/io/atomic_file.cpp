#include "linkage/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

namespace linkage {

namespace {

WriteResult failure(const std::string& path, const std::string& what, int err) {
  return {false, path + ": " + what + ": " + std::strerror(err)};
}

std::string directoryOf(const std::string& path) {
  size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// umask() can only be read by setting it, which races with other threads creating files;
// Linux reports it in /proc/self/status instead.
mode_t currentUmask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0)
      return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
  }
  return 022;
}

bool writeAll(int fd, std::string_view data) {
  while (!data.empty()) {
    ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

// Saving through a link must keep the link, so the file it points to is the one replaced.
std::string resolveSymlink(const std::string& path) {
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) return path;  // dangling link: replacing the link itself is the best we can do
  std::string resolved(real);
  std::free(real);
  return resolved;
}

}  // namespace

WriteResult writeFileAtomically(const std::string& path, std::string_view contents) {
  if (path.empty()) return {false, "cannot save: no file name given"};
  const std::string target = resolveSymlink(path);
  const std::string dir = directoryOf(target);
  const size_t slash = target.rfind('/');
  const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);

  struct stat existing;
  bool exists = ::stat(target.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) return failure(path, "cannot save", EISDIR);

  // Same directory, so the rename is atomic (no cross-filesystem copy); hidden, so a file browser
  // that catches it mid-write does not offer it.
  std::string tmpl = dir + "/." + base + ".tmp-XXXXXX";
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) return failure(path, "cannot create a temporary file in " + dir, errno);
  const std::string tmp(name.data());

  auto abandon = [&](const std::string& what, int err) {
    ::close(fd);
    ::unlink(tmp.c_str());
    return failure(path, what, err);
  };

  mode_t mode = exists ? (existing.st_mode & 07777) : (0666 & ~currentUmask());
  if (::fchmod(fd, mode) != 0) return abandon("cannot set permissions", errno);
  if (!writeAll(fd, contents)) return abandon("cannot write", errno);
  if (::fsync(fd) != 0) return abandon("cannot flush to disk", errno);
  if (::close(fd) != 0) {
    int err = errno;
    ::unlink(tmp.c_str());
    return failure(path, "cannot write", err);
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    int err = errno;
    ::unlink(tmp.c_str());
    return failure(path, "cannot replace", err);
  }

  // Makes the rename itself durable. The new file is already in place, so a failure here (some
  // filesystems refuse fsync on directories) is not reported as a failed save.
  int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return {true, {}};
}

}  // namespace linkage
