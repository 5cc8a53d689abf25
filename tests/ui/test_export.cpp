// File > Export: the motion table as the spec's CSV, figures as PNG, PDF and SVG, the animation
// as a GIF (read back with Qt's own GIF reader, not the giflib that wrote it) and as PNGs.
#include <gtest/gtest.h>

#include <QFile>
#include <QImageReader>
#include <QPainter>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <cmath>
#include <set>

#include "dialogs.h"
#include "document/document.h"
#include "window/features.h"

#include <QDialog>
#include <QFileDialog>
#include <QLineEdit>
#include <QSpinBox>
#include "export/animation_export.h"
#include "export/animation_export_dialog.h"
#include "export/motion_table_export.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/io/numbers.h"
#include "linkage/tables/motion_table.h"
#include "plots/plots_panel.h"

namespace linkage::ui {
namespace {

QString example(const char* name) {
  return QString::fromStdString(*resolveModel(name));
}

QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// --- motion table ---------------------------------------------------------------------------

// File > Export > Motion Table as a user fills its dialog: 36 steps per revolution, 2
// revolutions give 73 rows (it wrote 36 x 2 per revolution, 145, before).
TEST(MotionTableExport, TheWindowsDialogTakesStepsPerRevolution) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  QTemporaryDir dir;
  const QString path = dir.filePath("window.csv");
  test::DialogAnswer options, file;
  options.expect([&](QWidget* d) {
    const QList<QSpinBox*> boxes = d->findChildren<QSpinBox*>();
    ASSERT_EQ(boxes.size(), 2);
    boxes[0]->setValue(36);  // steps per revolution
    boxes[1]->setValue(2);   // revolutions
    file.expect([&](QWidget* f) {
      auto* chooser = qobject_cast<QFileDialog*>(f);
      ASSERT_NE(chooser, nullptr);
      // The name typed where a user types it (selectFile alone is taken asynchronously, once
      // the dialog has listed its folder).
      auto* name = chooser->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
      ASSERT_NE(name, nullptr);
      name->setText(path);
      QMetaObject::invokeMethod(chooser, "accept");
    });
    qobject_cast<QDialog*>(d)->accept();
  });
  w.exports().table->trigger();
  ASSERT_TRUE(options.seen && file.seen);
  const QList<QByteArray> lines = readAll(path).split('\n');
  ASSERT_EQ(lines.size(), 1 + 73 + 1);  // header, 0 ... 720 by 10 degrees, final newline
  EXPECT_EQ(lines[2].split(',').at(1).toStdString(), "10");
  EXPECT_EQ(lines[73].split(',').at(1).toStdString(), "720");
  // Every number determined, accelerations included: the window hidden, the document has them
  // off (a table of "nan" accelerations was written then; a debug build asserted).
  for (int i = 1; i <= 73; ++i)
    for (const QByteArray& field : lines[i].split(','))
      EXPECT_TRUE(std::isfinite(parseNumber(field.toStdString()).value_or(NAN)))
          << i << ": " << lines[i].toStdString();
}

TEST(MotionTableExport, ParsesAndMatchesTheSolverAtEveryRow) {
  Document doc;
  ASSERT_TRUE(doc.open(example("wanzer-inversion-2"), nullptr));
  ASSERT_TRUE(doc.setCrankDeg(40).ok());  // the table starts at 0 whatever the pose
  QTemporaryDir dir;
  const QString path = dir.filePath("table.csv");
  QString err;
  ASSERT_TRUE(exportMotionTable(doc, path, 72, 2, &err)) << err.toStdString();
  EXPECT_DOUBLE_EQ(doc.crankDeg(), 40);
  const QList<QByteArray> lines = readAll(path).split('\n');
  ASSERT_EQ(lines.size(), 1 + 145 + 1);  // header, 0 ... 720 by 5 degrees, final newline
  EXPECT_TRUE(lines.back().isEmpty());
  const std::vector<PointId> pts = doc.design().outputs;
  EXPECT_EQ(lines[0].toStdString(), motionTableHeader(doc.design(), pts));
  Kinematics k;
  ASSERT_TRUE(k.load(doc.design()).ok());
  const PointId G = pts.at(0);
  for (int i = 0; i <= 144; ++i) {
    const QList<QByteArray> f = lines[1 + i].split(',');
    ASSERT_EQ(f.size(), 8) << i;
    std::vector<double> v;
    for (const QByteArray& x : f) {
      const std::optional<double> d = parseNumber(x.toStdString());
      ASSERT_TRUE(d.has_value()) << x.toStdString();
      v.push_back(*d);
    }
    const double deg = i * 5.0;
    ASSERT_TRUE(k.moveTo(deg).ok());
    EXPECT_EQ(v[1], deg);
    EXPECT_DOUBLE_EQ(v[0], deg / (6 * k.rpm()));
    const Kinematics::PointMotion m = k.motion(G);
    const double expect[] = {m.position.x(), m.position.y(),     m.velocity.x(),
                             m.velocity.y(), m.acceleration.x(), m.acceleration.y()};
    // Solved from 40 degrees back to 0 rather than from the drawing: the same to rounding.
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(v[2 + c], expect[c], 1e-9 * std::max(1.0, std::abs(expect[c]))) << i << " " << c;
  }
}

#ifdef LINKAGE_CLI
TEST(MotionTableExport, TheSameBytesAsLinkageCliAnalyze) {
  Document doc;
  ASSERT_TRUE(doc.open(example("wanzer-inversion-1"), nullptr));
  QTemporaryDir dir;
  QString err;
  ASSERT_TRUE(exportMotionTable(doc, dir.filePath("ui.csv"), 360, 1, &err)) << err.toStdString();
  QProcess cli;
  cli.start(LINKAGE_CLI, {"analyze", "wanzer-inversion-1", "--out", dir.filePath("cli.csv")});
  ASSERT_TRUE(cli.waitForFinished(30000));
  ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
  EXPECT_EQ(readAll(dir.filePath("ui.csv")), readAll(dir.filePath("cli.csv")));
}
#endif

TEST(MotionTableExport, RefusesWhatIsNotTheFormatsTableAndWritesNothing) {
  Document doc;
  ASSERT_TRUE(doc.open(example("wanzer-inversion-1"), nullptr));
  QTemporaryDir dir;
  const QString path = dir.filePath("t.csv");
  QString err;
  EXPECT_FALSE(exportMotionTable(doc, path, 7, 0.5, &err));
  EXPECT_TRUE(err.contains("whole number")) << err.toStdString();
  Mechanism none = doc.design();
  none.outputs.clear();
  doc.setDesign(none);
  EXPECT_FALSE(exportMotionTable(doc, path, 360, 1, &err));
  EXPECT_TRUE(err.contains("no output points")) << err.toStdString();
  EXPECT_FALSE(QFile::exists(path));
}

// --- figures --------------------------------------------------------------------------------

class FigureExport : public ::testing::Test {
 protected:
  void SetUp() override {
    QSettings().remove("plots");
    ASSERT_TRUE(doc.open(example("wanzer-inversion-1"), nullptr));
    panel.setDocument(&doc);  // never shown: the export computes what it needs
    PlotUnits u;
    u.acceleration = AccelerationUnit::G;
    panel.setUnits(u);
  }
  void TearDown() override { QSettings().remove("plots"); }
  QTemporaryDir dir;
  Document doc;
  PlotsPanel panel;
  const QStringList labels{"Position y [mm]", "Velocity vy [mm/s]", "Acceleration ay [g]",
                           "disk angle [deg], clockwise", "Wanzer needle bar, inversion 1"};
};

TEST_F(FigureExport, PngDecodesWithTheAskedSize) {
  QString err;
  const QString path = dir.filePath("fig.png");
  ASSERT_TRUE(panel.exportFigure(path, QSize(1000, 750), &err)) << err.toStdString();
  EXPECT_EQ(panel.computations(), 1);
  QImage img(path);
  ASSERT_FALSE(img.isNull());
  EXPECT_EQ(img.size(), QSize(1000, 750));
  // The curve is there: pixels of its colour (31, 119, 180) in each third of the height.
  for (int band = 0; band < 3; ++band) {
    int blue = 0;
    for (int y = band * 250; y < (band + 1) * 250; ++y)
      for (int x = 0; x < 1000; ++x) {
        const QColor c = img.pixelColor(x, y);
        blue += std::abs(c.red() - 31) + std::abs(c.green() - 119) + std::abs(c.blue() - 180) < 30;
      }
    EXPECT_GT(blue, 300) << band;
  }
}

TEST_F(FigureExport, SvgIsWellFormedVectorWithTheLabels) {
  QString err;
  const QString path = dir.filePath("fig.svg");
  ASSERT_TRUE(panel.exportFigure(path, QSize(900, 700), &err)) << err.toStdString();
  const QByteArray svg = readAll(path);
  QXmlStreamReader xml(svg);
  int paths = 0;
  QString text;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && (xml.name() == u"path" || xml.name() == u"polyline")) ++paths;
    if (xml.isStartElement() && xml.name() == u"text") text += xml.readElementText() + "\n";
  }
  ASSERT_FALSE(xml.hasError()) << xml.errorString().toStdString();
  EXPECT_GT(paths, 10);
  EXPECT_EQ(svg.count("<image"), 0);  // nothing rastered
  for (const QString& l : labels) EXPECT_TRUE(text.contains(l)) << l.toStdString();
}

