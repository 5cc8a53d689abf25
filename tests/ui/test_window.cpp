// The main window as a user meets it: files (open, bad files, save keeping unknown fields,
// unsaved changes), the examples menu, the title, the scrubber, settings remembered.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImageReader>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>

#include "animation/crank_bar.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "dialogs.h"
#include "document/commands.h"
#include "document/document.h"
#include "export/animation_export.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

QString dataFile(const char* name) {
  return QStringLiteral(LINKAGE_TEST_DATA_DIR "/") + name;
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
  const QString path = dir.filePath(name);
  QFile f(path);
  f.open(QIODevice::WriteOnly);
  f.write(text);
  return path;
}

TEST(Window, BadFileShowsTheReadersMessageAndKeepsTheDocument) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-1"));
  ASSERT_TRUE(w.document()->setCrankDeg(25).ok());
  const std::string before = serializeMechanism(w.document()->design());
  QTemporaryDir dir;
  const QString bad = writeFile(dir, "bad.linkage.json",
                                R"({"format": "linkage", "version": 1, "bodies": [], "joints": [)");
  test::DialogAnswer answer;
  answer.press(QMessageBox::Ok);
  EXPECT_FALSE(w.openFile(bad));  // the dialog variant
  EXPECT_TRUE(answer.seen);
  EXPECT_NE(answer.text.indexOf("line 1"), -1) << answer.text.toStdString();
  EXPECT_EQ(serializeMechanism(w.document()->design()), before);
  EXPECT_NEAR(w.document()->crankDeg(), 25, 1e-12);
  EXPECT_EQ(w.windowTitle(), QStringLiteral("wanzer-inversion-1[*] \u2014 Linkage"));
}

TEST(Window, SaveRoundTripKeepsUnknownFields) {
  MainWindow w;
  QString why;
  ASSERT_TRUE(w.openFile(dataFile("io_extras.json"), &why)) << why.toStdString();
  QTemporaryDir dir;
  const QString out = dir.filePath("extras.linkage.json");
  ASSERT_TRUE(w.document()->save(out, &why)) << why.toStdString();
  const LoadResult a = loadMechanismFile(dataFile("io_extras.json").toStdString());
  const LoadResult b = loadMechanismFile(out.toStdString());
  ASSERT_TRUE(a.mechanism && b.mechanism);
  EXPECT_EQ(mechanismDifference(*a.mechanism, *b.mechanism), "");
  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QByteArray text = f.readAll();
  for (const char* field : {"\"zeta\"", "\"mass_kg\"", "\"motor\"", "\"comment\"", "\"view\""})
    EXPECT_NE(text.indexOf(field), -1) << field;
  EXPECT_EQ(w.windowTitle(), QStringLiteral("extras.linkage.json[*] \u2014 Linkage"));
}

TEST(Window, UnsavedChangesPromptOnNewOpenAndClose) {
  auto* w = new MainWindow;
  ASSERT_TRUE(w->openExample("four-bar-crank-rocker"));
  Mechanism m = w->document()->design();
  m.name = "renamed";
  editDesign(w->document(), "Rename", m);
  EXPECT_TRUE(w->document()->isModified());
  EXPECT_TRUE(w->isWindowModified());
  // New, cancelled: nothing changes.
  test::DialogAnswer cancel;
  cancel.press(QMessageBox::Cancel);
  w->file().newDocument->trigger();
  EXPECT_TRUE(cancel.seen);
  EXPECT_NE(cancel.text.indexOf("four-bar-crank-rocker"), -1);
  EXPECT_EQ(w->document()->design().name, "renamed");
  // Close, cancelled: the window stays.
  test::DialogAnswer keep;
  keep.press(QMessageBox::Cancel);
  EXPECT_FALSE(w->close());
  EXPECT_TRUE(keep.seen);
  // New, discarding: an empty document with a ground.
  test::DialogAnswer discard;
  discard.press(QMessageBox::Discard);
  w->file().newDocument->trigger();
  EXPECT_TRUE(discard.seen);
  EXPECT_EQ(w->document()->design().bodies.size(), 1u);
  EXPECT_FALSE(w->document()->isModified());
  // Unmodified: closing asks nothing.
  EXPECT_TRUE(w->close());
}

