// linkage-plot cycle-diagram, run by `linkage-cli timing --out`: the cycle (timing) diagram as
// a figure (ui/cycle/cycle_figure.h, as the editor's Cycle dock draws it, with the file's
// clearances when it keeps them). linkage-cli has already checked the arguments and written
// the CSV; this draws what the same arguments give.
#include <QApplication>
#include <iostream>

#include "cli_common.h"
#include "cli_cycle_setup.h"
#include "cli_parser.h"
#include "cycle/clearance_text.h"
#include "cycle/cycle_figure.h"
#include "figures/qcp.h"
#include "figures/units.h"
#include "window/qt_notes.h"

namespace linkage::cli {

namespace {

// The arguments of `linkage-cli timing`, as it passes them (checked there already).
struct Options {
  std::string model, out;
  std::vector<std::string> windows, conflicts;
  int steps = 360;
};

// The file's clearances, drawn under the rows when the windows are the file's too.
std::vector<ui::CycleClearanceRow> clearanceRows(const Kinematics& k, int steps) {
  const Mechanism& m = k.mechanism();
  std::vector<ui::CycleClearanceRow> out;
  ClearanceOptions opt;
  opt.steps = steps;
  for (const ClearanceWatch& w : m.timing.clearances) {
    Clearance c = findClearance(k, ClearancePart::of(w.point), w.other, opt);
    if (!c.status.ok()) continue;  // linkage-cli timing does not judge clearances
    out.push_back({ui::clearanceLabel(m, w), std::move(c), w.minMm, w});
  }
  return out;
}

int cycleFigure(const Options& o) {
  std::optional<Mechanism> m = openDrivenModel(o.model);
  if (!m) return kBadInput;
  const std::optional<CycleSetup> s = cycleSetup(*m, o.windows, o.conflicts);
  if (!s) return kBadInput;
  Kinematics k;
  if (int e = prepare(k, *m); e != kOk) return e;
  CycleOptions opt;
  opt.steps = o.steps;
  const CycleDiagram d = cycleDiagram(k, s->outputs, s->windows, s->conflicts, opt);
  if (!d.status.ok()) {
    error(d.status.message);
    return exitFor(d.status);
  }
  ui::prepareOffscreen();
  static int qtArgc = 1;
  static char qtName[] = "linkage-plot";
  static char* qtArgv[] = {qtName, nullptr};
  QApplication app(qtArgc, qtArgv);
  QCustomPlot p;
  ui::CycleFigure figure(&p);
  const std::vector<ui::CycleClearanceRow> clearances =
      o.windows.empty() ? clearanceRows(k, o.steps) : std::vector<ui::CycleClearanceRow>{};
  figure.build(d, s->windows, clearances,
               QString::fromStdString(m->name) + QStringLiteral(": cycle diagram"),
               ui::crankAxisLabel(*m));
  const int rows = static_cast<int>(d.rows.size() + clearances.size());
  const QSize size(900, ui::CycleFigure::heightFor(rows) + 40);
  p.resize(size);
  QString err;
  if (!figure.exportFigure(QString::fromStdString(o.out), size, &err)) {
    error(err.toStdString());
    return kFailure;
  }
  return kOk;
}

}  // namespace

Command cycleDiagramCommand(Parser& parser) {
  auto o = std::make_shared<Options>();
  CLI::App& c =
      parser.command("cycle-diagram",
                     "usage: linkage-plot cycle-diagram --model MODEL --out FIG "
                     "[--window NAME=EXPR ...] [--conflict N1,N2 ...] [--steps N]\n\n"
                     "Run by 'linkage-cli timing --out': see linkage-cli timing --help.\n");
  required(addText(c, "--model", o->model));
  required(addFigureFile(c, "--out", o->out));
  addTexts(c, "--window", o->windows);
  addTexts(c, "--conflict", o->conflicts);
  addWhole(c, "--steps", o->steps, 4, 1'000'000);
  return {&c, [o] { return cycleFigure(*o); }};
}

}  // namespace linkage::cli
