// No work lost: the copy of unsaved work (written on time and on leaving the window, removed
// when saved or closed), offered after a crash with what it differs in, recovered as an unsaved
// edit of its file, never written over the file unasked.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "dialogs.h"
#include "document/autosave.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "tools/selection.h"
#include "window/features.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

// The four-bar example copied to `dir`, opened in `w`.
QString openFourBar(MainWindow& w, const QTemporaryDir& dir) {
  const std::optional<std::string> ex =
      resolveModel("four-bar-crank-rocker", QApplication::applicationFilePath().toStdString());
  const QString path = dir.filePath("four-bar.linkage.json");
  QFile::copy(QString::fromStdString(*ex), path);
  EXPECT_TRUE(w.openFile(path));
  return path;
}

void moveCouplerP(Document* d, double x) {
  Mechanism m = d->design();
  m.point(*m.findPoint("coupler.P"))->pos.x() = x;
  editDesign(d, "move", m);
}

TEST(Recovery, TheCopyHoldsTheUnsavedWorkAndGoesWhenItIsSaved) {
  QTemporaryDir dir;
  MainWindow w;
  const QString path = openFourBar(w, dir);
  Autosaver* a = w.autosaver();
  moveCouplerP(w.document(), 33.25);
  EXPECT_FALSE(QFileInfo::exists(a->copyPath()));  // not at once: after 30 s, or leaving
  a->saveNow();
  a->waitForWrites();
  ASSERT_TRUE(QFileInfo::exists(a->copyPath()));
  LoadResult copy = loadMechanismFile(a->copyPath().toStdString());
  ASSERT_TRUE(copy.mechanism) << copy.error;
  EXPECT_EQ(serializeMechanism(*copy.mechanism), serializeMechanism(w.document()->design()));
  // Every 30 s of unsaved work (here 1 s).
  a->setInterval(1);
  moveCouplerP(w.document(), 34.5);
  QTest::qWait(1300);
  a->waitForWrites();
  copy = loadMechanismFile(a->copyPath().toStdString());
  ASSERT_TRUE(copy.mechanism);
  EXPECT_EQ(copy.mechanism->point(*copy.mechanism->findPoint("coupler.P"))->pos.x(), 34.5);
  // Saved: no unsaved work, no copy; and nothing is offered (this editor runs).
  ASSERT_TRUE(w.save());
  a->waitForWrites();
  EXPECT_FALSE(QFileInfo::exists(a->copyPath()));
  moveCouplerP(w.document(), 35);
  a->saveNow();
  a->waitForWrites();
  EXPECT_TRUE(QFileInfo::exists(a->copyPath()));
  EXPECT_TRUE(findRecoveries().empty());
  (void)path;
}

TEST(Recovery, ACopyLeftByAStoppedEditorIsOfferedAndRecoveredUnsaved) {
  QTemporaryDir dir;
  QString path, copy;
  std::string edited;
  {
    MainWindow w;
    path = openFourBar(w, dir);
    moveCouplerP(w.document(), 31.5);
    w.autosaver()->saveNow();
    w.autosaver()->waitForWrites();
    edited = serializeMechanism(w.document()->design());
    // A crash: the editor stops without removing its copy or its lock (kept aside here, and
    // put back once the window is gone).
    copy = w.autosaver()->copyPath();
    const QString meta = QString(copy).replace(".linkage.json", ".meta.json");
    QFile::copy(copy, copy + ".kept");
    QFile::copy(meta, meta + ".kept");
    w.document()->undoStack()->setClean();  // closes without asking
  }
  const QString meta = QString(copy).replace(".linkage.json", ".meta.json");
  ASSERT_FALSE(QFileInfo::exists(copy));
  QFile::rename(copy + ".kept", copy);
  QFile::rename(meta + ".kept", meta);
  const std::vector<Recovery> found = findRecoveries();
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].path, path);
  EXPECT_EQ(found[0].title, "four-bar.linkage.json");
  EXPECT_TRUE(found[0].saved.isValid());
  EXPECT_EQ(found[0].difference, "coupler.P moved from (30.293, 55.2441) to (31.5, 55.2441)");

  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QByteArray before = file.readAll();
  file.close();
  MainWindow w;
  test::DialogAnswer answer;
  answer.expect([](QWidget* box) {
    static_cast<QMessageBox*>(box)->defaultButton()->click();  // Recover
  });
  offerRecovery(&w, [&w](const Recovery& r) { w.openRecovered(r); });
  EXPECT_TRUE(answer.seen);
  EXPECT_TRUE(answer.text.contains("four-bar.linkage.json")) << answer.text;
  EXPECT_EQ(serializeMechanism(w.document()->design()), edited);
  EXPECT_TRUE(w.document()->isModified());
  EXPECT_EQ(w.document()->filePath(), path);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  EXPECT_EQ(file.readAll(), before);  // the file as it was: written only when saved
  file.close();
  EXPECT_FALSE(QFileInfo::exists(copy));
  EXPECT_TRUE(findRecoveries().empty());
  // One undo step back to the file.
  w.document()->undoStack()->undo();
  EXPECT_FALSE(w.document()->isModified());
  w.document()->undoStack()->redo();
  w.document()->undoStack()->setClean();
}