TEST(Window, UndoAndRedoRestoreTheDesignExactly) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  Document* d = w.document();
  ASSERT_TRUE(d->setCrankDeg(60).ok());
  const std::string before = serializeMechanism(d->design());
  const Vec2 at = d->kinematics().position(d->design().outputs[0]);
  Mechanism m = d->design();
  m.point(*m.findPoint("ground.O4"))->pos.x() += 3;
  editDesign(d, "Move O4", m);
  const std::string after = serializeMechanism(d->design());
  EXPECT_NE(after, before);
  w.edit().undo->trigger();
  EXPECT_EQ(serializeMechanism(d->design()), before);
  EXPECT_LT((d->kinematics().position(d->design().outputs[0]) - at).norm(), 1e-12);
  w.edit().redo->trigger();
  EXPECT_EQ(serializeMechanism(d->design()), after);
}

TEST(Window, ExamplesMenuListsEveryExampleByName) {
  MainWindow w;
  const std::vector<std::string> names = listExamples();
  for (const std::string& n : names) {
    QAction* a = w.findChild<QAction*>(QStringLiteral("example:") + QString::fromStdString(n));
    ASSERT_TRUE(a) << n;
    a->trigger();
    EXPECT_EQ(w.document()->displayName().toStdString(), n);
    EXPECT_TRUE(w.document()->solved()) << n;
    EXPECT_TRUE(w.document()->filePath().isEmpty());  // Save asks where
  }
}

TEST(Window, DroppedFileOpens) {
  MainWindow w;
  QMimeData data;
  data.setUrls({QUrl::fromLocalFile(dataFile("io_wanzer.json"))});
  w.show();
  QDragEnterEvent enter(QPoint(100, 100), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&w, &enter);
  EXPECT_TRUE(enter.isAccepted());
  QDropEvent drop(QPointF(100, 100), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(&w, &drop);
  EXPECT_EQ(w.document()->filePath(), dataFile("io_wanzer.json"));
}

TEST(Window, ScrubberMovesTheMechanismAndFollowsIt) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  Document* d = w.document();
  CrankBar* bar = w.animation().crankBar();
  bar->slider()->setValue(1200);  // tenths of a degree
  EXPECT_NEAR(d->crankDeg(), 120, 1e-9);
  bar->angleBox()->setValue(725.5);  // two turns and a bit
  EXPECT_NEAR(d->crankDeg(), 725.5, 1e-9);
  EXPECT_EQ(bar->slider()->value(), 55);
  // And the other way: the animation moves the scrubber.
  ASSERT_TRUE(d->setCrankDeg(400).ok());
  EXPECT_EQ(bar->slider()->value(), 400);
  EXPECT_NEAR(bar->angleBox()->value(), 400, 1e-9);
}

// The first start (no saved layout) at 1400 x 950 with the plots shown: the canvas has most of
// the height (it had 440 px: the docks' sizes were asked before the window had its own and
// were not applied), the Properties are wide enough for the outputs, and their form is whole,
// not cut off behind its splitter.
TEST(Window, TheFirstLayoutLeavesTheCanvasMostOfTheRoomAndTheFormWhole) {
  QSettings().clear();
  MainWindow w;
  ASSERT_TRUE(w.openNameOrPath(QStringLiteral("wanzer-inversion-2")));
  w.resize(1400, 950);
  w.plots().dock->show();
  w.show();
  QTest::qWait(100);
  EXPECT_GE(w.canvas()->height(), 480);
  EXPECT_GE(w.plots().dock->height(), 220);
  EXPECT_GE(w.properties().dock->width(), 300);
  auto* form = w.properties().dock->findChild<QScrollArea*>();
  ASSERT_TRUE(form);
  EXPECT_GE(form->height(), form->widget()->sizeHint().height());
  EXPECT_FALSE(form->verticalScrollBar()->isVisible());
  QSettings().clear();
}

