// linkage: the editor. Also renders a screenshot without a display (the frame benchmarks in
// the same offscreen window are bench/editor_frames_bench.cpp).
//
//   linkage [FILE | EXAMPLE-NAME]
//   linkage --screenshot OUT.png [FILE|EXAMPLE] [--angle DEG] [--ics] [--plots] [--size WxH]
//           [--dark] [--extremes] [--transmission] [--checks] [--forces] [--cycle] [--cam]
//           [--sensitivity] [--3d]
//           [--plane NAME]
//   linkage --version | --help
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QTimer>
#include <algorithm>
#include <cstdio>

#include "document/autosave.h"
#include "document/document.h"
#include "window/main_window.h"
#include "window/offscreen_window.h"
#include "window/probe.h"
#include "window/qt_notes.h"

namespace {

// The editor's options, read by one QCommandLineParser.
struct Options {
  const QCommandLineOption help{{QStringLiteral("h"), QStringLiteral("help"), QStringLiteral("?")},
                                QStringLiteral("Print this help and exit.")};
  const QCommandLineOption version{{QStringLiteral("v"), QStringLiteral("version")},
                                   QStringLiteral("Print the version and exit.")};
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
  const QCommandLineOption view3d{
      QStringLiteral("3d"),
      QStringLiteral("The picture is the 3D view alone (isometric; a planar machine from the "
                     "front) at --size.")};
  const QCommandLineOption plane{QStringLiteral("plane"),
                                 QStringLiteral("The plane the canvas shows (a machine in space)."),
                                 QStringLiteral("NAME")};
  const QCommandLineOption cycle{
      QStringLiteral("cycle"),
      QStringLiteral("Show the cycle dock (the file's timing) and its clearances on the canvas.")};
  const QCommandLineOption cam{QStringLiteral("cam"),
                               QStringLiteral("Show the cam dock (the file's first cam).")};
  const QCommandLineOption sensitivity{
      QStringLiteral("sensitivity"),
      QStringLiteral("Show the sensitivity dock (the first output point's y).")};

  // The frame benchmarks were options of the editor until issue 19: they say where they went.
  const QCommandLineOption benchmarks = [] {
    QCommandLineOption o({QStringLiteral("benchmark-frames"), QStringLiteral("benchmark-drag")},
                         QStringLiteral("Moved to bench/linkage_frames_bench."),
                         QStringLiteral("N"));
    o.setFlags(QCommandLineOption::HiddenFromHelp);
    return o;
  }();

