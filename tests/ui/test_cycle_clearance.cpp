// What the Cycle dock says a clearance measured (issue 26, item 7): the part named (a point, the
// segment between two points of a body, a slot), and what was found in words, never a bare
// "0 mm": where the hook point meets the needle (the segment from its point N to the bar's pin
// B), where a needle point runs along its guide slot, where the hook point touches the plate;
// the diagram's row and the canvas mark say the same, the mark with the needle where it is
// then. Analysis > Watch Clearance (Shift+W) takes a point and two points of another body as the
// point to the segment between them. The numbers are the lockstitch machine's closed forms:
// needle N_y = 16 cos t - sqrt(45^2 - (16 sin t)^2) - 131, hook point K at radius 15 about
// (0, -200) from atan2(9, 12), turning twice as fast.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>
#include <cmath>

#include "canvas/canvas_view.h"
#include "cycle/cycle_panel.h"
#include "document/document.h"
#include "drawing.h"
#include "figures/qcp.h"
#include "linkage/io/model_lookup.h"
#include "tools/selection.h"
#include "ui_test.h"
#include "window/cycle_feature.h"
#include "window/features.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

double needleY(double crankDeg) {
  const double t = crankDeg * M_PI / 180, s = 16 * std::sin(t);
  return 16 * std::cos(t) - std::sqrt(45 * 45 - s * s) - 131;
}

// Where K is over the needle's line at the top of its circle (0, -185): K's angle 90 degrees,
// a0 + 2 t = 90 (and the turn after, 180 degrees of crank later).
double hookOverTheNeedle(int turn) {
  return (90 - std::atan2(9.0, 12.0) * 180 / M_PI) / 2 + 180 * turn;
}

QString f2(double v) {
  return QString::number(v, 'f', 2);
}

class CycleClearanceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-machine")), nullptr));
    Mechanism m = doc.design();
    m.timing = {};  // entries made here
    doc.setContents(m, doc.filePath());
    panel.resize(1400, 350);
    panel.show();
  }
  void settle() {
    QTest::qWait(40);
    QElapsedTimer t;
    t.start();
    while (panel.redrawPending() && t.elapsed() < 10000) QTest::qWait(5);
    ASSERT_FALSE(panel.redrawPending());
  }
  QString add(const char* entry) {
    QString why;
    EXPECT_TRUE(panel.addEntry(EntryKind::Clearance, entry, &why)) << why;
    settle();
    return panel.resultText(EntryKind::Clearance, 0);
  }
  QTreeWidgetItem* clearanceItem() const {
    QTreeWidget* l = panel.entryList();
    return l->topLevelItem(l->topLevelItemCount() - 1);
  }
  // The texts drawn on the diagram.
  QStringList plotTexts() const {
    QStringList out;
    for (int i = 0; i < panel.plotWidget()->itemCount(); ++i)
      if (auto* t = qobject_cast<QCPItemText*>(panel.plotWidget()->item(i))) out << t->text();
    return out;
  }
  Document doc;
  CyclePanel panel{&doc};
};

TEST_F(CycleClearanceTest, TheSegmentSaysWhereTheHookPointMeetsTheNeedle) {
  QSignalSpy marks(&panel, &CyclePanel::marksChanged);
  const QString result = add("hook.K needlebar.N-B");
  const double meet = hookOverTheNeedle(1);
  const QString figures = QString("0 mm, meets it at %1°, %2 mm from needlebar.N")
                              .arg(f2(meet), f2(-185 - needleY(meet)));
  EXPECT_EQ(result, "segment needlebar.N-B: " + figures);
  EXPECT_EQ(f2(-185 - needleY(meet)), "4.74");  // above the needle's point: the loop's place
  // Hovered: what is measured, and every crossing of the needle's line (K is 23.88 mm below
  // the needle's point on its idle turn, when the needle is high).
  EXPECT_TRUE(clearanceItem()->toolTip(1).contains(
      "From the point hook.K to the segment needlebar.N-B as drawn"))
      << clearanceItem()->toolTip(1);
  const double idle = hookOverTheNeedle(0);
  EXPECT_TRUE(clearanceItem()->toolTip(2).contains(
      QString("crosses its line at %1°, %2 mm beyond needlebar.N")
          .arg(f2(idle), f2(needleY(idle) + 185))))
      << clearanceItem()->toolTip(2);
  // The diagram's row and its note; the cursor line names the segment too.
  const CycleFigure& fig = panel.figure();
  EXPECT_TRUE(fig.rowLabel(fig.rowCount() - 1).startsWith("hook.K – segment needlebar.N-B"))
      << fig.rowLabel(fig.rowCount() - 1);
  EXPECT_TRUE(plotTexts().contains(QString("meets it at %1°").arg(meet, 0, 'f', 1)))
      << plotTexts().join(" | ");
  EXPECT_TRUE(panel.cursorText().contains("hook.K – segment needlebar.N-B")) << panel.cursorText();
  // On the canvas: where they meet, on the needle as it is then (its point 4.74 mm below).
  ASSERT_FALSE(marks.isEmpty());
  const auto last = marks.back().at(0).value<std::vector<ClearanceMark>>();
  ASSERT_EQ(last.size(), 1u);
  EXPECT_EQ(last[0].text, QString("hook.K – segment needlebar.N-B: meets it at %1°").arg(f2(meet)));
  EXPECT_NEAR((last[0].a - Vec2(0, -185)).norm(), 0, 1e-9);
  EXPECT_NEAR((last[0].b - Vec2(0, -185)).norm(), 0, 1e-9);
  ASSERT_EQ(last[0].part.size(), 2u);
  EXPECT_NEAR((last[0].part[0] - Vec2(0, needleY(meet))).norm(), 0, 1e-9);
  EXPECT_NEAR((last[0].part[1] - Vec2(0, needleY(meet) + 131)).norm(), 0, 1e-9);
}

