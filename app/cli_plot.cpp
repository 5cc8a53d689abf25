// linkage-cli plot: runs linkage-plot, found next to linkage-cli, with the same arguments. The
// figure needs Qt and QCustomPlot; loading them into linkage-cli would add about 20 ms to the
// start of every command (docs/benchmarks.md, Plots), so only this command pays for them.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"

namespace linkage::cli {

int plot(int argc, char** argv) {
  // executablePath is /proc/self/exe (main), so this is the directory linkage-cli runs from.
  const std::filesystem::path helper =
      std::filesystem::path(executablePath).parent_path() / "linkage-plot";
  if (::access(helper.c_str(), X_OK) != 0) {
    error("plot: " + helper.string() +
          " is not there; it draws the figures (built with the editor's libraries, "
          "LINKAGE_BUILD_UI=ON)");
    return kFailure;
  }
  std::vector<char*> args;
  std::string name = helper.string();
  args.push_back(name.data());
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  std::cout.flush();
  ::execv(name.c_str(), args.data());
  error("plot: cannot run " + name + ": " + std::strerror(errno));
  return kFailure;
}

}  // namespace linkage::cli
