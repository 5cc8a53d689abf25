// linkage-cli plot as a script runs it: the homework's 3 x 2 figure from the command line, the
// stacked figure of one model, bad input, a crank that stops; the other commands make no
// QApplication.
#ifdef LINKAGE_CLI
#include <gtest/gtest.h>

#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include "linkage/io/model_file.h"
#include "mechanisms.h"

namespace linkage::ui {
namespace {

struct CliRun {
  int exit = -1;
  QString err;
};

CliRun cli(const QStringList& args, const QString& platform = QString()) {
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.remove("QT_QPA_PLATFORM");  // the command chooses offscreen itself
  env.remove("DISPLAY");
  if (!platform.isEmpty()) env.insert("QT_QPA_PLATFORM", platform);
  p.setProcessEnvironment(env);
  p.start(LINKAGE_CLI, args);
  if (!p.waitForFinished(60000)) return {};
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
          QString::fromUtf8(p.readAllStandardError())};
}

// Pixels near a colour in a rectangle of an image.
int pixelsNear(const QImage& img, QRect r, QColor c) {
  int n = 0;
  for (int y = r.top(); y <= r.bottom(); ++y)
    for (int x = r.left(); x <= r.right(); ++x) {
      const QColor p = img.pixelColor(x, y);
      n += std::abs(p.red() - c.red()) + std::abs(p.green() - c.green()) +
               std::abs(p.blue() - c.blue()) <
           40;
    }
  return n;
}

TEST(CliPlot, TheHomeworksThreeByTwoFigure) {
  QTemporaryDir dir;
  const QString png = dir.filePath("wanzer.png");
  const CliRun r =
      cli({"plot", "wanzer-inversion-1", "wanzer-inversion-2", "--point", "needlebar.G", "--revs",
           "4", "--units", "g", "--size", "1400x900", "--out", png});
  ASSERT_EQ(r.exit, 0) << r.err.toStdString();
  const QImage img(png);
  ASSERT_EQ(img.size(), QSize(1400, 900));
  // One column per model (blue, then red), three plots in each: a curve in every cell.
  for (int col = 0; col < 2; ++col)
    for (int row = 0; row < 3; ++row) {
      const QRect cell(col * 700, 30 + row * 280, 700, 260);
      const QColor mine = col == 0 ? QColor(31, 119, 180) : QColor(214, 39, 40);
      const QColor other = col == 0 ? QColor(214, 39, 40) : QColor(31, 119, 180);
      EXPECT_GT(pixelsNear(img, cell, mine), 500) << col << "," << row;
      EXPECT_EQ(pixelsNear(img, cell, other), 0) << col << "," << row;
    }
  // The same figure as SVG: titled by the models' names, labelled with units.
  const QString svg = dir.filePath("wanzer.svg");
  ASSERT_EQ(cli({"plot", "wanzer-inversion-1", "wanzer-inversion-2", "--point", "needlebar.G",
                 "--revs", "4", "--units", "g", "--out", svg})
                .exit,
            0);
  QFile f(svg);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QString text = QString::fromUtf8(f.readAll());
  EXPECT_TRUE(text.contains("Wanzer needle bar, inversion 1: needlebar.G"));
  EXPECT_TRUE(text.contains("Wanzer needle bar, inversion 2: needlebar.G"));
  EXPECT_EQ(text.count("Acceleration ay [g]"), 2);
  EXPECT_EQ(text.count("Position y [mm]"), 2);
  EXPECT_TRUE(text.contains(">1440<"));  // four revolutions on the axis
}

TEST(CliPlot, OneModelGivesThreeStackedPlots) {
  QTemporaryDir dir;
  const QString pdf = dir.filePath("sc.pdf");
  const CliRun r = cli({"plot", "slider-crank-22a-lambda-0.5", "--out", pdf, "--units", "m"});
  ASSERT_EQ(r.exit, 0) << r.err.toStdString();
  QFile f(pdf);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  EXPECT_TRUE(bytes.startsWith("%PDF-"));
  EXPECT_TRUE(bytes.trimmed().endsWith("%%EOF"));
  const QString png = dir.filePath("sc.png");
  ASSERT_EQ(cli({"plot", "slider-crank-22a-lambda-0.5", "--out", png, "--jerk"}).exit, 0);
  EXPECT_EQ(QImage(png).size(), QSize(900, 1100));  // the default size with a jerk row
}

// The distance between two points of a machine in space, and a tilted direction: figures with
// the quantity in their labels (the values are checked in tests/test_spatial_curves.cpp).
TEST(CliPlot, ADistanceInSpaceAndATiltedDirection) {
  QTemporaryDir dir;
  const QString svg = dir.filePath("d.svg");
  CliRun r = cli({"plot", "lockstitch-bevel", "--point", "needlebar.N", "--component", "distance",
                  "--to", "hook.K", "--out", svg});
  ASSERT_EQ(r.exit, 0) << r.err.toStdString();
  QFile f(svg);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  EXPECT_TRUE(f.readAll().contains("d to hook.K"));
  const QString tilted = dir.filePath("t.svg");
  r = cli({"plot", "rssr-crank-rocker", "--point", "rocker.C", "--along", "30", "--elevation", "45",
           "--out", tilted});
  ASSERT_EQ(r.exit, 0) << r.err.toStdString();
  QFile t(tilted);
  ASSERT_TRUE(t.open(QIODevice::ReadOnly));
  EXPECT_TRUE(QString::fromUtf8(t.readAll()).contains(QString::fromUtf8("at 45° up")));
}

TEST(CliPlot, BadInputExitsTwoWithAMessage) {
  QTemporaryDir dir;
  const QString out = dir.filePath("x.png");
  const std::vector<std::pair<QStringList, QString>> cases = {
      {{"plot", "--out", out}, "no MODEL"},
      {{"plot", "wanzer-inversion-1"}, "no --out"},
      {{"plot", "no-such-model", "--out", out}, "no such file"},
      {{"plot", "wanzer-inversion-1", "--out", dir.filePath("x.jpg")}, ".png, .pdf or .svg"},
      {{"plot", "wanzer-inversion-1", "--out", out, "--size", "12x9"}, "--size"},
      {{"plot", "wanzer-inversion-1", "--out", out, "--revs", "0"}, "--revs"},
      {{"plot", "wanzer-inversion-1", "--out", out, "--units", "furlongs"}, "--units"},
      {{"plot", "wanzer-inversion-1", "--out", out, "--frobnicate"}, "unknown option"},
      {{"plot", "wanzer-inversion-1", "slider-crank-22a-lambda-0.3", "--point", "needlebar.G",
        "--out", out},
       "no point \"needlebar.G\""},
      {{"plot", "lockstitch-bevel", "--out", out, "--component", "distance"}, "needs --to"},
      {{"plot", "lockstitch-bevel", "--out", out, "--to", "hook.K"}, "--to is the second point"},
      {{"plot", "lockstitch-bevel", "--out", out, "--component", "distance", "--to", "hook.Q"},
       "no point \"hook.Q\" (--to body.point)"},
      {{"plot", "lockstitch-bevel", "--out", out, "--elevation", "10"}, "give --along DEG"},
      {{"plot", "lockstitch-bevel", "--out", out, "--along", "0", "--elevation", "91"},
       "[-90, 90]"},
  };
  for (const auto& [args, message] : cases) {
    const CliRun r = cli(args);
    EXPECT_EQ(r.exit, 2) << args.join(' ').toStdString();
    EXPECT_TRUE(r.err.contains(message)) << r.err.toStdString();
  }
  EXPECT_FALSE(QFile::exists(out));
  EXPECT_EQ(cli({"plot", "--help"}).exit, 0);
}

TEST(CliPlot, CrankThatStopsDrawsThePartThatExistsAndExitsThree) {
  QTemporaryDir dir;
  auto f = test::fourBar(100, 60, 40, 70, 30);  // locks 52.8 degrees on
  f.m.name = "non-Grashof four-bar";
  const QString model = dir.filePath("stops.linkage.json");
  ASSERT_TRUE(saveMechanismFile(f.m, model.toStdString()).ok);
  const QString png = dir.filePath("stops.png");
  const CliRun r = cli({"plot", model, "--out", png});
  EXPECT_EQ(r.exit, 3) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains("the figure shows the curves up to there")) << r.err.toStdString();
  EXPECT_EQ(QImage(png).size(), QSize(900, 900));
}

