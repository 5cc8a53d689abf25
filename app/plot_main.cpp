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

#include <QApplication>

#include "export/figure_export.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"
#include "plots/curve_set.h"
#include "plots/motion_figure.h"
#include "plots/qcp.h"

namespace linkage::cli {

namespace {

const char* kHelp =
    R"(usage: linkage-cli plot MODEL [MODEL2 ...] [--point body.point] --out FIG.png|pdf|svg
                        [--revs R] [--steps N] [--units mm|m|g] [--size WxH]
                        [--component x|y|magnitude] [--along DEG] [--jerk] [--overlay]

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
  --component C      x, y (default) or magnitude (|r|, speed |v|, |a|)
  --along DEG        the component along a direction, degrees counter-clockwise from +x
  --jerk             a fourth row: the jerk (spectral derivative of the exact accelerations)
  --overlay          models overlaid in one column instead of side by side

Exit status: 0 success, 2 bad input (options, files, a point a model does not have), 3 a
crank that cannot turn the whole way (the figure shows the part that exists, with the reason),
1 the file could not be written.
)";

struct PlotOptions {
  std::vector<std::string> models;
  std::string point, out, component = "y";
  std::optional<double> along;
  long long revs = 1, steps = 360;
  std::string units = "mm";
  int width = 0, height = 0;
  bool jerk = false, overlay = false;
};

bool parseSize(const std::string& text, int& w, int& h) {
  const size_t x = text.find('x');
  const std::optional<double> a =
      x == std::string::npos ? std::nullopt : parseNumber(text.substr(0, x));
  const std::optional<double> b =
      x == std::string::npos ? std::nullopt : parseNumber(text.substr(x + 1));
  const bool ok = a && b && *a == std::floor(*a) && *b == std::floor(*b) && *a >= 50 && *b >= 50 &&
                  *a <= 20000 && *b <= 20000;
  if (!ok) error("--size: \"" + text + "\" is not WxH with whole numbers from 50 to 20000");
  w = ok ? static_cast<int>(*a) : 0;
  h = ok ? static_cast<int>(*b) : 0;
  return ok;
}

// The value if it is one of `allowed`; prints the problem otherwise.
bool oneOf(const std::string& option, const std::string& v,
           const std::vector<std::string>& allowed) {
  for (const std::string& x : allowed)
    if (v == x) return true;
  std::string list;
  for (size_t i = 0; i < allowed.size(); ++i)
    list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
  error(option + ": \"" + v + "\" is not " + list);
  return false;
}

bool wholeIn(const std::string& option, const std::string& v, long long lo, long long hi,
             long long& out) {
  const std::optional<long long> n = wholeNumber(option, v);
  if (n && (*n < lo || *n > hi))
    error(option + ": must be from " + std::to_string(lo) + " to " + std::to_string(hi));
  if (!n || *n < lo || *n > hi) return false;
  out = *n;
  return true;
}

// One option and its value (empty for flags); false after printing the problem.
bool apply(const std::string& a, const std::string& v, PlotOptions& o) {
  if (a == "--revs") return wholeIn(a, v, 1, 100, o.revs);
  if (a == "--steps") return wholeIn(a, v, 12, 36000, o.steps);
  if (a == "--size") return parseSize(v, o.width, o.height);
  if ((a == "--units" && !oneOf(a, v, {"mm", "m", "g"})) ||
      (a == "--component" && !oneOf(a, v, {"x", "y", "magnitude"})))
    return false;
  if (a == "--along") {
    o.along = number(a, v);
    return o.along.has_value();
  }
  if (a == "--point") {
    o.point = v;
  } else if (a == "--out") {
    o.out = v;
  } else if (a == "--units") {
    o.units = v;
  } else if (a == "--component") {
    o.component = v;
  } else if (a == "--jerk") {
    o.jerk = true;
  } else if (a == "--overlay") {
    o.overlay = true;
  } else if (!a.empty() && a[0] == '-') {
    error("plot: unknown option " + a + " (see linkage-cli plot --help)");
    return false;
  } else {
    o.models.push_back(a);
  }
  return true;
}

// Returns kOk, or the exit status after printing the problem.
int parseOptions(int argc, char** argv, PlotOptions& o) {
  const std::vector<std::string> withValue = {"--point", "--out",  "--revs",      "--steps",
                                              "--units", "--size", "--component", "--along"};
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    std::string v;
    if (std::find(withValue.begin(), withValue.end(), a) != withValue.end()) {
      if (i + 1 == argc) {
        error(a + ": needs a value");
        return kBadInput;
      }
      v = argv[++i];
    }
    if (!apply(a, v, o)) return kBadInput;
  }
  if (o.models.empty()) {
    error("plot: no MODEL given (see linkage-cli plot --help)");
    return kBadInput;
  }
  if (o.out.empty()) {
    error("plot: no --out FILE given (.png, .pdf or .svg)");
    return kBadInput;
  }
  const std::string ext = o.out.substr(o.out.find_last_of('.') + 1);
  if (o.out.find('.') == std::string::npos || (ext != "png" && ext != "pdf" && ext != "svg")) {
    error("--out " + o.out + ": the name must end in .png, .pdf or .svg");
    return kBadInput;
  }
  return kOk;
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
                  : o.component == "magnitude" ? Quantity::Component::Magnitude
                                               : Quantity::Component::Y;
  req.directionDeg = o.along.value_or(0);
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
  const int w = o.width > 0 ? o.width : (columns == 1 ? 900 : 700 * columns);
  const int h = o.height > 0 ? o.height : (o.jerk ? 1100 : 900);
  plot.resize(w, h);
  figure.build(shown, fo);
  QString err;
  if (!ui::exportPlot(&plot, QString::fromStdString(o.out), QSize(w, h), &err)) {
    error(err.toStdString());
    return kFailure;
  }
  return kOk;
}

}  // namespace

int plot(int argc, char** argv) {
  for (int i = 0; i < argc; ++i)
    if (isHelp(argv[i])) {
      std::cout << kHelp;
      return kOk;
    }
  PlotOptions o;
  if (int e = parseOptions(argc, argv, o); e != kOk) return e;
  // Every model loaded and solved before any window system is touched.
  std::vector<Kinematics> solved;
  std::vector<std::string> names;
  if (int e = loadModels(o, solved, names); e != kOk) return e;

  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
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

}  // namespace linkage::cli

namespace linkage::cli {
int cycleFigure(int argc, char** argv);  // cycle_figure.cpp: `linkage-cli timing --out`
}

int main(int argc, char** argv) {
  linkage::cli::executablePath = linkage::runningExecutable(argc > 0 ? argv[0] : "");
  if (argc > 1 && std::string(argv[1]) == "--cycle-diagram")
    return linkage::cli::cycleFigure(argc - 2, argv + 2);
  return linkage::cli::plot(argc - 1, argv + 1);
}
