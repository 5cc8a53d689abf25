// linkage-cli: the command-line front end to the kinematic core.
#include <iostream>
#include <string>

#include "cli_common.h"
#include "cli_parser.h"
#include "linkage/io/model_lookup.h"

namespace linkage::cli {
// Each command's options and run (app/cli_<command>.cpp).
Command analyzeCommand(Parser& parser);
Command infoCommand(Parser& parser);
Command icsCommand(Parser& parser);
Command plotCommand(Parser& parser);
Command limitsCommand(Parser& parser);
Command transmissionCommand(Parser& parser);
Command studyCommand(Parser& parser);
Command dynamicsCommand(Parser& parser);
Command balanceCommand(Parser& parser);
Command slotsCommand(Parser& parser);
Command clearanceCommand(Parser& parser);
Command timingCommand(Parser& parser);
Command camCommand(Parser& parser);
Command sensitivityCommand(Parser& parser);
Command toleranceCommand(Parser& parser);
Command optimizeCommand(Parser& parser);
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
  cam MODEL ...       a cam's checks (pressure angle, curvature, undercut) and its profile
  sensitivity MODEL --point body.point
                      how far a point moves per mm of each dimension, exactly, over a turn
  tolerance MODEL --point body.point --tol DIM=T ...
                      a point's band and stroke spread under tolerances: first order, Monte Carlo
  optimize MODEL --vary DIM=LO:HI --target ...
                      dimensions found for targets (stroke, position, path, transmission), NLopt
  examples            list the example mechanisms that MODEL can name

MODEL is a .linkage.json file or the name of an example (e.g. wanzer-inversion-2).
Run 'linkage-cli COMMAND --help' for a command's options, 'linkage-cli --version' for the
version. Numbers are written with '.' as the decimal point whatever the locale.
)";

const char* kExamplesHelp =
    "usage: linkage-cli examples\n\nLists the example mechanisms by name.\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace linkage::cli;
  executablePath = linkage::runningExecutable(argc > 0 ? argv[0] : "");
  Parser parser("linkage-cli", kHelp);
  parser.version("linkage-cli " LINKAGE_VERSION);
  std::vector<Command> commands;
  for (auto* add :
       {analyzeCommand, infoCommand, icsCommand, plotCommand, limitsCommand, transmissionCommand,
        studyCommand, dynamicsCommand, balanceCommand, slotsCommand, clearanceCommand,
        timingCommand, camCommand, sensitivityCommand, toleranceCommand, optimizeCommand})
    commands.push_back(add(parser));
  commands.push_back({&parser.command("examples", kExamplesHelp), [] {
                        for (const std::string& n : linkage::listExamples(executablePath))
                          std::cout << n << "\n";
                        return int(kOk);
                      }});
  return parser.run(commands, argc, argv);
}
