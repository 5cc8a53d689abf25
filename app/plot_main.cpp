// linkage-plot, run by `linkage-cli plot`: the motion curves of one or more mechanisms as a
// figure file, without a window (a QApplication on the offscreen platform unless
// QT_QPA_PLATFORM says otherwise). A program of its own so that linkage-cli does not load Qt:
// that would add 20 ms to the start of every other command (docs/benchmarks.md, Plots).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "cli_parser.h"

#include <QApplication>

#include "figures/qcp.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"
#include "plots/curve_set.h"
#include "plots/motion_figure.h"
#include "window/qt_notes.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli plot MODEL [MODEL2 ...] [--point body.point] --out FIG.png|pdf|svg
                        [--revs R] [--steps N] [--units mm|m|g] [--size WxH]
                        [--component x|y|z|magnitude|distance] [--to body.point]
                        [--along DEG [--elevation DEG]] [--jerk] [--overlay]

Draws position, velocity and acceleration of a point against the crank angle, stacked on a
shared axis: one model gives one column, two or more models one column each side by side (the
Wanzer homework's 3 x 2 figure: linkage-cli plot wanzer-inversion-1 wanzer-inversion-2
--point needlebar.G --revs 4 --units g --out wanzer.png), each titled by the model's name.
Velocities and accelerations are the solver's exact values at every step; extremes are marked.

  --point B.P        the point (default: the first model's first output); every model must
                     have a point of that name
  --out FILE         .png (raster), .pdf or .svg (vector); written atomically
  --revs R           whole revolutions of the crank on the axis (default 1)
  --steps N          samples per revolution (default 360)
  --units U          mm: mm/s and mm/s^2 (default); m: m/s and m/s^2; g: mm/s and g
                     (standard gravity, 9806.65 mm/s^2), as the homework plots them
  --size WxH         pixels (default 900x900 for one model, 700 per model x 900)
  --component C      x, y (default), z, magnitude (|r|, speed |v|, |a|) or distance (to the
                     point --to names, and its rates: exact)
  --to B.P           the second point of a distance
  --along DEG        the component along a direction, degrees counter-clockwise from +x
  --elevation DEG    with --along: the direction's angle above the x-y plane
On a machine in space (a model with planes) x, y, z, directions and distances are the world's.
  --jerk             a fourth row: the jerk (spectral derivative of the exact accelerations)
  --overlay          models overlaid in one column instead of side by side

Exit status: 0 success, 2 bad input (options, files, a point a model does not have), 3 a
crank that cannot turn the whole way (the figure shows the part that exists, with the reason),
1 the file could not be written.
)";

const char* kProgramHelp =
    R"(usage: linkage-plot plot ...            (linkage-cli plot runs it: linkage-cli plot --help)
       linkage-plot cycle-diagram ...   (linkage-cli timing --out runs it)

Draws the figures of linkage-cli, which itself does not load Qt.
)";

struct PlotOptions {
  std::vector<std::string> models;
  std::string point, out, component = "y";
  std::optional<double> along, elevation;
  std::string to;
  long long revs = 1, steps = 360;
  std::string units = "mm";
  std::optional<std::pair<int, int>> size;  // else one that fits the columns
  bool jerk = false, overlay = false;
};

// The options, read into `o`.
CLI::App* addOptions(Parser& parser, PlotOptions& o) {
  CLI::App& c = parser.command("plot", kHelp);
  addModels(c, o.models);
  addText(c, "--point", o.point);
  addFigureFile(c, "--out", o.out);
  addWhole(c, "--revs", o.revs, 1, 100);
  addWhole(c, "--steps", o.steps, 12, 36000);
  addWord(c, "--units", o.units, {"mm", "m", "g"});
  addPixelSize(c, "--size", o.size);
  addWord(c, "--component", o.component, {"x", "y", "z", "magnitude", "distance"});
  addText(c, "--to", o.to);
  addNumber(c, "--along", o.along);
  addNumber(c, "--elevation", o.elevation);
  addFlag(c, "--jerk", o.jerk);
  addFlag(c, "--overlay", o.overlay);
  return &c;
}

// Loads and solves every model, each with the point plotted (by default the first model's first
// output), checked to be one the driver moves; their names for the titles.
int loadModels(PlotOptions& o, std::vector<Kinematics>& solved, std::vector<std::string>& names) {
  for (const std::string& model : o.models) {
    std::optional<Mechanism> m = openModel(model);
    if (!m) return kBadInput;
    if (!m->driver) {
      error(model + ": the mechanism has no driver");
      return kBadInput;
    }
    if (o.point.empty()) {
      if (m->outputs.empty()) {
        error(model + ": the model names no output points: give --point body.point");
        return kBadInput;
      }
      o.point = m->pointLabel(m->outputs[0]);
    }
    if (!m->findPoint(o.point)) {
      error(model + ": no point \"" + o.point + "\" (--point body.point)");
      return kBadInput;
    }
    if (!o.to.empty() && !m->findPoint(o.to)) {
      error(model + ": no point \"" + o.to + "\" (--to body.point)");
      return kBadInput;
    }
    Kinematics k;
    if (int e = prepare(k, *m); e != kOk) return e;
    if (Status s = k.checkDetermined({*m->findPoint(o.point)}); !s.ok()) {
      error(model + ": " + s.message);
      return exitFor(s);
    }
    names.push_back(m->name.empty() ? model : m->name);
    solved.push_back(std::move(k));
  }
  return kOk;
}

