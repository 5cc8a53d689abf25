// Documents opened, edited, autosaved, replaced, made new and closed in a seeded sequence
// (issue 26, item 4): with clearances watched and their marks (rings and labelled distances)
// on the canvas, zoomed and restyled in between. Opening an example over a watched clearance
// crashed: fitting the view restyled the canvas's items from a list taken before the marks
// made their labels anew. After every step what each window shows is whole: the marks' labels
// are the marks', the autosaved copy is the unsaved design or there is none.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QPointer>
#include <QTest>
#include <QUndoStack>
#include <random>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "canvas/clearance_marks.h"
#include "cycle/cycle_entries.h"
#include "cycle/cycle_panel.h"
#include "dialogs.h"
#include "document/autosave.h"
#include "document/commands.h"
#include "document/document.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

std::vector<QString> examples() {
  std::vector<QString> out;
  for (const std::string& n : listExamples(QApplication::applicationFilePath().toStdString()))
    out.push_back(QString::fromStdString(n));
  return out;
}

// Two points of different moving bodies ("hook.K needlebar.N"), or "" when there are none.
QString twoPoints(const Mechanism& m) {
  for (const Point& a : m.points)
    for (const Point& b : m.points)
      if (a.body != b.body && !m.body(a.body)->ground && !m.body(b.body)->ground)
        return QString::fromStdString(m.pointLabel(a.id) + " " + m.pointLabel(b.id));
  return {};
}

// The cycle dock computes on its throttle: until it has, or a second has passed.
void settle(MainWindow& w) {
  for (int i = 0; i < 100; ++i) {
    QCoreApplication::processEvents();
    if (!w.cycle().panel()->redrawPending()) break;
    QTest::qWait(10);
  }
  QCoreApplication::processEvents();
}

// What every window shows after a step: the marks' labels are as many as the marks (none left
// from before, none missing), and the copy of unsaved work is the design or there is none.
void expectWhole(MainWindow& w, const char* step) {
  SCOPED_TRACE(step);
  const ClearanceMarksItem* marks = w.cycle().marks();
  EXPECT_EQ(marks->childItems().size(), static_cast<qsizetype>(marks->marks().size()));
  EXPECT_EQ(marks->scene(), w.scene());
  w.autosaver()->waitForWrites();
  const QString copy = w.autosaver()->copyPath();
  if (!w.document()->isModified()) {
    EXPECT_FALSE(QFileInfo::exists(copy)) << "a copy of work there is not";
    return;
  }
  // Autosaved at every turn of the event loop: the copy is the design as it is.
  const LoadResult r = loadMechanismFile(copy.toStdString());
  ASSERT_TRUE(r.mechanism) << r.error;
  EXPECT_EQ(serializeMechanism(*r.mechanism), serializeMechanism(w.document()->design()));
}

// One step of the sequence, chosen by `r`.
void step(MainWindow& w, std::mt19937& r, const std::vector<QString>& names) {
  Document* doc = w.document();
  switch (r() % 10) {
    case 0:
    case 1: {  // another example over this one (a clearance or not)
      const QString name = names[r() % names.size()];
      ASSERT_TRUE(w.openExample(name)) << name;
      break;
    }
    case 2:
    case 3: {  // a clearance watched, computed, marked
      const QString pair = twoPoints(doc->design());
      if (!pair.isEmpty()) w.cycle().panel()->addEntry(EntryKind::Clearance, pair);
      break;
    }
    case 4:  // zoom in or out: the items restyled for the scale
      w.canvas()->zoomBy(r() % 2 ? 1.6 : 0.55);
      break;
    case 5: {  // an edit, autosaved now (on the writer's thread) or at the next turn
      Mechanism m = doc->design();
      m.name += "+";
      editDesign(doc, "Rename", std::move(m));
      if (r() % 2) w.autosaver()->saveNow();
      break;
    }
    case 6:  // undo or redo
      r() % 2 ? doc->undoStack()->undo() : doc->undoStack()->redo();
      break;
    case 7:  // the dock hidden or shown: its marks go and come back
      w.cycle().dock->setVisible(!w.cycle().dock->isVisible());
      break;
    case 8:  // the palette: the items restyled for the colours
      w.scene()->setPalette(r() % 2 ? QPalette(Qt::darkGray) : QPalette());
      break;
    case 9: {  // File > New, its unsaved changes let go
      test::DialogAnswer discard;
      if (doc->isModified()) discard.press(QMessageBox::Discard);
      w.file().newDocument->trigger();
      EXPECT_FALSE(doc->isModified());
      break;
    }
  }
}

TEST(DocumentStress, OpeningEditingAutosavingAndClosingInterleavedWithClearancesShown) {
  const std::vector<QString> names = examples();
  ASSERT_GE(names.size(), 5u);
  std::mt19937 r(26);
  auto* w = new MainWindow;
  w->resize(1200, 800);
  w->show();
  // Autosave at every turn of the event loop rather than after 30 s.
  w->autosaver()->setInterval(0);
  ASSERT_TRUE(w->openExample("lockstitch-machine"));
  w->cycle().dock->show();
  // The example's own clearance (to the needle as a segment), and one more.
  ASSERT_TRUE(w->cycle().panel()->addEntry(EntryKind::Clearance, "hook.K needlebar.N"));
  settle(*w);
  ASSERT_EQ(w->cycle().marks()->marks().size(), 2u);
  // The sequence first: another example over the marked clearance.
  ASSERT_TRUE(w->openExample("slider-crank-22a-masses"));
  settle(*w);
  expectWhole(*w, "slider-crank over the lockstitch machine's clearance");
  for (int i = 0; i < 60; ++i) {
    step(*w, r, names);
    settle(*w);
    expectWhole(*w, "a step");
    if (i % 15 == 14) {
      // A second window, worked in and closed with its copy being written.
      auto* other = new MainWindow;
      other->show();
      other->autosaver()->setInterval(0);
      for (int k = 0; k < 6; ++k) {
        step(*other, r, names);
        settle(*other);
      }
      Mechanism m = other->document()->design();
      m.name += " edited";
      editDesign(other->document(), "Rename", std::move(m));
      other->autosaver()->saveNow();
      const QString copy = other->autosaver()->copyPath();
      QPointer<MainWindow> gone(other);
      test::DialogAnswer discard;  // its unsaved changes let go
      discard.press(QMessageBox::Discard);
      EXPECT_TRUE(other->close());
      EXPECT_TRUE(discard.seen);
      QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
      EXPECT_TRUE(gone.isNull());
      EXPECT_FALSE(QFileInfo::exists(copy)) << "the closed window's copy stayed";
    }
  }
  // Edited and left: the copy is the design, byte for byte.
  Mechanism m = w->document()->design();
  m.name = "last";
  editDesign(w->document(), "Rename", std::move(m));
  w->autosaver()->saveNow();
  w->autosaver()->waitForWrites();
  const LoadResult copy = loadMechanismFile(w->autosaver()->copyPath().toStdString());
  ASSERT_TRUE(copy.mechanism) << copy.error;
  EXPECT_EQ(serializeMechanism(*copy.mechanism), serializeMechanism(w->document()->design()));
  test::DialogAnswer discard;
  discard.press(QMessageBox::Discard);
  EXPECT_TRUE(w->close());
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

}  // namespace
}  // namespace linkage::ui