// To the needle's point alone: the closest approach, and the result says it is to a point.
TEST_F(CycleClearanceTest, ThePointSaysItIsAPoint) {
  const QString result = add("hook.K needlebar.N");
  EXPECT_TRUE(result.startsWith("point needlebar.N: closest 4.411 mm at 210.25°")) << result;
  EXPECT_TRUE(clearanceItem()->toolTip(1).contains("name the segment: body.P-Q"))
      << clearanceItem()->toolTip(1);
  EXPECT_TRUE(
      panel.figure().rowLabel(panel.figure().rowCount() - 1).startsWith("hook.K – needlebar.N\n"));
}

// The needle point runs along its guide (x = 0, y from -20 to -170): on it while N_y >= -170,
// from 360 - a to a through 0, N_y(a) = -170 (bisected here).
TEST_F(CycleClearanceTest, ANeedlePointInItsGuideRunsAlongIt) {
  const QString result = add("needlebar.N ground.needle");
  double lo = 0, hi = 180;  // N_y falls from -160 to -192
  for (int i = 0; i < 100; ++i) (needleY((lo + hi) / 2) > -170 ? lo : hi) = (lo + hi) / 2;
  const double a = (lo + hi) / 2;
  EXPECT_EQ(result, QString("slot ground.needle: runs along its line, on it (0 mm) %1°–%2°")
                        .arg(f2(360 - a), f2(a)));
  EXPECT_TRUE(
      plotTexts().contains(QString("on it %1°–%2°").arg(360 - a, 0, 'f', 1).arg(a, 0, 'f', 1)))
      << plotTexts().join(" | ");
  for (const QString& t : plotTexts()) EXPECT_FALSE(t.contains("closest 0 mm")) << t;
}

// The top of K's circle is the plate's line y = -185: K touches it there, crossing no line.
TEST_F(CycleClearanceTest, TheHookPointTouchesThePlate) {
  const QString result = add("hook.K ground.plate");
  EXPECT_EQ(result, QString("slot ground.plate: 0 mm, meets it at %1°; at %2°")
                        .arg(f2(hookOverTheNeedle(0)), f2(hookOverTheNeedle(1))));
  EXPECT_TRUE(clearanceItem()->toolTip(2).contains(
      QString("touches it at %1°").arg(f2(hookOverTheNeedle(0)))))
      << clearanceItem()->toolTip(2);
}

JointId pinOf(const Mechanism& m, const char* a, const char* b) {
  const PointId pa = *m.findPoint(a), pb = *m.findPoint(b);
  for (const Joint& j : m.joints)
    if ((j.a == pa && j.b == pb) || (j.a == pb && j.b == pa)) return j.id;
  return {};
}

// Shift+W on a point and two points of another body: the point to the segment between them,
// from the first selected; the needle bar's top B is its rod's pin, which a click selects.
TEST(WatchClearance, APointAndTwoPointsOfAnotherBodyAreThePointAndTheSegment) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "lockstitch-machine"));
  Document* doc = w.document();
  Mechanism bare = doc->design();
  bare.timing.clearances.clear();
  doc->setContents(bare, doc->filePath());
  QAction* watch = w.findChild<QAction*>("watchClearance");
  ASSERT_TRUE(watch);
  EXPECT_TRUE(watch->statusTip().contains("a point and two points of another body"))
      << watch->statusTip();
  const Mechanism& m = doc->design();
  const PointId K = *m.findPoint("hook.K"), N = *m.findPoint("needlebar.N"),
                B = *m.findPoint("needlebar.B");
  const JointId pinB = pinOf(m, "rod.B", "needlebar.B");
  ASSERT_TRUE(pinB);
  Selection& s = *w.tools().selection();
  const ClearanceWatch want{K, ClearancePart::segment(N, B), std::nullopt};
  auto shiftW = [&] {
    w.canvas()->setFocus();
    QTest::keyClick(w.canvas(), Qt::Key_W, Qt::ShiftModifier);
    QApplication::processEvents();
  };
  // The hook point, the needle's point, the pin at the bar's top; then three points in
  // another order.
  s.add(K);
  s.add(N);
  s.add(pinB);
  shiftW();
  ASSERT_EQ(doc->design().timing.clearances.size(), 1u) << w.messageStrip()->message();
  EXPECT_EQ(doc->design().timing.clearances[0], want);
  EXPECT_TRUE(w.cycle().dock->isVisible());
  const QTreeWidget* list = w.cycle().panel()->entryList();
  EXPECT_EQ(list->topLevelItem(list->topLevelItemCount() - 1)->text(1), "hook.K needlebar.N-B");
  doc->undoStack()->undo();
  s.clear();
  s.add(N);
  s.add(K);
  s.add(B);
  shiftW();
  ASSERT_EQ(doc->design().timing.clearances.size(), 1u) << w.messageStrip()->message();
  EXPECT_EQ(doc->design().timing.clearances[0], want);
  doc->undoStack()->undo();
  // Three bodies: no segment; the message says what to select.
  const int steps = doc->undoStack()->count();
  s.clear();
  s.add(K);
  s.add(N);
  s.add(*m.findPoint("takeup.E"));
  shiftW();
  EXPECT_TRUE(doc->design().timing.clearances.empty());
  EXPECT_EQ(doc->undoStack()->count(), steps);
  EXPECT_TRUE(w.messageStrip()->message().contains("a point and two points of one other body"))
      << w.messageStrip()->message();
}

}  // namespace
}  // namespace linkage::ui
