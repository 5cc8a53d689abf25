// The editor's frames in its real main window, offscreen (QT_QPA_PLATFORM=offscreen, the raster
// engine, fresh settings), as the running editor makes them. Prints one line each; numbers for
// docs/benchmarks.md, "The editor". Not a test.
//
//   build/bench/linkage_frames_bench --frames N [FILE|EXAMPLE] [--ics] [--plots] ...
//   build/bench/linkage_frames_bench --drag N [FILE|EXAMPLE] [--ctrl] [--ics] [--plots] ...
//   build/bench/linkage_frames_bench --frames N --3d [FILE|EXAMPLE] [--size WxH] (the 3D view)
//   (both also [--size WxH] [--angle DEG] [--dark] [--extremes] [--transmission] [--checks]
//   [--forces], as `linkage --screenshot` takes them)
//
// Exit status: 0, or 2 with a message naming the cause (a bad option, a model that cannot be
// opened or is not solved, frames that were not painted).
#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "canvas/canvas_view.h"
#include "document/document.h"
#include "view3d/view3d_widget.h"
#include "window/features.h"
#include "window/offscreen_window.h"

namespace {

using namespace linkage;
using namespace linkage::ui;

struct PaintCounter : QObject {
  int paints = 0;
  bool eventFilter(QObject*, QEvent* e) override {
    if (e->type() == QEvent::Paint) ++paints;
    return false;
  }
};

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const size_t i = std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5));
  return v[i];
}

void printTimes(const char* what, const std::vector<double>& ms) {
  std::printf("%s median_ms %.3f p99_ms %.3f max_ms %.3f\n", what, percentile(ms, 0.5),
              percentile(ms, 0.99), *std::max_element(ms.begin(), ms.end()));
}

// Each frame as the running editor makes it: the solve to the next crank angle (2 degrees on,
// a frame of the Wanzer at x1/10 of 240 rpm and 60 frames a second), the scene and the docks
// updated, then the event loop paints every widget that changed and flushes the window. Paints
// of the canvas are counted, to prove each frame was drawn.
// With `view3d`, the 3D view alone (at the window's size) is what is painted and counted.
int benchmarkFrames(MainWindow& w, int frames, QWidget* view3d = nullptr) {
  Document* d = w.document();
  if (!d->solved()) {
    std::fprintf(stderr, "linkage_frames_bench: the mechanism is not solved: %s\n",
                 d->solveStatus().message.c_str());
    return 2;
  }
  PaintCounter canvasPaints;
  (view3d ? view3d : w.canvas()->viewport())->installEventFilter(&canvasPaints);
  std::vector<double> ms;
  ms.reserve(frames);
  QElapsedTimer t;
  double deg = d->crankDeg();
  for (int f = 0; f < frames; ++f) {
    t.start();
    deg += 2.0;
    if (!d->setCrankDeg(deg).ok()) deg = d->crankDeg();
    QCoreApplication::processEvents();
    ms.push_back(t.nsecsElapsed() * 1e-6);
  }
  if (canvasPaints.paints < frames) {
    std::fprintf(stderr, "linkage_frames_bench: only %d of %d frames were painted\n",
                 canvasPaints.paints, frames);
    return 2;
  }
  printTimes(qPrintable(QString::fromLatin1(view3d ? "3d frames %1" : "frames %1").arg(frames)),
             ms);
  return 0;
}