TEST_F(FigureExport, PdfIsWellFormedWithTheLabels) {
  QString err;
  const QString path = dir.filePath("fig.pdf");
  ASSERT_TRUE(panel.exportFigure(path, QSize(900, 700), &err)) << err.toStdString();
  const QByteArray pdf = readAll(path);
  EXPECT_TRUE(pdf.startsWith("%PDF-"));
  EXPECT_TRUE(pdf.trimmed().endsWith("%%EOF"));
  const QString pdftotext = QStandardPaths::findExecutable("pdftotext");
  if (pdftotext.isEmpty()) GTEST_SKIP() << "pdftotext (poppler-utils) is not installed";
  QProcess p;
  p.start(pdftotext, {path, "-"});
  ASSERT_TRUE(p.waitForFinished(30000));
  ASSERT_EQ(p.exitCode(), 0) << p.readAllStandardError().toStdString();
  const QString text = QString::fromUtf8(p.readAllStandardOutput());
  for (const QString& l : labels)
    EXPECT_TRUE(text.contains(l)) << l.toStdString() << "\n" << text.toStdString();
}

TEST_F(FigureExport, BadNamesAndSizesAreRefused) {
  QString err;
  EXPECT_FALSE(panel.exportFigure(dir.filePath("fig.bmp"), QSize(900, 700), &err));
  EXPECT_TRUE(err.contains("png, pdf or svg")) << err.toStdString();
  EXPECT_FALSE(panel.exportFigure(dir.filePath("fig.png"), QSize(10, 700), &err));
  EXPECT_FALSE(panel.exportFigure(dir.filePath("no/such/dir/fig.png"), QSize(900, 700), &err));
  EXPECT_FALSE(err.isEmpty());
  EXPECT_FALSE(QFile::exists(dir.filePath("fig.png")));
}

