// linkage-cli plot: runs `linkage-plot plot`, found next to linkage-cli, with the same arguments.
// The figure needs Qt and QCustomPlot; loading them into linkage-cli would add about 20 ms to the
// start of every command (docs/benchmarks.md, Plots), so only this command pays for them.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli_common.h"
#include "cli_parser.h"

namespace linkage::cli {

namespace {

// linkage-plot's own command `plot` reads the arguments (cli_parser.h, as here) and prints the
// help; nothing is read twice.
int plot(const std::vector<std::string>& arguments) {
  // executablePath is /proc/self/exe (main), so this is the directory linkage-cli runs from.
  const std::filesystem::path helper =
      std::filesystem::path(executablePath).parent_path() / "linkage-plot";
  if (::access(helper.c_str(), X_OK) != 0) {
    error("plot: " + helper.string() +
          " is not there; it draws the figures (built with the editor's libraries, "
          "LINKAGE_BUILD_UI=ON)");
    return kFailure;
  }
  std::vector<std::string> words = {helper.string(), "plot"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> args;
  for (std::string& w : words) args.push_back(w.data());
  args.push_back(nullptr);
  std::cout.flush();
  ::execv(args[0], args.data());
  error("plot: cannot run " + words[0] + ": " + std::strerror(errno));
  return kFailure;
}

}  // namespace

Command plotCommand(Parser& parser) {
  // Every argument after `plot`, --help too, goes to linkage-plot as it is.
  return parser.passThrough("plot", plot);
}

}  // namespace linkage::cli