// Mouse moves of a drag of the first output point in the real window, each measured from the
// move event to the redrawn frame: the event handled, the mechanism solved (the crank turned,
// or with Ctrl the design changed and re-solved), the canvas, docks and plots brought up to
// date and painted by the event loop, until nothing is left to do.
int benchmarkDrag(MainWindow& w, int moves, bool reshape) {
  Document* d = w.document();
  if (!d->solved() || d->design().outputs.empty()) {
    std::fprintf(stderr,
                 "linkage_frames_bench: --drag needs a solved mechanism with an output point\n");
    return 2;
  }
  CanvasView* v = w.canvas();
  QWidget* port = v->viewport();
  const Qt::KeyboardModifiers mods = reshape ? Qt::ControlModifier : Qt::NoModifier;
  const Vec2 start = d->kinematics().position(d->design().outputs[0]);
  auto send = [&](QEvent::Type type, const Vec2& at, Qt::MouseButton b, Qt::MouseButtons bs) {
    const QPointF p = v->mapFromScene(QPointF(at.x(), at.y()));
    QMouseEvent e(type, p, port->mapToGlobal(p), b, bs, mods);
    QApplication::sendEvent(port, &e);
  };
  auto drain = [] {
    for (int i = 0; i < 4; ++i) QCoreApplication::processEvents();
  };
  send(QEvent::MouseMove, start, Qt::NoButton, Qt::NoButton);
  send(QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  drain();
  // A circle of a tenth of the mechanism's size about where the point was: the crank turns to
  // follow (or, with Ctrl, the point is moved in its link).
  const double r = 0.1 * d->kinematics().size();
  std::vector<double> ms;
  QElapsedTimer t;
  for (int i = 1; i <= moves; ++i) {
    const double a = 2 * M_PI * i / std::max(moves, 60);
    const Vec2 at = start + r * Vec2(std::sin(a), 1 - std::cos(a));
    t.start();
    send(QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
    drain();
    ms.push_back(t.nsecsElapsed() * 1e-6);
  }
  send(QEvent::MouseButtonRelease, start, Qt::LeftButton, Qt::NoButton);
  drain();
  printTimes(qPrintable(QStringLiteral("drag %1 moves %2")
                            .arg(reshape ? QStringLiteral("design") : QStringLiteral("motion"))
                            .arg(moves)),
             ms);
  return 0;
}

// A whole number of at least 1 from option `name`, or 0 when it is not set; -1 when bad.
int count(const QCommandLineParser& cli, const QString& name) {
  if (!cli.isSet(name)) return 0;
  bool ok = false;
  const int n = cli.value(name).toInt(&ok);
  if (ok && n >= 1) return n;
  std::fprintf(stderr, "linkage_frames_bench: --%s: \"%s\" is not a whole number of at least 1\n",
               qPrintable(name), qPrintable(cli.value(name)));
  return -1;
}

void addOptions(QCommandLineParser& cli) {
  const auto flag = [&](const char* name, const char* help) {
    cli.addOption({QString::fromLatin1(name), QString::fromLatin1(help)});
  };
  const auto value = [&](const char* name, const char* help, const char* arg) {
    cli.addOption({QString::fromLatin1(name), QString::fromLatin1(help), QString::fromLatin1(arg)});
  };
  value("frames", "Animate N frames as fast as possible and print frame times.", "N");
  value("drag",
        "Drag the first output point with N mouse moves; print the time from each move "
        "to the redrawn frame.",
        "N");
  flag("ctrl", "With --drag: hold Ctrl (the design changes while dragging).");
  value("angle", "Crank angle to start from (degrees).", "DEG");
  value("size", "Window size (default 1280x800).", "WxH");
  flag("ics", "Show the instant centres (overlay and panel).");
  flag("plots", "Show the plots dock.");
  flag("dark", "Use the dark palette.");
  flag("extremes", "Draw the extreme positions of the output.");
  flag("transmission", "Show the transmission angles.");
  flag("checks", "Show the design-checks dock.");
  flag("forces", "Show the joint reactions and the force plots.");
  flag("3d", "With --frames: animate the 3D view alone at --size (the window not painted).");
  cli.addPositionalArgument("model", "A .linkage.json file or an example's name.",
                            "[FILE | EXAMPLE-NAME]");
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  // Fresh settings, the user's left alone (as `linkage --screenshot`).
  QApplication::setOrganizationName(QStringLiteral("linkage-headless"));
  QCommandLineParser cli;
  cli.setApplicationDescription(QStringLiteral("The editor's frame times, offscreen."));
  cli.addHelpOption();
  addOptions(cli);
  cli.process(app);
  const int frames = count(cli, QStringLiteral("frames"));
  const int moves = count(cli, QStringLiteral("drag"));
  if (frames < 0 || moves < 0) return 2;
  if (frames == 0 && moves == 0) {
    std::fprintf(stderr, "linkage_frames_bench: give --frames N or --drag N\n");
    return 2;
  }
  if (cli.positionalArguments().size() > 1) {
    std::fprintf(stderr, "linkage_frames_bench: give one model\n");
    return 2;
  }
  OffscreenOptions o;
  o.model = cli.positionalArguments().value(0);
  for (auto [name, on] : {std::pair{"ics", &o.ics},
                          {"plots", &o.plots},
                          {"dark", &o.dark},
                          {"extremes", &o.extremes},
                          {"transmission", &o.transmission},
                          {"checks", &o.checks},
                          {"forces", &o.forces}})
    *on = cli.isSet(QString::fromLatin1(name));
  QString why;
  if (!parseOffscreen(cli.value("angle"), cli.value("size"), o, &why)) {
    std::fprintf(stderr, "linkage_frames_bench: %s\n", qPrintable(why));
    return 2;
  }
  MainWindow w;
  if (const int status = setUpOffscreen(w, o)) return status;
  if (frames > 0 && cli.isSet("3d")) {
    // The window hidden: only the 3D view is painted, as `linkage --screenshot --3d` draws it.
    w.hide();
    std::unique_ptr<View3dWidget> v(makeOffscreen3dView(w, o));
    return benchmarkFrames(w, frames, v.get());
  }
  if (frames > 0)
    if (const int status = benchmarkFrames(w, frames)) return status;
  return moves > 0 ? benchmarkDrag(w, moves, cli.isSet("ctrl")) : 0;
}
