// linkage: the editor. Also renders a screenshot or measures frame times without a display.
//
//   linkage [FILE | EXAMPLE-NAME]
//   linkage --screenshot OUT.png [FILE|EXAMPLE] [--angle DEG] [--ics] [--size WxH] [--dark]
//   linkage --benchmark-frames N [FILE|EXAMPLE] [--ics] [--plots] [--size WxH]
//   linkage --benchmark-drag N [FILE|EXAMPLE] [--ctrl] [--ics] [--plots] [--size WxH]
//   (all three also [--extremes] [--transmission] [--checks]: the design checks)
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QTimer>
#include <cstdio>
#include <cstring>

#include "document/autosave.h"
#include "document/document.h"
#include "window/headless.h"
#include "window/main_window.h"
#include "window/probe.h"

namespace {

bool wantsHeadless(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--screenshot") || !std::strcmp(argv[i], "--benchmark-frames") ||
        !std::strcmp(argv[i], "--benchmark-drag"))
      return true;
  return false;
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
  const bool headless = wantsHeadless(argc, argv);
  // No display needed for pictures and measurements (unless one is asked for explicitly).
  if (headless && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("linkage"));
  // Headless runs start from the default layout and leave the user's settings alone.
  QApplication::setOrganizationName(headless ? QStringLiteral("linkage-headless")
                                             : QStringLiteral("linkage"));

  QCommandLineParser cli;
  cli.setApplicationDescription(
      QStringLiteral("Planar linkage editor: draw, animate, instant centres, plots."));
  cli.addHelpOption();
  cli.addPositionalArgument(QStringLiteral("model"),
                            QStringLiteral("A .linkage.json file or an example's name "
                                           "(e.g. wanzer-inversion-2)."),
                            QStringLiteral("[FILE | EXAMPLE-NAME]"));
  const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                      QStringLiteral("Render the window to a PNG and exit."),
                                      QStringLiteral("OUT.png"));
  const QCommandLineOption bench(QStringLiteral("benchmark-frames"),
                                 QStringLiteral("Animate N frames as fast as possible in the "
                                                "offscreen window and print frame times."),
                                 QStringLiteral("N"));
  const QCommandLineOption drag(QStringLiteral("benchmark-drag"),
                                QStringLiteral("Drag the first output point with N mouse moves "
                                               "in the offscreen window; print the time from "
                                               "each move to the redrawn frame."),
                                QStringLiteral("N"));
  const QCommandLineOption ctrl(QStringLiteral("ctrl"),
                                QStringLiteral("With --benchmark-drag: hold Ctrl (the design "
                                               "changes while dragging)."));
  const QCommandLineOption angle(QStringLiteral("angle"),
                                 QStringLiteral("Crank angle for the screenshot (degrees)."),
                                 QStringLiteral("DEG"));
  const QCommandLineOption ics(QStringLiteral("ics"),
                               QStringLiteral("Show the instant centres (overlay and panel)."));
  const QCommandLineOption plots(QStringLiteral("plots"), QStringLiteral("Show the plots dock."));
  const QCommandLineOption size(QStringLiteral("size"),
                                QStringLiteral("Window size (default 1280x800)."),
                                QStringLiteral("WxH"));
  const QCommandLineOption dark(QStringLiteral("dark"), QStringLiteral("Use the dark palette."));
  const QCommandLineOption extremes(QStringLiteral("extremes"),
                                    QStringLiteral("Draw the extreme positions of the output."));
  const QCommandLineOption transmission(QStringLiteral("transmission"),
                                        QStringLiteral("Show the transmission angles."));
  const QCommandLineOption checks(QStringLiteral("checks"),
                                  QStringLiteral("Show the design-checks dock."));
  cli.addOptions({screenshot, bench, drag, ctrl, angle, ics, plots, size, dark, extremes,
                  transmission, checks});
  cli.process(app);

  const QStringList args = cli.positionalArguments();
  if (args.size() > 1) {
    std::fprintf(stderr, "linkage: give one model, not %lld\n", (long long)args.size());
    return 2;
  }
  if (headless) {
    linkage::ui::HeadlessOptions o;
    o.model = args.value(0);
    o.screenshot = cli.value(screenshot);
    o.ics = cli.isSet(ics);
    o.plots = cli.isSet(plots);
    o.dark = cli.isSet(dark);
    o.reshape = cli.isSet(ctrl);
    o.extremes = cli.isSet(extremes);
    o.transmission = cli.isSet(transmission);
    o.checks = cli.isSet(checks);
    QString why;
    if (!linkage::ui::parseHeadless(cli.value(bench), cli.value(angle), cli.value(size), o, &why,
                                    cli.value(drag))) {
      std::fprintf(stderr, "linkage: %s\n", qPrintable(why));
      return 2;
    }
    return linkage::ui::runHeadless(o);
  }

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
