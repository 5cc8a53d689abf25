// linkage-cli timing: the windows of a machine's cycle (timing) diagram and the conflicts
// between them, every crossing found by root finding on the exact motion (linkage/timing.h).
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "cli_common.h"
#include "cli_cycle_setup.h"
#include "cli_parser.h"
#include "linkage/io/numbers.h"
#include "linkage/tables/timing_table.h"
#include "linkage/timing.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli timing MODEL [--window NAME=EXPR ...] [--conflict N1,N2 ...]
                          [--steps N] [--out FIG.png|pdf|svg]

The windows of MODEL's machine cycle (crank angle 0 to 360 of the driver, the main shaft):
the crank angles where each condition holds, its ends found to 1e-9 degree of crank by root
finding on the exact motion; then the overlaps of windows that must not overlap. Without
--window, the windows, conflicts and rows kept in MODEL's "timing" (what the editor's Cycle
dock keeps), with any --conflict added.

  --window NAME=EXPR  EXPR is OUTPUT<VALUE or OUTPUT>VALUE, OUTPUT one of
                        body.point:y    the point's y (mm)
                        body.point:x    its x (mm)
                        body.point:DX,DY   its position along the direction DX,DY (mm)
                        body:angle      the body's angle from the drawing (degrees, ccw,
                                        whole turns counted)
                      e.g. --window 'needle=needlebar.N:y<-150'
  --conflict N1,N2    windows N1 and N2 must not overlap
  --steps N           sampling intervals that bracket the crossings (default 360)
  --out FIG           the cycle diagram as a figure (.png, .pdf or .svg): a row per output
                      normalised to its stroke with its dead centres, the windows shaded in
                      their rows, the conflicts' overlaps in red (drawn by linkage-plot)

Output, CSV: window,from_deg,to_deg; a row "NAME,FROM,TO" per interval of each window (in the
order given, intervals in order of their start; FROM in [0, 360), TO > FROM, past 360 when the
interval wraps through 0); then "conflict:N1+N2,FROM,TO" per overlap. 17 significant digits.

Exit status: 0 success, 4 a conflict (the rows are still written), 2 bad input (the message
names the argument and the part of it that is wrong), 3 the crank cannot turn fully, 1 the
figure could not be written.
)";

constexpr int kConflict = 4;

struct Options {
  std::string model;
  std::vector<std::string> windows, conflicts;
  int steps = 360;
  std::string out;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, Options& o) {
  CLI::App& c = parser.command("timing", kHelp);
  addModel(c, o.model);
  addTexts(c, "--window", o.windows);
  addTexts(c, "--conflict", o.conflicts);
  addWhole(c, "--steps", o.steps, 4, 1'000'000);
  addFigureFile(c, "--out", o.out);
  return &c;
}

// linkage-plot, next to linkage-cli, draws the figure from the same arguments (linkage-cli
// itself does not load Qt); kOk, or kFailure with the reason printed.
int drawFigure(const Options& o) {
  const std::filesystem::path helper =
      std::filesystem::path(executablePath).parent_path() / "linkage-plot";
  if (::access(helper.c_str(), X_OK) != 0) {
    error("--out: " + helper.string() + " is not there; it draws the figures");
    return kFailure;
  }
  std::vector<std::string> args = {helper.string(), "cycle-diagram",         "--model", o.model,
                                   "--steps",       std::to_string(o.steps), "--out",   o.out};
  for (const std::string& w : o.windows) args.insert(args.end(), {"--window", w});
  for (const std::string& c : o.conflicts) args.insert(args.end(), {"--conflict", c});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::cout.flush();
  const pid_t child = ::fork();
  if (child == 0) {
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    error("--out " + o.out + ": the figure could not be drawn");
    return kFailure;
  }
  return kOk;
}

int timing(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<CycleSetup> setup = cycleSetup(*m, o.windows, o.conflicts);
  if (!setup) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  CycleOptions opt;
  opt.steps = o.steps;
  const CycleDiagram d = cycleDiagram(k, setup->outputs, setup->windows, setup->conflicts, opt);
  if (!d.status.ok()) {
    error(d.status.message);
    return exitFor(d.status);
  }
  std::cout << timingTable(d) << std::flush;
  for (const CycleRow& r : d.rows)
    if (!r.periodic)
      note(r.output.name + " does not repeat after one turn: its windows end at 0 and 360");
  if (!o.out.empty())
    if (int e = drawFigure(o); e != kOk) return e;
  return d.anyConflict() ? kConflict : kOk;
}

}  // namespace

Command timingCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  return {addOptions(parser, *o), [o] { return timing(*o); }};
}

}  // namespace linkage::cli
