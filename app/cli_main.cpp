// linkage-cli: the command-line front end to the kinematic core.
#include <cstring>
#include <iostream>
#include <string>

#include "cli_common.h"
#include "linkage/io/model_lookup.h"

namespace linkage::cli {
int analyze(int argc, char** argv);
int ics(int argc, char** argv);
int info(int argc, char** argv);
int plot(int argc, char** argv);
int limits(int argc, char** argv);
int transmission(int argc, char** argv);
int study(int argc, char** argv);
int dynamics(int argc, char** argv);
int balance(int argc, char** argv);
int slots(int argc, char** argv);
int clearance(int argc, char** argv);
int timing(int argc, char** argv);
}  // namespace linkage::cli

namespace {

const char* kHelp = R"(usage: linkage-cli COMMAND [ARGS]

Commands:
  analyze MODEL ...   motion table (position, velocity, acceleration of points) over crank angles
  info MODEL          structure of a mechanism: degrees of freedom, redundant joints, assembly
  ics MODEL --angle D instant centres (Kennedy-Aronhold) at a crank angle; velocity chains
  plot MODEL...       figure of position, velocity, acceleration of a point (PNG, PDF, SVG)
  limits MODEL ...    limit positions and stroke of a point along a direction or of a body
  transmission MODEL  transmission angles over a turn, checked against a band (30 to 150)
  study MODEL ...     one point moved over a range: stroke, swings, transmission, peaks
  dynamics MODEL ...  forces at the driver's speed: its torque, the joints' reactions, shaking
  balance MODEL ...   counterweights that minimise the peak shaking force, exactly
  slots MODEL         travel of every block and pin along its slot against the slot's ends
  clearance MODEL ... distance between two moving points (or a point and a slot): minima
  timing MODEL ...    windows of the machine cycle (timing diagram) and their conflicts
  examples            list the example mechanisms that MODEL can name

MODEL is a .linkage.json file or the name of an example (e.g. wanzer-inversion-2).
Run 'linkage-cli COMMAND --help' for a command's options, 'linkage-cli --version' for the
version. Numbers are written with '.' as the decimal point whatever the locale.
)";

}  // namespace

int main(int argc, char** argv) {
  using namespace linkage::cli;
  executablePath = linkage::runningExecutable(argc > 0 ? argv[0] : "");
  if (argc < 2 || isHelp(argv[1])) {
    std::cout << kHelp;
    return argc < 2 ? kBadInput : kOk;
  }
  const std::string cmd = argv[1];
  if (cmd == "--version") {
    std::cout << "linkage-cli " LINKAGE_VERSION "\n";
    return kOk;
  }
  if (cmd == "analyze") return analyze(argc - 2, argv + 2);
  if (cmd == "info") return info(argc - 2, argv + 2);
  if (cmd == "ics") return ics(argc - 2, argv + 2);
  if (cmd == "plot") return plot(argc - 2, argv + 2);
  if (cmd == "limits") return limits(argc - 2, argv + 2);
  if (cmd == "transmission") return transmission(argc - 2, argv + 2);
  if (cmd == "study") return study(argc - 2, argv + 2);
  if (cmd == "dynamics") return dynamics(argc - 2, argv + 2);
  if (cmd == "balance") return balance(argc - 2, argv + 2);
  if (cmd == "slots") return slots(argc - 2, argv + 2);
  if (cmd == "clearance") return clearance(argc - 2, argv + 2);
  if (cmd == "timing") return timing(argc - 2, argv + 2);
  if (cmd == "examples") {
    if (argc > 2 && isHelp(argv[2])) {
      std::cout << "usage: linkage-cli examples\n\nLists the example mechanisms by name.\n";
      return kOk;
    }
    for (const std::string& n : linkage::listExamples(executablePath)) std::cout << n << "\n";
    return kOk;
  }
  error("unknown command \"" + cmd + "\" (see linkage-cli --help)");
  return kBadInput;
}
