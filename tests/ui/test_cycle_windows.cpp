// The Cycle dock's windows made by choosing (issue 26): a point chosen from the form's list
// (named as the canvas names it) or picked, the threshold typed in its number field or dragged
// on the diagram, where the window's ends follow the drag live and its release is one undo
// step; the windows made so are the file's, as if typed. The ends are checked against the
// lockstitch needle's closed form (a central slider-crank 16, 45, its point 131 below the pin).
#include <gtest/gtest.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>
#include <cmath>

#include "cycle/cycle_panel.h"
#include "cycle/window_form.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "linkage/timing_text.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

// The crank angles from which the lockstitch needle point is below `level` (to 360 minus it):
// there the rod's pin B is |OB| = -level - 131 below the shaft, and the triangle O, A, B with
// OA 16, AB 45 gives the crank's angle from the top.
double needleBelowFrom(double level) {
  const double d = -level - 131;
  return std::acos((45.0 * 45 - 16 * 16 - d * d) / (2 * 16 * d)) * 180 / M_PI;
}

QString ends(double from, double to) {
  return QString("%1°–%2°").arg(from, 0, 'f', 2).arg(to, 0, 'f', 2);
}

class CycleWindowsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-machine")), nullptr));
    panel.resize(1400, 400);
    panel.show();
    settle();
    ASSERT_TRUE(panel.diagram()) << panel.message();
  }
  void settle() {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    ASSERT_FALSE(panel.redrawPending());
  }
  void typeInto(QWidget* w, const char* text) {
    w->setFocus();
    QTest::keyClick(w, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(w, text);
    QTest::keyClick(w, Qt::Key_Return);
  }
  // A mouse event on the plot as a drag makes it (the left button held).
  void mouse(QEvent::Type type, QPointF at, Qt::MouseButtons held) {
    QWidget* plot = panel.plotWidget();
    QMouseEvent e(type, at, plot->mapToGlobal(at), Qt::LeftButton, held, Qt::NoModifier);
    QApplication::sendEvent(plot, &e);
  }
  const TimingWindow& window(int i) const { return doc.design().timing.windows.at(i); }
  void chooseKind(EntryKind k) {
    panel.kindBox()->setCurrentIndex(panel.kindBox()->findData(static_cast<int>(k)));
  }

  Document doc;
  CyclePanel panel{&doc};
  WindowForm& form = *panel.windowForm();
};

TEST_F(CycleWindowsTest, APointFromTheListAThresholdTypedAndAddedAsOneStep) {
  // The form is there while windows are what the dock adds.
  EXPECT_FALSE(form.isVisible());
  chooseKind(EntryKind::Window);
  EXPECT_TRUE(form.isVisible());
  EXPECT_EQ(form.target(), -1);
  EXPECT_TRUE(form.addButton()->isVisible());
  // The list names points as the canvas does; points that cannot move are not offered.
  EXPECT_GE(form.pointBox()->findText("takeup.E"), 0);
  EXPECT_GE(form.pointBox()->findText("needlebar.N"), 0);
  EXPECT_LT(form.pointBox()->findText("ground.O"), 0);
  EXPECT_LT(form.pointBox()->findText("armshaft.O"), 0);  // pinned to the ground
  // Typed to the list (its keyboard search), as a user chooses.
  form.pointBox()->setFocus();
  QTest::keyClicks(form.pointBox(), "takeup.E");
  ASSERT_EQ(form.pointBox()->currentText(), "takeup.E");
  EXPECT_EQ(form.nameField()->text(), "takeup");  // a name made from the body
  // The threshold is put in the eye's stroke, where the window holds part of the cycle.
  const Mechanism& m = doc.design();
  const LimitMeasure eyeY = LimitMeasure::along(*m.findPoint("takeup.E"), Vec2(0, 1));
  const CycleDiagram alone = cycleDiagram(doc.kinematics(), {{"takeup.E:y", eyeY}}, {}, {});
  ASSERT_EQ(alone.rows.size(), 1u);
  EXPECT_GT(form.level(), alone.rows[0].min);
  EXPECT_LT(form.level(), alone.rows[0].max);
  EXPECT_NEAR(form.level(), (alone.rows[0].min + alone.rows[0].max) / 2, 0.005);
  form.compareBox()->setFocus();
  QTest::keyClicks(form.compareBox(), "a");  // above
  typeInto(form.levelField(), "78");
  typeInto(form.nameField(), "eye");  // Return in the name adds it
  EXPECT_EQ(doc.undoStack()->count(), 1);
  shot(&panel, "cycle-window-added");
  ASSERT_EQ(doc.design().timing.windows.size(), 4u);
  EXPECT_EQ(windowText(doc.design(), window(3)), "eye=takeup.E:y>78");
  // The window added is the one the form edits, chosen in the list.
  EXPECT_EQ(form.target(), 3);
  EXPECT_TRUE(form.newButton()->isVisible());
  ASSERT_TRUE(panel.entryList()->currentItem());
  EXPECT_EQ(panel.entryList()->currentItem()->text(1), "eye=takeup.E:y>78");
  settle();
  std::string why;
  const CycleDiagram typed = cycleDiagram(
      doc.kinematics(), {}, {*parseWindow(doc.design(), "eye=takeup.E:y>78", &why)}, {});
  ASSERT_EQ(typed.windows[0].intervals.size(), 1u);
  const AngleInterval e = typed.windows[0].intervals[0];
  EXPECT_EQ(panel.resultText(EntryKind::Window, 3), ends(e.fromDeg, e.toDeg));
  EXPECT_EQ(form.resultText(), ends(e.fromDeg, e.toDeg));
  // The file keeps it as typed.
  EXPECT_NE(serializeMechanism(doc.design()).find(R"("eye=takeup.E:y>78")"), std::string::npos);
  // Undo takes it away; the form keeps its fields as a new window.
  doc.undoStack()->undo();
  EXPECT_EQ(doc.design().timing.windows.size(), 3u);
  EXPECT_EQ(form.target(), -1);
  EXPECT_EQ(form.pointBox()->currentText(), "takeup.E");
}

