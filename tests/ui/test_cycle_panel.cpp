// The Cycle dock (issue 18): entries typed are undo steps kept in the file, their results are
// the solver's exact windows, overlaps and closest approaches; a clearance is watched from the
// canvas's selection and marked on the canvas at its closest pose; the cursor follows the crank
// and a click turns it; only determined numbers are shown; no work while hidden; the exports
// are the command line's table and a figure.
#include <gtest/gtest.h>

#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

#include "cycle/cycle_panel.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/tables/timing_table.h"
#include "tools/selection.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

class CyclePanelTest : public ::testing::Test {
 protected:
  void open(const char* name) {
    ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel(name)), nullptr)) << name;
  }
  // The example without the timing it ships: entries made from nothing.
  void openBare(const char* name) {
    open(name);
    Mechanism m = doc.design();
    m.timing = {};
    doc.setContents(m, doc.filePath());
  }
  void showAndSettle() {
    panel.resize(1400, 350);
    panel.show();
    settle();
  }
  void settle() {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    ASSERT_FALSE(panel.redrawPending());
  }
  Document doc;
  CyclePanel panel{&doc};
};

TEST_F(CyclePanelTest, EntriesAreUndoStepsWithTheSolversResults) {
  openBare("lockstitch-machine");
  showAndSettle();
  EXPECT_FALSE(panel.diagram());  // nothing to show yet: a sentence says what to add
  EXPECT_TRUE(panel.message().contains("add a row")) << panel.message();
  QString why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Window, "needle=needlebar.N:y<-185", &why)) << why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Window, " low=needlebar.N:y<-180 ", &why)) << why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Conflict, "needle,low", &why)) << why;
  EXPECT_EQ(doc.undoStack()->count(), 3);
  EXPECT_TRUE(doc.isModified());
  settle();
  ASSERT_TRUE(panel.diagram()) << panel.message();
  const CycleDiagram expect = cycleDiagram(doc.kinematics(), doc.design().timing);
  ASSERT_EQ(expect.windows.size(), 2u);
  const AngleInterval n = expect.windows[0].intervals.at(0);
  EXPECT_EQ(panel.diagram()->windows[0].intervals.at(0).fromDeg, n.fromDeg);
  EXPECT_EQ(panel.resultText(EntryKind::Window, 0),
            QString("%1°–%2°").arg(n.fromDeg, 0, 'f', 2).arg(n.toDeg, 0, 'f', 2));
  // The needle below -185 is inside the needle below -180: they overlap where the first holds.
  EXPECT_TRUE(panel.resultText(EntryKind::Conflict, 0).startsWith("overlap 131.59°"))
      << panel.resultText(EntryKind::Conflict, 0);
  EXPECT_EQ(panel.entryList()->topLevelItemCount(), 3);
  // Undo takes the conflict away, redo puts it back; the file keeps them.
  doc.undoStack()->undo();
  settle();
  EXPECT_EQ(panel.entryList()->topLevelItemCount(), 2);
  doc.undoStack()->redo();
  const std::string text = serializeMechanism(doc.design());
  EXPECT_NE(text.find(R"("low=needlebar.N:y<-180")"), std::string::npos) << text;
  // A wrong entry changes nothing and says why.
  EXPECT_FALSE(panel.addEntry(EntryKind::Window, "x=needlebar.Q:y<0", &why));
  EXPECT_TRUE(why.contains("no point \"needlebar.Q\"")) << why;
  EXPECT_FALSE(panel.addEntry(EntryKind::Window, "needle=needlebar.N:y<0", &why));
  EXPECT_TRUE(why.contains("a second window named")) << why;
  EXPECT_EQ(doc.undoStack()->count(), 3);
}

// The pixel rect of a label on the diagram.
QRectF rectOf(const QCPItemText* t) {
  return QRectF(t->topLeft->pixelPosition(), t->bottomRight->pixelPosition()).normalized();
}