// --- animation ------------------------------------------------------------------------------

// A stand-in for the canvas: a bar turning about the centre, with (antialiased) or without
// blended edges.
FrameRenderer bar(bool antialiased) {
  return [antialiased](double deg, QSize size) {
    QImage img(size, QImage::Format_ARGB32_Premultiplied);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing, antialiased);
    p.translate(size.width() / 2.0, size.height() / 2.0);
    p.rotate(-deg);
    p.setPen(QPen(QColor(31, 119, 180), 6));
    p.drawLine(QPointF(0, 0), QPointF(size.width() / 3.0, 0));
    if (antialiased) {
      // More links, thin and at odd angles: their blended edges make hundreds of colours.
      const QColor links[] = {QColor(44, 160, 44), QColor(148, 103, 189), QColor(255, 127, 14),
                              QColor(140, 86, 75), QColor(23, 190, 207)};
      for (int i = 0; i < 5; ++i) {
        p.setPen(QPen(links[i], 1.7 + 0.6 * i));
        p.drawLine(QPointF(-size.width() / 2.0 + 7 * i, -size.height() / 3.0 + 3 * i),
                   QPointF(size.width() / 3.0 - 5 * i, size.height() / 2.5 - 11 * i));
      }
    }
    p.setBrush(QColor(214, 39, 40));
    p.setPen(Qt::NoPen);
    p.drawEllipse(QPointF(0, 0), 8, 8);
    return img;
  };
}

// An animation of `frames` frames of the given size written in `dir`.
AnimationSpec animation(const QTemporaryDir& dir, const char* name, QSize size, int frames) {
  AnimationSpec s;
  s.path = dir.filePath(name);
  s.size = size;
  s.frames = frames;
  return s;
}

TEST(AnimationExport, GifDecodesToTheAskedFramesAndSizeExactlyWhenFewColours) {
  QTemporaryDir dir;
  AnimationSpec s = animation(dir, "run.gif", QSize(160, 120), 12);
  s.fps = 20;
  QString err;
  const FrameRenderer render = bar(false);
  std::vector<double> angles;
  ASSERT_TRUE(exportAnimation(
      s,
      [&](double d, QSize z) {
        angles.push_back(d);
        return render(d, z);
      },
      &err))
      << err.toStdString();
  QImageReader reader(s.path);
  ASSERT_TRUE(reader.canRead()) << reader.errorString().toStdString();
  EXPECT_EQ(reader.imageCount(), 12);
  EXPECT_EQ(reader.size(), QSize(160, 120));
  int frames = 0;
  for (QImage img = reader.read(); !img.isNull(); img = reader.read(), ++frames) {
    EXPECT_EQ(img.size(), QSize(160, 120));
    EXPECT_EQ(reader.nextImageDelay(), 50);  // 100 / 20 fps = 5 hundredths
    // Three colours: the palette holds them exactly and the frame comes back unchanged.
    const QImage expected =
        render(frameAngle(s, frames), s.size).convertToFormat(QImage::Format_RGB32);
    EXPECT_EQ(img.convertToFormat(QImage::Format_RGB32), expected) << frames;
  }
  EXPECT_EQ(frames, 12);
  // Frames cover one turn without repeating the first: 0, 30, ..., 330.
  EXPECT_DOUBLE_EQ(frameAngle(s, 11), 330);
}

