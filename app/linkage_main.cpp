// linkage: the editor. Also renders a screenshot without a display (the frame benchmarks in
// the same offscreen window are bench/editor_frames_bench.cpp).
//
//   linkage [FILE | EXAMPLE-NAME]
//   linkage --screenshot OUT.png [FILE|EXAMPLE] [--angle DEG] [--ics] [--plots] [--size WxH]
//           [--dark] [--extremes] [--transmission] [--checks] [--forces] [--cycle]
//   linkage --version | --help
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QTimer>
#include <cstdio>
#include <cstring>
#include <initializer_list>

#include "document/autosave.h"
#include "document/document.h"
#include "window/main_window.h"
#include "window/offscreen_window.h"
#include "window/probe.h"

namespace {

bool hasArgument(int argc, char** argv, std::initializer_list<const char*> names) {
  for (int i = 1; i < argc; ++i)
    for (const char* n : names)
      if (!std::strcmp(argv[i], n)) return true;
  return false;
}

bool wantsHeadless(int argc, char** argv) {
  return hasArgument(argc, argv, {"--screenshot"});
}

// --version and --help print and exit: they need no display either.
bool onlyPrints(int argc, char** argv) {
  return hasArgument(argc, argv, {"--version", "-v", "--help", "-h", "-?", "--help-all"});
}

// The editor's options besides --help and --version.
struct Options {
  const QCommandLineOption screenshot{QStringLiteral("screenshot"),
                                      QStringLiteral("Render the window to a PNG and exit."),
                                      QStringLiteral("OUT.png")};
  const QCommandLineOption angle{QStringLiteral("angle"),
                                 QStringLiteral("Crank angle for the screenshot (degrees)."),
                                 QStringLiteral("DEG")};
  const QCommandLineOption ics{QStringLiteral("ics"),
                               QStringLiteral("Show the instant centres (overlay and panel).")};
  const QCommandLineOption plots{QStringLiteral("plots"), QStringLiteral("Show the plots dock.")};
  const QCommandLineOption size{QStringLiteral("size"),
                                QStringLiteral("Window size (default 1280x800)."),
                                QStringLiteral("WxH")};
  const QCommandLineOption dark{QStringLiteral("dark"), QStringLiteral("Use the dark palette.")};
  const QCommandLineOption extremes{QStringLiteral("extremes"),
                                    QStringLiteral("Draw the extreme positions of the output.")};
  const QCommandLineOption transmission{QStringLiteral("transmission"),
                                        QStringLiteral("Show the transmission angles.")};
  const QCommandLineOption forces{QStringLiteral("forces"),
                                  QStringLiteral("Show the joint reactions and the force plots.")};
  const QCommandLineOption checks{QStringLiteral("checks"),
                                  QStringLiteral("Show the design-checks dock.")};
  const QCommandLineOption cycle{
      QStringLiteral("cycle"),
      QStringLiteral("Show the cycle dock (the file's timing) and its clearances on the canvas.")};

  void addTo(QCommandLineParser& cli) const {
    cli.addOptions(
        {screenshot, angle, ics, plots, size, dark, extremes, transmission, checks, forces, cycle});
  }
};

// --screenshot: the window offscreen, no event loop.
int runOffscreen(const QCommandLineParser& cli, const Options& opt, const QString& model) {
  linkage::ui::OffscreenOptions o;
  o.model = model;
  o.ics = cli.isSet(opt.ics);
  o.forces = cli.isSet(opt.forces);
  o.cycle = cli.isSet(opt.cycle);
  o.plots = cli.isSet(opt.plots);
  o.dark = cli.isSet(opt.dark);
  o.extremes = cli.isSet(opt.extremes);
  o.transmission = cli.isSet(opt.transmission);
  o.checks = cli.isSet(opt.checks);
  QString why;
  if (!linkage::ui::parseOffscreen(cli.value(opt.angle), cli.value(opt.size), o, &why)) {
    std::fprintf(stderr, "linkage: %s\n", qPrintable(why));
    return 2;
  }
  return linkage::ui::writeScreenshot(o, cli.value(opt.screenshot));
}

// Work an editor left unsaved when it stopped (a crash, kill -9): offered once the window is up,
// into this window while it is empty, else into a new one each.
void offerRecoveries(linkage::ui::MainWindow* w) {
  linkage::ui::offerRecovery(w, [w](const linkage::ui::Recovery& r) {
    linkage::ui::MainWindow* into = w;
    if (w->document()->isModified() || !w->document()->filePath().isEmpty() ||
        w->document()->design().bodies.size() > 1) {
      into = new linkage::ui::MainWindow;
      into->show();
    }
    into->openRecovered(r);
  });
}

}  // namespace

int main(int argc, char** argv) {
  // The frame benchmarks were options of the editor until issue 19.
  if (hasArgument(argc, argv, {"--benchmark-frames", "--benchmark-drag"})) {
    std::fprintf(stderr,
                 "linkage: the frame benchmarks are bench/linkage_frames_bench (--frames N, "
                 "--drag N; docs/benchmarks.md, \"The editor\")\n");
    return 2;
  }
  const bool headless = wantsHeadless(argc, argv);
  // No display needed for pictures (unless one is asked for explicitly).
  if ((headless || onlyPrints(argc, argv)) && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("linkage"));
  QApplication::setApplicationVersion(QStringLiteral(LINKAGE_VERSION));
  // The installed desktop entry (share/applications), so that the desktop shows its name and icon.
  QGuiApplication::setDesktopFileName(QStringLiteral("io.github.linkage.Linkage"));
  // Screenshots start from the default layout and leave the user's settings alone.
  QApplication::setOrganizationName(headless ? QStringLiteral("linkage-headless")
                                             : QStringLiteral("linkage"));

  QCommandLineParser cli;
  cli.setApplicationDescription(
      QStringLiteral("Planar linkage editor: draw, animate, instant centres, plots."));
  cli.addHelpOption();
  cli.addVersionOption();
  cli.addPositionalArgument(QStringLiteral("model"),
                            QStringLiteral("A .linkage.json file or an example's name "
                                           "(e.g. wanzer-inversion-2)."),
                            QStringLiteral("[FILE | EXAMPLE-NAME]"));
  const Options opt;
  opt.addTo(cli);
  cli.process(app);

  const QStringList args = cli.positionalArguments();
  if (args.size() > 1) {
    std::fprintf(stderr, "linkage: give one model, not %lld\n", (long long)args.size());
    return 2;
  }
  if (headless) return runOffscreen(cli, opt, args.value(0));

  linkage::ui::startProbeFromEnvironment();
  auto* w = new linkage::ui::MainWindow;
  if (!args.isEmpty()) {
    QString why;
    if (!w->openNameOrPath(args[0], &why)) {
      std::fprintf(stderr, "linkage: %s\n", qPrintable(why));
      delete w;
      return 2;
    }
  }
  w->show();
  QTimer::singleShot(0, w, [w] { offerRecoveries(w); });
  return app.exec();
}
