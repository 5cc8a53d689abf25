// The Cam dock (issue 28, "Design from the motion"): the programme typed in its table and its
// segments' ends dragged on its plots, each one undo step that cuts the cam again and moves
// the machine; the base found for a pressure-angle limit and the roller for no undercut, each
// checked against the exact checks one step either side; the cursor at the cam's angle.
#include <gtest/gtest.h>

#include <QDoubleSpinBox>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

#include "cam/cam_figure.h"
#include "cam/cam_panel.h"
#include "cam/cam_table.h"
#include "document/document.h"
#include "figures/qcp.h"
#include "linkage/cam_checks.h"
#include "linkage/cam_edits.h"
#include "linkage/cam_joint.h"
#include "linkage/io/model_lookup.h"
#include "ui_test.h"

namespace linkage::ui {
namespace {

class CamPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("cam-translating-roller")), nullptr));
    panel.resize(1200, 420);
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
  CamJoint cam() const {
    std::string why;
    const std::optional<CamJoint> c =
        camJoint(doc.design(), *doc.design().joint(panel.camShown()), &why);
    EXPECT_TRUE(c) << why;
    return c ? *c : CamJoint{};
  }
  cam::CamChecks checksWith(double base, double roller) const {
    Mechanism m = doc.design();
    std::string why;
    EXPECT_TRUE(setCamRoller(m, panel.camShown(), roller, &why)) << why;
    EXPECT_TRUE(setCamBase(m, panel.camShown(), base, &why)) << why;
    return cam::camChecks(cam::geometryOf(*camJoint(m, *m.joint(panel.camShown()))));
  }
  double followerY() const {
    return doc.kinematics().position(*doc.design().findPoint("follower.R")).y();
  }
  Document doc;
  CamPanel panel{&doc};
};

TEST_F(CamPanelTest, ARiseTypedIsOneUndoStepThatMovesTheMachine) {
  QTableWidget* t = panel.table()->table();
  ASSERT_EQ(t->rowCount(), 4);
  EXPECT_EQ(t->item(0, 3)->text(), "8");
  const int steps = doc.undoStack()->count();
  const double drawn = doc.design().point(*doc.design().findPoint("follower.R"))->pos.y();
  t->item(0, 3)->setText("9");
  settle();
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  // The fall that follows takes the difference: the programme stays closed.
  EXPECT_EQ(cam().program.segments()[0].rise, 9);
  EXPECT_EQ(cam().program.segments()[2].rise, -9);
  EXPECT_EQ(t->item(2, 3)->text(), "-9");
  doc.setCrankDeg(100);
  EXPECT_NEAR(followerY() - drawn, 9, 1e-9);
  doc.undoStack()->undo();
  settle();
  EXPECT_EQ(cam().program.segments()[0].rise, 8);
  EXPECT_EQ(t->item(0, 3)->text(), "8");
}

TEST_F(CamPanelTest, WhatIsNotAProgrammeIsRefusedWithItsReason) {
  QTableWidget* t = panel.table()->table();
  const int steps = doc.undoStack()->count();
  t->item(0, 1)->setText("abc");
  settle();
  EXPECT_EQ(doc.undoStack()->count(), steps);
  EXPECT_EQ(t->item(0, 1)->text(), "100");
  // The first end past the second's: the programme's own message, naming the segment.
  t->item(0, 1)->setText("170");
  settle();
  EXPECT_TRUE(panel.findChild<QLabel*>("camMessage")->text().contains("motion[1].to_deg"));
  EXPECT_EQ(doc.undoStack()->count(), steps);
  EXPECT_EQ(t->item(0, 1)->text(), "100");
  EXPECT_EQ(cam().program.segments()[0].toDeg, 100);
}

TEST_F(CamPanelTest, TheBaseFoundIsTheSmallestWithinTheLimit) {
  auto* limit = panel.findChild<QDoubleSpinBox*>("camLimit");
  ASSERT_TRUE(limit);
  EXPECT_EQ(limit->value(), 30);  // a translating follower's custom limit
  limit->setValue(15);            // below today's 20.3 degrees: a larger base is needed
  settle();
  const int steps = doc.undoStack()->count();
  QString why;
  ASSERT_TRUE(panel.findBase(&why)) << why;
  settle();
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  ASSERT_TRUE(doc.solved()) << doc.solveStatus().message;
  const CamJoint c = cam();
  const double base = c.kind.base;
  // Rounded up to 0.01 mm: within the limit, and 0.01 mm less is not.
  EXPECT_NEAR(base * 100, std::round(base * 100), 1e-6);
  EXPECT_LE(checksWith(base, c.kind.roller).pressureMax.value, 15);
  EXPECT_GT(checksWith(base - 0.01, c.kind.roller).pressureMax.value, 15);
  EXPECT_EQ(panel.findChild<QDoubleSpinBox*>("camBase")->value(), base);
}