TEST_F(CycleWindowsTest, AThresholdTypedEditsTheWindowChosenInTheList) {
  panel.entryList()->setCurrentItem(panel.entryList()->topLevelItem(0));
  ASSERT_EQ(form.target(), 0);
  EXPECT_EQ(form.pointBox()->currentText(), "needlebar.N");
  EXPECT_EQ(form.axisBox()->currentText(), "y");
  EXPECT_EQ(form.compareBox()->currentText(), "below");
  EXPECT_EQ(form.level(), -185);
  typeInto(form.levelField(), "-180");
  EXPECT_EQ(doc.undoStack()->count(), 1);
  EXPECT_EQ(window(0).level, -180);
  settle();
  const double a = needleBelowFrom(-180);
  EXPECT_EQ(panel.resultText(EntryKind::Window, 0), ends(a, 360 - a));
  EXPECT_EQ(form.resultText(), ends(a, 360 - a));
  // Above in place of below: another step; the conflict with the feed dog now overlaps.
  form.compareBox()->setFocus();
  QTest::keyClicks(form.compareBox(), "a");
  EXPECT_EQ(doc.undoStack()->count(), 2);
  EXPECT_FALSE(window(0).below);
  doc.undoStack()->undo();
  doc.undoStack()->undo();
  EXPECT_EQ(window(0).level, -185);
  EXPECT_TRUE(window(0).below);
  EXPECT_EQ(form.level(), -185);  // the form follows the undo
  EXPECT_EQ(form.compareBox()->currentText(), "below");
  // A name another window has is refused, and said so; nothing changes.
  typeInto(form.nameField(), "feed");
  EXPECT_EQ(doc.undoStack()->count(), 2);
  EXPECT_EQ(doc.undoStack()->index(), 0);
  EXPECT_TRUE(panel.entryError().contains("a second window named")) << panel.entryError();
  EXPECT_EQ(form.nameField()->text(), "needle");
}