// Issue 26: two windows on one row of the cycle diagram printed their names over each other,
// and the list's Result column was cut off at its edge. At the dock's size in the window's
// first layout (1280 x 800: about 880 x 190 px) and in a larger one: the names of windows of one
// row apart, each result whole in its column (wrapped), the rows' labels apart.
TEST_F(CyclePanelTest, WindowsOfOneRowAndTheResultsAreReadWhole) {
  openBare("lockstitch-machine");
  QString why;
  for (const char* w : {"needle_below_plate=needlebar.N:y<-185",
                        "needle_in_hook_zone=needlebar.N:y<-175", "feed=feedbar.T:y>-185"})
    ASSERT_TRUE(panel.addEntry(EntryKind::Window, w, &why)) << why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Row, "takeup.E:y", &why)) << why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Conflict, "needle_below_plate,feed", &why)) << why;
  for (const QSize size : {QSize(880, 190), QSize(1400, 350)}) {
    SCOPED_TRACE(size.width());
    panel.resize(size);
    panel.show();
    settle();
    QTest::qWait(20);  // the list's rows laid out again for its columns
    ASSERT_TRUE(panel.diagram()) << panel.message();
    panel.plotWidget()->replot();
    std::vector<const QCPItemText*> names;
    for (int i = 0; i < panel.plotWidget()->itemCount(); ++i)
      if (auto* t = qobject_cast<QCPItemText*>(panel.plotWidget()->item(i)))
        if (t->text().startsWith("needle_")) names.push_back(t);
    ASSERT_EQ(names.size(), 2u);  // one interval each
    EXPECT_FALSE(rectOf(names[0]).intersects(rectOf(names[1])))
        << names[0]->text() << " over " << names[1]->text();
    // The rows a label's two lines apart, at least.
    const CycleFigure& f = panel.figure();
    for (int r = 0; r + 1 < f.rowCount(); ++r)
      EXPECT_GE(f.pixelAt(0, 0, r + 1).y() - f.pixelAt(0, 0, r).y(), 34) << r;
    // Each result whole: its column within the list, its row as tall as its text wrapped there.
    QTreeWidget* list = panel.entryList();
    const QHeaderView* h = list->header();
    EXPECT_LE(h->sectionViewportPosition(2) + h->sectionSize(2), list->viewport()->width());
    for (int r = 0; r < list->topLevelItemCount(); ++r) {
      QTreeWidgetItem* item = list->topLevelItem(r);
      const QRect cell = list->visualItemRect(item);
      const QRect text = list->fontMetrics().boundingRect(QRect(0, 0, h->sectionSize(2) - 8, 10000),
                                                          Qt::TextWordWrap, item->text(2));
      EXPECT_GE(cell.height(), text.height()) << item->text(2);
    }
    shot(&panel, size.width() < 1000 ? "cycle-panel-880x190" : "cycle-panel-1400x350");
  }
}

TEST_F(CyclePanelTest, TypedInTheLineAndEditedInTheList) {
  openBare("lockstitch-machine");
  showAndSettle();
  panel.kindBox()->setCurrentIndex(0);  // a row
  QTest::keyClicks(panel.entryLine(), "takeup.E:y");
  QTest::keyClick(panel.entryLine(), Qt::Key_Return);
  EXPECT_TRUE(panel.entryLine()->text().isEmpty());
  ASSERT_EQ(doc.design().timing.outputs.size(), 1u);
  QTest::keyClicks(panel.entryLine(), "takeup.Z:y");
  QTest::keyClick(panel.entryLine(), Qt::Key_Return);
  EXPECT_EQ(panel.entryLine()->text(), "takeup.Z:y");  // kept to be corrected
  EXPECT_TRUE(panel.entryError().contains("no point")) << panel.entryError();
  // Edited in the list: a valid text is an undo step; a wrong one goes back and says why.
  QTreeWidgetItem* item = panel.entryList()->topLevelItem(0);
  item->setText(1, "takeup.E:x");
  EXPECT_EQ(doc.design().timing.outputs[0].direction, Vec2(1, 0));
  EXPECT_EQ(doc.undoStack()->count(), 2);
  item = panel.entryList()->topLevelItem(0);
  item->setText(1, "takeup.E:q");
  EXPECT_EQ(panel.entryList()->topLevelItem(0)->text(1), "takeup.E:x");
  EXPECT_TRUE(panel.entryError().contains("\"q\"")) << panel.entryError();
  EXPECT_EQ(doc.undoStack()->count(), 2);
  // Delete in the list takes the entry out, as one undo step.
  panel.entryList()->setCurrentItem(panel.entryList()->topLevelItem(0));
  QTest::keyClick(panel.entryList(), Qt::Key_Delete);
  EXPECT_TRUE(doc.design().timing.outputs.empty());
  EXPECT_EQ(doc.undoStack()->count(), 3);
}