TEST(CliPlot, OtherCommandsMakeNoQApplicationAndLinkageCliLoadsNoQt) {
  // A platform plugin that does not exist aborts any QApplication: these must not make one.
  EXPECT_EQ(cli({"info", "wanzer-inversion-2"}, "no-such-platform").exit, 0);
  EXPECT_EQ(cli({"analyze", "wanzer-inversion-2", "--angle", "10"}, "no-such-platform").exit, 0);
  // The figure is drawn by linkage-plot; linkage-cli itself links no Qt library.
  QProcess ldd;
  ldd.start("ldd", {LINKAGE_CLI});
  if (!ldd.waitForFinished(30000) || ldd.exitCode() != 0) GTEST_SKIP() << "no ldd";
  const QString libs = QString::fromUtf8(ldd.readAllStandardOutput());
  EXPECT_TRUE(libs.contains("libc.so")) << libs.toStdString();
  EXPECT_FALSE(libs.contains("Qt")) << libs.toStdString();
}

TEST(CliPlot, WithoutLinkageplotBesideItPlotSaysSo) {
  QTemporaryDir dir;
  const QString lone = dir.filePath("linkage-cli");
  ASSERT_TRUE(QFile::copy(LINKAGE_CLI, lone));
  QProcess p;
  p.start(lone, {"plot", "wanzer-inversion-1", "--out", dir.filePath("x.png")});
  ASSERT_TRUE(p.waitForFinished(30000));
  EXPECT_EQ(p.exitCode(), 1);
  EXPECT_TRUE(QString::fromUtf8(p.readAllStandardError()).contains("linkage-plot is not there"));
  EXPECT_FALSE(QFile::exists(dir.filePath("x.png")));
}

}  // namespace
}  // namespace linkage::ui
#endif