  void addTo(QCommandLineParser& cli) const {
    // -platform is one option, as Qt reads it (not -p -l -a ...); -v and -h are still known.
    cli.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    cli.setApplicationDescription(
        QStringLiteral("Planar linkage editor: draw, animate, instant centres, plots."));
    cli.addPositionalArgument(QStringLiteral("model"),
                              QStringLiteral("A .linkage.json file or an example's name "
                                             "(e.g. wanzer-inversion-2)."),
                              QStringLiteral("[FILE | EXAMPLE-NAME]"));
    cli.addOptions({help, version, screenshot, angle, ics, plots, size, dark, extremes,
                    transmission, checks, forces, cycle, cam, sensitivity, view3d, plane,
                    benchmarks});
  }
};

QStringList argumentsOf(int argc, char** argv) {
  QStringList out;
  for (int i = 0; i < argc; ++i) out << QString::fromLocal8Bit(argv[i]);
  return out;
}

// Whether the options the parser did not know are all Qt's own (QGuiApplication's and
// QApplication's, as `-platform offscreen` or `-style Fusion`), which QApplication takes out of
// the command line before it is read again.
bool onlyQtOptionsUnknown(const QCommandLineParser& cli) {
  static const QStringList qt =
      QStringLiteral(
          "platform platformpluginpath platformtheme plugin qmljsdebugger qwindowgeometry "
          "qwindowicon qwindowtitle reverse session style stylesheet widgetcount display geometry "
          "name title visual ncols cmap fn font bg background fg foreground btn button im "
          "inputstyle nograb dograb sync")
          .split(QLatin1Char(' '));
  const QStringList unknown = cli.unknownOptionNames();
  return !unknown.isEmpty() && std::all_of(unknown.begin(), unknown.end(),
                                           [](const QString& n) { return qt.contains(n); });
}

// What the command line asks that needs no window: the help, the version, a refusal. Returns
// the exit status, or -1 to go on.
int answerWithoutWindow(const QCommandLineParser& cli, const Options& opt) {
  if (cli.isSet(opt.help)) {
    // Read without an application, the parser does not know the program's name.
    QString help = cli.helpText();
    help.replace(QStringLiteral("<executable_name>"), QStringLiteral("linkage"));
    std::fputs(qPrintable(help), stdout);
    return 0;
  }
  if (cli.isSet(opt.version)) {
    std::printf("linkage %s\n", LINKAGE_VERSION);
    return 0;
  }
  if (cli.isSet(opt.benchmarks)) {
    std::fprintf(stderr,
                 "linkage: the frame benchmarks are bench/linkage_frames_bench (--frames N, "
                 "--drag N; docs/benchmarks.md, \"The editor\")\n");
    return 2;
  }
  if (cli.positionalArguments().size() > 1) {
    std::fprintf(stderr, "linkage: give one model, not %lld\n",
                 static_cast<long long>(cli.positionalArguments().size()));
    return 2;
  }
  return -1;
}

// --screenshot: the window offscreen, no event loop.
int runOffscreen(const QCommandLineParser& cli, const Options& opt, const QString& model) {
  linkage::ui::OffscreenOptions o;
  o.model = model;
  o.ics = cli.isSet(opt.ics);
  o.forces = cli.isSet(opt.forces);
  o.cycle = cli.isSet(opt.cycle);
  o.cam = cli.isSet(opt.cam);
  o.sensitivity = cli.isSet(opt.sensitivity);
  o.plots = cli.isSet(opt.plots);
  o.dark = cli.isSet(opt.dark);
  o.extremes = cli.isSet(opt.extremes);
  o.transmission = cli.isSet(opt.transmission);
  o.checks = cli.isSet(opt.checks);
  o.view3d = cli.isSet(opt.view3d);
  o.plane = cli.value(opt.plane);
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
  QCommandLineParser cli;
  const Options opt;
  opt.addTo(cli);
  // Read before any application exists: --help and --version print and exit without one (a
  // QGuiApplication would look for a display and write its notes on standard error), and
  // --screenshot needs the offscreen platform chosen before it starts. A command line that
  // does not read may hold Qt's own options (-platform, -style): read again once QApplication
  // has taken them out.
  if (cli.parse(argumentsOf(argc, argv))) {
    if (const int status = answerWithoutWindow(cli, opt); status >= 0) return status;
    // No display needed for pictures (unless one is asked for explicitly).
    if (cli.isSet(opt.screenshot)) linkage::ui::prepareOffscreen();
  } else if (!onlyQtOptionsUnknown(cli)) {
    std::fprintf(stderr, "linkage: %s\n", qPrintable(cli.errorText()));
    return 2;
  }
  QApplication app(argc, argv);
  if (!cli.parse(QApplication::arguments())) {
    std::fprintf(stderr, "linkage: %s\n", qPrintable(cli.errorText()));
    return 2;
  }
  if (const int status = answerWithoutWindow(cli, opt); status >= 0) return status;
  const bool headless = cli.isSet(opt.screenshot);
  QApplication::setApplicationName(QStringLiteral("linkage"));
  QApplication::setApplicationVersion(QStringLiteral(LINKAGE_VERSION));
  // The installed desktop entry (share/applications), so that the desktop shows its name and icon.
  QGuiApplication::setDesktopFileName(QStringLiteral("io.github.linkage.Linkage"));
  // Screenshots start from the default layout and leave the user's settings alone.
  QApplication::setOrganizationName(headless ? QStringLiteral("linkage-headless")
                                             : QStringLiteral("linkage"));
  const QStringList args = cli.positionalArguments();
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