ui::CurveRequest curveRequest(const PlotOptions& o) {
  ui::CurveRequest req;
  req.target = QString::fromStdString(o.point);
  req.component = o.along                      ? Quantity::Component::Along
                  : o.component == "x"         ? Quantity::Component::X
                  : o.component == "z"         ? Quantity::Component::Z
                  : o.component == "magnitude" ? Quantity::Component::Magnitude
                  : o.component == "distance"  ? Quantity::Component::Distance
                                               : Quantity::Component::Y;
  req.directionDeg = o.along.value_or(0);
  req.elevationDeg = o.elevation.value_or(0);
  req.other = QString::fromStdString(o.to);
  req.orders = {true, true, true, o.jerk};
  req.revs = static_cast<int>(o.revs);
  req.steps = static_cast<int>(o.steps);
  return req;
}

// Every model's curves; a crank that cannot turn the whole way is reported and its exit status
// returned (the figure still shows the curves up to there).
int sampleCurves(const PlotOptions& o, const std::vector<Kinematics>& solved,
                 const std::vector<std::string>& names,
                 std::vector<std::unique_ptr<ui::CurveSet>>& sets) {
  const ui::CurveRequest req = curveRequest(o);
  int status = kOk;
  for (size_t i = 0; i < solved.size(); ++i) {
    sets.push_back(
        std::make_unique<ui::CurveSet>(solved[i], req, QString::fromStdString(names[i])));
    if (!sets.back()->status().ok()) {
      error(o.models[i] + ": " + sets.back()->status().message +
            " (the figure shows the curves up to there)");
      status = exitFor(sets.back()->status());
    }
  }
  return status;
}

ui::MotionFigure::Options figureOptions(const PlotOptions& o, size_t models) {
  ui::MotionFigure::Options fo;
  fo.layout = o.overlay || models == 1 ? ui::MotionFigure::Layout::Overlay
                                       : ui::MotionFigure::Layout::SideBySide;
  fo.cursor = false;
  if (o.units == "m") {
    fo.units.velocity = ui::VelocityUnit::MetrePerSecond;
    fo.units.acceleration = ui::AccelerationUnit::MetrePerSecond2;
  } else if (o.units == "g") {
    fo.units.acceleration = ui::AccelerationUnit::G;
  }
  return fo;
}

// The figure of the curves written to --out, at --size or a size for the columns and rows.
int writeFigure(const PlotOptions& o, const std::vector<const ui::CurveSet*>& shown) {
  QCustomPlot plot;
  ui::MotionFigure figure(&plot);
  const ui::MotionFigure::Options fo = figureOptions(o, shown.size());
  const int columns =
      fo.layout == ui::MotionFigure::Layout::SideBySide ? static_cast<int>(shown.size()) : 1;
  const int w = o.size ? o.size->first : (columns == 1 ? 900 : 700 * columns);
  const int h = o.size ? o.size->second : (o.jerk ? 1100 : 900);
  plot.resize(w, h);
  figure.build(shown, fo);
  QString err;
  if (!figure.exportFigure(QString::fromStdString(o.out), QSize(w, h), &err)) {
    error(err.toStdString());
    return kFailure;
  }
  return kOk;
}

int plot(PlotOptions& o) {
  if (o.out.empty()) {  // (required, in words that say what it takes)
    error("plot: no --out FILE given (.png, .pdf or .svg)");
    return kBadInput;
  }
  if ((o.component == "distance") != !o.to.empty()) {
    error(o.to.empty() ? "plot: --component distance needs --to body.point"
                       : "plot: --to is the second point of --component distance");
    return kBadInput;
  }
  if (o.elevation && (!o.along || !(std::abs(*o.elevation) <= 90))) {
    error(o.along ? "plot: --elevation must lie in [-90, 90] degrees"
                  : "plot: --elevation tilts the direction of --along: give --along DEG");
    return kBadInput;
  }
  // Every model loaded and solved before any window system is touched.
  std::vector<Kinematics> solved;
  std::vector<std::string> names;
  if (int e = loadModels(o, solved, names); e != kOk) return e;

  ui::prepareOffscreen();
  static int qtArgc = 1;
  static char qtName[] = "linkage-cli";
  static char* qtArgv[] = {qtName, nullptr};
  QApplication app(qtArgc, qtArgv);

  std::vector<std::unique_ptr<ui::CurveSet>> sets;
  const int status = sampleCurves(o, solved, names, sets);
  std::vector<const ui::CurveSet*> shown;
  for (const auto& s : sets) shown.push_back(s.get());
  if (int e = writeFigure(o, shown); e != kOk) return e;
  return status;
}

}  // namespace

Command plotCommand(Parser& parser) {
  auto o = std::make_shared<PlotOptions>();
  return {addOptions(parser, *o), [o] { return plot(*o); }};
}

}  // namespace linkage::cli

namespace linkage::cli {
Command cycleDiagramCommand(Parser& parser);  // cycle_figure.cpp: `linkage-cli timing --out`
}

int main(int argc, char** argv) {
  using namespace linkage::cli;
  executablePath = linkage::runningExecutable(argc > 0 ? argv[0] : "");
  Parser parser("linkage-plot", kProgramHelp);
  const std::vector<Command> commands = {plotCommand(parser), cycleDiagramCommand(parser)};
  return parser.run(commands, argc, argv);
}