TEST_F(CamPanelTest, TheRollerFoundIsTheLargestThatDoesNotUndercut) {
  const CamJoint before = cam();
  const double pitch = before.kind.base + before.kind.roller;
  QString why;
  ASSERT_TRUE(panel.findRoller(&why)) << why;
  settle();
  const CamJoint c = cam();
  EXPECT_NEAR(c.kind.base + c.kind.roller, pitch, 1e-12);  // the pitch curve kept
  EXPECT_FALSE(checksWith(c.kind.base, c.kind.roller).undercut);
  EXPECT_TRUE(checksWith(c.kind.base - 0.02, c.kind.roller + 0.02).undercut);
  EXPECT_TRUE(panel.checksText().contains("No undercut")) << panel.checksText();
}

TEST_F(CamPanelTest, ASegmentsEndDraggedIsOneUndoStep) {
  CamFigure* f = panel.figure();
  ASSERT_EQ(f->rects(), 5);
  ASSERT_EQ(f->ends(), (std::vector<double>{100, 160, 280}));
  QWidget* plot = f->plot();
  const QPoint from = f->pixelAt(1, 100, 0).toPoint(), to = f->pixelAt(1, 120, 0).toPoint();
  ASSERT_EQ(f->endNear(from), 0);
  const int steps = doc.undoStack()->count();
  QTest::mousePress(plot, Qt::LeftButton, {}, from);
  QTest::mouseMove(plot, (from + to) / 2);
  settle();
  EXPECT_EQ(doc.undoStack()->count(), steps);  // live: the machine follows, no step yet
  EXPECT_GT(cam().program.segments()[0].toDeg, 100);
  QTest::mouseMove(plot, to);
  QTest::mouseRelease(plot, Qt::LeftButton, {}, to);
  settle();
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  EXPECT_NEAR(cam().program.segments()[0].toDeg, 120, 0.5);
  EXPECT_EQ(f->ends()[0], cam().program.segments()[0].toDeg);
  doc.undoStack()->undo();
  settle();
  EXPECT_EQ(cam().program.segments()[0].toDeg, 100);
}

TEST_F(CamPanelTest, TheCursorIsAtTheCamsAngle) {
  doc.setCrankDeg(75);
  settle();
  EXPECT_NEAR(panel.figure()->cursor(), 75, 1e-9);  // the cam is the crank, counter-clockwise
}

TEST_F(CamPanelTest, TheChecksAreMarkedOnTheCamWhereTheyOccur) {
  // Turned to each extreme's cam angle, the mark is where the roller touches the cam: a
  // roller's radius from its centre, whatever the pose was when the marks were made.
  const CamJoint c = cam();
  const cam::CamChecks checks = cam::camChecks(cam::geometryOf(c));
  for (const cam::CamExtreme* e : {&checks.pressureMax, &checks.pitchRadiusMin}) {
    ASSERT_TRUE(e->found);
    doc.setCrankDeg(e->atDeg);  // the cam is the crank, counter-clockwise
    settle();
    ASSERT_EQ(panel.marks().size(), 2u);
    const ClearanceMark& m = panel.marks()[e == &checks.pressureMax ? 0 : 1];
    EXPECT_NEAR((doc.kinematics().position(*doc.design().findPoint("follower.R")) - m.a).norm(),
                c.kind.roller, 1e-9)
        << m.text;
    EXPECT_FALSE(m.tooClose) << m.text;
  }
  // Under a limit below the largest angle, its mark is a warning.
  panel.findChild<QDoubleSpinBox*>("camLimit")->setValue(10);
  settle();
  EXPECT_TRUE(panel.marks()[0].tooClose);
  EXPECT_TRUE(panel.marks()[0].text.startsWith("largest pressure angle")) << panel.marks()[0].text;
}

TEST(CamPanel, AMechanismWithoutACamSaysHowToMakeOne) {
  Document doc;
  ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("four-bar-crank-rocker")), nullptr));
  CamPanel panel(&doc);
  panel.resize(900, 400);
  panel.show();
  QTest::qWait(60);
  EXPECT_EQ(panel.figure()->rects(), 0);
  EXPECT_FALSE(panel.camShown());
}

TEST(CamTable, ARiseTypedIsTakenByTheNextFall) {
  std::vector<cam::Segment> s = {
      {90, 10, cam::Law::Cycloidal}, {180, 0, {}}, {270, -10, cam::Law::Harmonic}, {360, 0, {}}};
  ASSERT_TRUE(CamTable::withRise(s, 0, 12));
  EXPECT_EQ(s[2].rise, -12);
  ASSERT_TRUE(CamTable::withRise(s, 2, -5));  // the rise before it, round the turn
  EXPECT_EQ(s[0].rise, 5);
  const std::vector<cam::Segment> halves = CamTable::split(s, 0);
  ASSERT_EQ(halves.size(), 5u);
  EXPECT_EQ(halves[0].toDeg, 45);
  EXPECT_EQ(halves[0].rise + halves[1].rise, 5);
  EXPECT_EQ(CamTable::joined(halves, 1), s);
}

}  // namespace
}  // namespace linkage::ui