TEST(Recovery, DiscardRemovesTheCopyAndKeepAsksAgain) {
  QTemporaryDir dir;
  QDir().mkpath(Autosaver::folder());
  Mechanism m = *loadMechanismFile(*resolveModel("four-bar-crank-rocker",
                                                 QApplication::applicationFilePath().toStdString()))
                     .mechanism;
  const QString copy = Autosaver::folder() + "/left-1.linkage.json";
  ASSERT_TRUE(saveMechanismFile(m, copy.toStdString()).ok);
  QFile meta(Autosaver::folder() + "/left-1.meta.json");
  ASSERT_TRUE(meta.open(QIODevice::WriteOnly));
  meta.write(R"({"path": "", "title": "untitled", "saved": "2024-01-01T10:00:00"})");
  meta.close();
  MainWindow w;
  test::DialogAnswer keep;
  keep.expect([](QWidget* box) {
    for (QAbstractButton* b : static_cast<QMessageBox*>(box)->buttons())
      if (b->text().contains("Keep")) b->click();
  });
  bool opened = false;
  offerRecovery(&w, [&](const Recovery&) { opened = true; });
  EXPECT_TRUE(keep.seen);
  EXPECT_TRUE(keep.text.contains("untitled"));
  EXPECT_FALSE(opened);
  EXPECT_EQ(findRecoveries().size(), 1u);
  test::DialogAnswer discard;
  discard.press(QMessageBox::Discard);
  offerRecovery(&w, [&](const Recovery&) { opened = true; });
  EXPECT_TRUE(discard.seen);
  EXPECT_FALSE(opened);
  EXPECT_TRUE(findRecoveries().empty());
  EXPECT_FALSE(QFileInfo::exists(copy));
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

// Another program writes the open file: the window says so and offers to reload it; its own
// saves are not taken for another program's.
TEST(Recovery, AFileChangedOnDiskIsOfferedForReload) {
  QTemporaryDir dir;
  MainWindow w;
  const QString path = openFourBar(w, dir);
  moveCouplerP(w.document(), 36);
  ASSERT_TRUE(w.save());
  QTest::qWait(400);  // no question for our own save
  EXPECT_EQ(QApplication::activeModalWidget(), nullptr);
  // Another program: coupler.P moved to x = 50.
  Mechanism other = w.document()->design();
  other.point(*other.findPoint("coupler.P"))->pos.x() = 50;
  test::DialogAnswer answer;
  answer.press(QMessageBox::Yes);
  ASSERT_TRUE(saveMechanismFile(other, path.toStdString()).ok);
  for (int i = 0; i < 50 && !answer.seen; ++i) QTest::qWait(50);
  EXPECT_TRUE(answer.seen);
  EXPECT_TRUE(answer.text.contains("changed on disk by another program")) << answer.text;
  const Mechanism& m = w.document()->design();
  EXPECT_EQ(m.point(*m.findPoint("coupler.P"))->pos.x(), 50);
  EXPECT_FALSE(w.document()->isModified());
  // Declined: asked once, the window says the file differs.
  other.point(*other.findPoint("coupler.P"))->pos.x() = 51;
  test::DialogAnswer no;
  no.press(QMessageBox::No);
  ASSERT_TRUE(saveMechanismFile(other, path.toStdString()).ok);
  for (int i = 0; i < 50 && !no.seen; ++i) QTest::qWait(50);
  EXPECT_TRUE(no.seen);
  EXPECT_EQ(w.document()->design().point(*m.findPoint("coupler.P"))->pos.x(), 50);
  // The window says so while it is true: a selection, an edit and its undo leave it (it went
  // at the next selection), a save over the file ends it.
  const QString differs = "four-bar.linkage.json differs from the file on disk";
  EXPECT_EQ(w.messageStrip()->notice(), differs);
  w.tools().selection()->add(*m.findPoint("coupler.P"));
  QApplication::processEvents();
  EXPECT_EQ(w.messageStrip()->notice(), differs);
  moveCouplerP(w.document(), 40);
  w.edit().undo->trigger();
  w.animation().toStart->trigger();
  QApplication::processEvents();
  EXPECT_EQ(w.messageStrip()->notice(), differs);
  ASSERT_TRUE(w.save());
  EXPECT_TRUE(w.messageStrip()->notice().isEmpty()) << w.messageStrip()->notice();
}

}  // namespace
}  // namespace linkage::ui