TEST_F(CyclePanelTest, ClearanceFromTheSelectionMarkedAtItsClosestPose) {
  openBare("lockstitch-machine");
  showAndSettle();
  QSignalSpy marks(&panel, &CyclePanel::marksChanged);
  Selection s;
  QString why;
  EXPECT_FALSE(panel.watchSelection(s, &why));
  EXPECT_TRUE(why.contains("Select two points")) << why;
  s.add(*doc.design().findPoint("hook.K"));
  s.add(*doc.design().findPoint("needlebar.N"));
  ASSERT_TRUE(panel.watchSelection(s, &why)) << why;
  settle();
  ASSERT_TRUE(panel.diagram()) << panel.message();
  ASSERT_EQ(panel.clearances().size(), 1u);
  const Mechanism& m = doc.design();
  const Clearance c = findClearance(doc.kinematics(), ClearancePart::of(*m.findPoint("hook.K")),
                                    ClearancePart::of(*m.findPoint("needlebar.N")));
  const Clearance& shown = panel.clearances()[0].clearance;
  EXPECT_EQ(shown.closest.distance, c.closest.distance);
  EXPECT_EQ(shown.closest.crankDeg, c.closest.crankDeg);
  ASSERT_FALSE(marks.isEmpty());
  auto last = marks.back().at(0).value<std::vector<ClearanceMark>>();
  ASSERT_EQ(last.size(), 1u);
  EXPECT_EQ(last[0].a, c.closestPoint);
  EXPECT_EQ(last[0].b, c.closestOther);
  EXPECT_FALSE(last[0].tooClose);
  // A minimum above the closest approach: too close, in the result and on the canvas.
  ASSERT_TRUE(panel.editEntry(EntryKind::Clearance, 0, "hook.K needlebar.N min 5", &why)) << why;
  settle();
  EXPECT_TRUE(panel.resultText(EntryKind::Clearance, 0).contains("under the minimum, 5 mm"))
      << panel.resultText(EntryKind::Clearance, 0);
  last = marks.back().at(0).value<std::vector<ClearanceMark>>();
  ASSERT_EQ(last.size(), 1u);
  EXPECT_TRUE(last[0].tooClose);
  // Hidden, the canvas shows none.
  panel.hide();
  EXPECT_TRUE(marks.back().at(0).value<std::vector<ClearanceMark>>().empty());
}

TEST_F(CyclePanelTest, CursorFollowsTheCrankAndAClickTurnsIt) {
  openBare("lockstitch-machine");
  QString why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Window, "needle=needlebar.N:y<-185", &why)) << why;
  showAndSettle();
  ASSERT_TRUE(panel.diagram());
  ASSERT_TRUE(doc.setCrankDeg(100).ok());
  EXPECT_DOUBLE_EQ(panel.figure().cursor(), 100);
  EXPECT_TRUE(panel.cursorText().startsWith("At 100.00°: needle does not")) << panel.cursorText();
  ASSERT_TRUE(doc.setCrankDeg(180).ok());
  EXPECT_TRUE(panel.cursorText().contains("needle holds")) << panel.cursorText();
  QSignalSpy asked(&panel, &CyclePanel::crankAngleRequested);
  const QPointF at = panel.figure().pixelAt(250, 0.5, 0);
  QTest::mouseClick(panel.plotWidget(), Qt::LeftButton, {}, at.toPoint());
  ASSERT_EQ(asked.size(), 1);
  EXPECT_NEAR(asked[0][0].toDouble(), 250, 1.0);  // a pixel's worth
}

TEST_F(CyclePanelTest, OnlyDeterminedNumbersAndNoWorkWhileHidden) {
  openBare("lockstitch-machine");
  QString why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Window, "needle=needlebar.N:y<-185", &why)) << why;
  EXPECT_EQ(panel.computations(), 0);  // hidden: nothing computed
  showAndSettle();
  EXPECT_EQ(panel.computations(), 1);
  panel.hide();
  ASSERT_TRUE(panel.addEntry(EntryKind::Row, "takeup.E:y", &why)) << why;
  QTest::qWait(60);
  EXPECT_EQ(panel.computations(), 1);
  // A pin taken out: the motion is not determined; a sentence in place of the diagram.
  Mechanism m = doc.design();
  m.remove(m.joints[1].id);
  doc.setDesign(m);
  showAndSettle();
  EXPECT_FALSE(panel.diagram());
  EXPECT_TRUE(panel.message().contains("not determined") || panel.message().contains("not solved"))
      << panel.message();
  EXPECT_TRUE(panel.resultText(EntryKind::Window, 0).isEmpty());
  EXPECT_TRUE(panel.cursorText().isEmpty());
}

TEST_F(CyclePanelTest, ExportsAreTheCommandLinesTableAndAFigure) {
  openBare("lockstitch-machine");
  QString why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Window, "needle=needlebar.N:y<-185", &why)) << why;
  ASSERT_TRUE(panel.addEntry(EntryKind::Clearance, "hook.K needlebar.N", &why)) << why;
  QTemporaryDir dir;
  const QString csv = dir.filePath("t.csv"), svg = dir.filePath("t.svg");
  ASSERT_TRUE(panel.exportTable(csv, &why)) << why;  // computed for it while hidden
  QFile f(csv);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  EXPECT_EQ(f.readAll().toStdString(),
            timingTable(cycleDiagram(doc.kinematics(), doc.design().timing)));
  ASSERT_TRUE(panel.exportFigure(svg, QSize(1200, 400), &why)) << why;
  QFile g(svg);
  ASSERT_TRUE(g.open(QIODevice::ReadOnly));
  const QByteArray text = g.readAll();
  EXPECT_TRUE(text.contains("needlebar.N:y"));
  EXPECT_TRUE(text.contains("closest"));
}

}  // namespace
}  // namespace linkage::ui