TEST(Window, ViewOptionsAndLayoutAreRemembered) {
  QSettings().clear();
  {
    MainWindow w;
    w.view().showGrid->setChecked(false);
    w.centres().show->setChecked(true);
    w.centres().dock->hide();
    w.resize(1100, 760);
    w.show();
    QApplication::processEvents();
    EXPECT_TRUE(w.close());
  }
  MainWindow w;
  EXPECT_FALSE(w.view().showGrid->isChecked());
  EXPECT_TRUE(w.centres().show->isChecked());
  EXPECT_EQ(w.size(), QSize(1100, 760));
  w.show();
  QApplication::processEvents();
  EXPECT_FALSE(w.centres().dock->isVisible());
  QSettings().clear();
}

TEST(Window, EveryActionHasAStatusTipAndTheKeysAreTheDocumented) {
  MainWindow w;
  // The typed handles are the actions of those object names (QSettings and scripts know them
  // by these), with their documented keys.
  const std::tuple<QAction*, const char*, const char*> keys[] = {
      {w.file().open, "open", "Ctrl+O"},
      {w.file().save, "save", "Ctrl+S"},
      {w.file().saveAs, "saveAs", "Ctrl+Shift+S"},
      {w.animation().play, "play", "Space"},
      {w.animation().stepForward, "stepForward", "Right"},
      {w.animation().stepBack, "stepBack", "Left"},
      {w.view().fit, "fit", "F"},
      {w.centres().show, "showCentres", "I"},
      {w.edit().undo, "undo", "Ctrl+Z"}};
  for (const auto& [a, name, key] : keys) {
    ASSERT_TRUE(a) << name;
    EXPECT_EQ(a->objectName(), QString::fromLatin1(name));
    EXPECT_EQ(a->shortcut().toString(), QString::fromLatin1(key)) << name;
  }
  EXPECT_TRUE(w.edit().redo->shortcuts().contains(QKeySequence("Ctrl+Shift+Z")));
  EXPECT_TRUE(w.edit().redo->shortcuts().contains(QKeySequence("Ctrl+Y")));
  for (QAction* a : w.findChildren<QAction*>())
    if (!a->objectName().isEmpty() && !a->isSeparator() && !a->menu())
      EXPECT_FALSE(a->statusTip().isEmpty()) << a->objectName().toStdString();
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

// File > Export > Animation: each frame is the mechanism at its crank angle, the whole motion
// in view at the asked size; the window is as it was afterwards.
TEST(Window, AnimationFramesShowTheMechanismAtEachAngle) {
  MainWindow w;
  w.resize(1000, 700);
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  w.show();
  QApplication::processEvents();
  const double zoom = w.canvas()->zoom();
  const QImage a = w.exports().renderFrame(0, QSize(320, 240));
  const QImage b = w.exports().renderFrame(90, QSize(320, 240));
  EXPECT_EQ(a.size(), QSize(320, 240));
  EXPECT_NE(a, b);
  EXPECT_EQ(a, w.exports().renderFrame(0, QSize(320, 240)));  // the same angle, the same picture
  shot(&w, "animation-window");
  a.save(QString::fromLocal8Bit(qgetenv("LINKAGE_TEST_SHOTS")) + "/frame-0.png");
  QTemporaryDir dir;
  AnimationSpec spec;
  spec.path = dir.filePath("wanzer.gif");
  spec.size = QSize(240, 180);
  spec.frames = 12;
  QString why;
  ASSERT_TRUE(exportAnimation(
      spec, [&](double deg, QSize s) { return w.exports().renderFrame(deg, s); }, &why))
      << why.toStdString();
  w.exports().endFrames();
  EXPECT_NEAR(w.canvas()->zoom(), zoom, 1e-12);
  EXPECT_NEAR(w.scene()->pixelSize(), 1 / zoom, 1e-12);
  QImageReader gif(spec.path);
  EXPECT_EQ(gif.imageCount(), 12);
  EXPECT_EQ(gif.size(), QSize(240, 180));
}

}  // namespace
}  // namespace linkage::ui