TEST_F(CycleWindowsTest, DraggingTheThresholdMovesTheEndsLiveAndOneUndoRestores) {
  const QString before = panel.resultText(EntryKind::Window, 0);
  const double a0 = needleBelowFrom(-185);
  ASSERT_EQ(before, ends(a0, 360 - a0));
  const std::optional<QPointF> on = panel.levelPixel(0, 300);
  ASSERT_TRUE(on);
  // Pressed on the needle's threshold line, dragged down (a lower level), not released yet.
  mouse(QEvent::MouseButtonPress, *on, Qt::LeftButton);
  EXPECT_EQ(form.target(), 0);  // the window grabbed is the one the form shows
  // ... but not shown for it: the diagram does not move under the mouse.
  EXPECT_FALSE(form.isVisible());
  // (8 pixels: the needle's row of the shipped machine, with its clearance's row under the
  // others, is about 50 pixels for its 32 mm stroke.)
  for (int dy = 2; dy <= 8; dy += 2) mouse(QEvent::MouseMove, *on + QPointF(0, dy), Qt::LeftButton);
  settle();
  const double level = form.level();
  EXPECT_LT(level, -185);
  EXPECT_GT(level, -192);                           // still in the needle's stroke
  EXPECT_EQ(level, std::round(level * 100) / 100);  // in hundredths of a millimetre
  const double a = needleBelowFrom(level);
  // The ends follow the line before the release; the document is not changed yet.
  EXPECT_EQ(panel.resultText(EntryKind::Window, 0), ends(a, 360 - a));
  EXPECT_EQ(panel.entryList()->topLevelItem(0)->text(1),
            QString("needle=needlebar.N:y<%1").arg(QString::fromStdString(shortestText(level))));
  EXPECT_EQ(doc.undoStack()->count(), 0);
  EXPECT_EQ(window(0).level, -185);
  shot(&panel, "cycle-threshold-dragged");
  // The release makes it one undo step.
  mouse(QEvent::MouseButtonRelease, *on + QPointF(0, 8), Qt::NoButton);
  EXPECT_EQ(doc.undoStack()->count(), 1);
  EXPECT_EQ(window(0).level, level);
  settle();
  EXPECT_EQ(panel.resultText(EntryKind::Window, 0), ends(a, 360 - a));
  // The line is drawn where the level is now.
  const std::optional<QPointF> moved = panel.levelPixel(0, 300);
  ASSERT_TRUE(moved);
  EXPECT_NEAR(moved->y(), on->y() + 8, 1.0);
  doc.undoStack()->undo();
  EXPECT_EQ(window(0).level, -185);
  settle();
  EXPECT_EQ(panel.resultText(EntryKind::Window, 0), before);
  EXPECT_EQ(form.level(), -185);
  // A press away from every line turns the crank as before.
  QSignalSpy asked(&panel, &CyclePanel::crankAngleRequested);
  mouse(QEvent::MouseButtonPress, panel.figure().pixelAt(100, 0.5, 0), Qt::LeftButton);
  mouse(QEvent::MouseButtonRelease, panel.figure().pixelAt(100, 0.5, 0), Qt::NoButton);
  EXPECT_EQ(asked.size(), 1);
  EXPECT_EQ(doc.undoStack()->index(), 0);
}

TEST_F(CycleWindowsTest, APointPickedIsChosenAndItsOutputsStrokeTakesTheThreshold) {
  chooseKind(EntryKind::Window);
  QSignalSpy asked(&panel, &CyclePanel::pickPointRequested);
  QTest::mouseClick(form.pickButton(), Qt::LeftButton);
  ASSERT_EQ(asked.size(), 1);
  EXPECT_TRUE(asked[0][0].toBool());
  // The canvas answers with the point clicked (window/cycle_feature.cpp; tests/x11 clicks it).
  panel.pointPicked(*doc.design().findPoint("hook.K"));
  EXPECT_FALSE(form.pickButton()->isChecked());
  EXPECT_EQ(form.pointBox()->currentText(), "hook.K");
  EXPECT_TRUE(form.axisBox()->hasFocus() || !panel.isActiveWindow());
  // The hook point's y runs from -215 to -185: its threshold is put at mid-stroke, -200.
  EXPECT_EQ(form.level(), -200);
  EXPECT_EQ(form.nameField()->text(), "hook2");  // "hook" is taken
  // Its crank angles before it is added: the hook point below its shaft (angle 180 to 360).
  const double a0 = std::atan2(9.0, 12.0) * 180 / M_PI;
  EXPECT_EQ(form.resultText(), ends((180 - a0) / 2, (360 - a0) / 2) + "; " +
                                   ends((180 - a0) / 2 + 180, (360 - a0) / 2 + 180));
  EXPECT_EQ(doc.undoStack()->count(), 0);
}

// Another file opened: the form shows nothing of the last one (a point of the same name is
// not carried over to a machine that merely has one).
TEST_F(CycleWindowsTest, AnotherFileLeavesNothingOfTheLastInTheForm) {
  panel.entryList()->setCurrentItem(panel.entryList()->topLevelItem(0));
  ASSERT_EQ(form.target(), 0);
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-arm-shaft")), nullptr));
  EXPECT_EQ(form.target(), -1);
  EXPECT_EQ(form.pointBox()->currentIndex(), -1);
  EXPECT_TRUE(form.nameField()->text().isEmpty());
  EXPECT_GE(form.pointBox()->findText("hook.K"), 0);
  EXPECT_LT(form.pointBox()->findText("feedbar.T"), 0);  // the machine's, not the arm shaft's
}

}  // namespace
}  // namespace linkage::ui