TEST(AnimationExport, GifOfAnAntialiasedSceneKeepsItsColoursClose) {
  QTemporaryDir dir;
  const AnimationSpec s = animation(dir, "aa.gif", QSize(200, 150), 8);
  QString err;
  const FrameRenderer render = bar(true);
  std::set<QRgb> colours;  // more than a GIF holds: the palette must choose
  const QImage first = render(0, s.size).convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < first.height(); ++y)
    for (int x = 0; x < first.width(); ++x) colours.insert(first.pixel(x, y));
  ASSERT_GT(colours.size(), 256u);
  ASSERT_TRUE(exportAnimation(s, render, &err)) << err.toStdString();
  QImageReader reader(s.path);
  ASSERT_EQ(reader.imageCount(), 8);
  for (int i = 0; i < 8; ++i) {
    const QImage got = reader.read().convertToFormat(QImage::Format_RGB32);
    const QImage want = render(frameAngle(s, i), s.size).convertToFormat(QImage::Format_RGB32);
    ASSERT_EQ(got.size(), want.size());
    double sum = 0;
    int worst = 0;
    for (int y = 0; y < got.height(); ++y)
      for (int x = 0; x < got.width(); ++x) {
        const QRgb a = got.pixel(x, y), b = want.pixel(x, y);
        const int d = std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) +
                      std::abs(qBlue(a) - qBlue(b));
        sum += d;
        worst = std::max(worst, d);
      }
    EXPECT_LT(sum / (got.width() * got.height()), 1.0) << i;  // mean error under a level
    EXPECT_LT(worst, 60) << i;
    EXPECT_EQ(got.pixel(0, 0), qRgb(255, 255, 255));  // flat colours exact
  }
}

TEST(AnimationExport, PngSequenceIsNumberedFrames) {
  QTemporaryDir dir;
  AnimationSpec s = animation(dir, "run.png", QSize(64, 48), 5);
  s.format = AnimationSpec::Format::PngSequence;
  QString err;
  ASSERT_TRUE(exportAnimation(s, bar(true), &err)) << err.toStdString();
  const QStringList names = pngSequenceNames(s.path, 5);
  ASSERT_EQ(names.size(), 5);
  EXPECT_EQ(names[0], dir.filePath("run_0001.png"));
  for (const QString& n : names) EXPECT_EQ(QImage(n).size(), QSize(64, 48)) << n.toStdString();
  EXPECT_FALSE(QFile::exists(dir.filePath("run_0006.png")));
}

TEST(AnimationExport, SpeedAndRefusals) {
  // 240 rpm is 4 turns a second: 72 frames of one turn at real speed is 288 fps, at a quarter
  // of it 72 fps.
  EXPECT_DOUBLE_EQ(framesPerSecondFor(72, 1, 240, 1), 288);
  EXPECT_DOUBLE_EQ(framesPerSecondFor(72, 1, 240, 0.25), 72);
  EXPECT_EQ(gifDelay(25), 4);
  EXPECT_EQ(gifDelay(1000), 2);
  AnimationSpec s;
  s.path = "/nonexistent/dir/x.gif";
  s.size = QSize(32, 32);
  s.frames = 2;
  QString err;
  EXPECT_FALSE(exportAnimation(s, bar(false), &err));
  EXPECT_FALSE(err.isEmpty());
  s.frames = 0;
  EXPECT_FALSE(exportAnimation(s, bar(false), &err));
  s.frames = 2;
  EXPECT_FALSE(exportAnimation(
      s, [](double, QSize) { return QImage(); }, &err));
  EXPECT_TRUE(err.contains("frame 1")) << err.toStdString();
}

TEST(AnimationExport, DialogGivesTheSpec) {
  AnimationExportDialog d(240);
  AnimationSpec s;
  s.format = AnimationSpec::Format::PngSequence;
  s.path = "/tmp/x.png";
  s.size = QSize(320, 200);
  s.frames = 36;
  s.revs = 2;
  s.fps = 12;
  d.setSpec(s);
  const AnimationSpec got = d.spec();
  EXPECT_EQ(got.format, s.format);
  EXPECT_EQ(got.path, s.path);
  EXPECT_EQ(got.size, s.size);
  EXPECT_EQ(got.frames, 36);
  EXPECT_DOUBLE_EQ(got.revs, 2);
  EXPECT_DOUBLE_EQ(got.fps, 12);
}

}  // namespace
}  // namespace linkage::ui
