// The docks' panel base (docks/dock_panel.h): a stale panel computes only while seen, a burst
// of edits computes once, a panel that rests behind a tab computes when its tab comes in front,
// and one that works behind a tab goes on computing.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QMainWindow>
#include <QTest>

#include "docks/dock_panel.h"

namespace linkage::ui {
namespace {

// Counts what the base asks of it.
class CountingPanel : public DockPanel {
 public:
  CountingPanel(Redraw redraw, Behind behind) : DockPanel(redraw, behind) {}
  void edit() { markStale(); }
  int computed = 0, cameIn = 0, left = 0;

 private:
  void compute() override { ++computed; }
  void cameIntoView() override { ++cameIn; }
  void leftView() override { ++left; }
};

void settle() {
  for (int i = 0; i < 4; ++i) QApplication::processEvents();
}

void waitForRedraw(const DockPanel& p) {
  QElapsedTimer t;
  t.start();
  while (p.redrawPending() && t.elapsed() < 5000) QTest::qWait(5);
  ASSERT_FALSE(p.redrawPending());
}

TEST(DockPanel, HiddenComputesNothingAndComputesOnceWhenShown) {
  CountingPanel p(DockPanel::Redraw::Now, DockPanel::Behind::Works);
  for (int i = 0; i < 3; ++i) p.edit();
  EXPECT_EQ(p.computed, 0);
  p.show();
  EXPECT_EQ(p.computed, 1);
  EXPECT_EQ(p.cameIn, 1);
  p.edit();  // seen: at once
  EXPECT_EQ(p.computed, 2);
  p.hide();
  EXPECT_EQ(p.left, 1);
  p.edit();
  p.edit();
  EXPECT_EQ(p.computed, 2);
  p.show();  // stale: once
  EXPECT_EQ(p.computed, 3);
  p.hide();
  p.show();  // nothing changed meanwhile: nothing computed
  EXPECT_EQ(p.computed, 3);
}

TEST(DockPanel, ABurstOfEditsComputesOnce) {
  for (auto redraw : {DockPanel::Redraw::NextTurn, DockPanel::Redraw::Throttled}) {
    CountingPanel p(redraw, DockPanel::Behind::Works);
    p.show();
    ASSERT_EQ(p.computed, 1);
    for (int i = 0; i < 100; ++i) p.edit();
    EXPECT_EQ(p.computed, 1);  // later, not at each edit
    EXPECT_TRUE(p.redrawPending());
    waitForRedraw(p);
    EXPECT_EQ(p.computed, 2);
    // Hidden before the throttle's turn: done when shown again.
    p.edit();
    p.hide();
    QTest::qWait(60);
    EXPECT_EQ(p.computed, 2);
    p.show();
    EXPECT_EQ(p.computed, 3);
  }
}

TEST(DockPanel, ARestingPanelBehindATabComputesWhenItsTabComesInFront) {
  QMainWindow w;
  w.setCentralWidget(new QWidget);
  auto* resting = new CountingPanel(DockPanel::Redraw::Now, DockPanel::Behind::Rests);
  auto* working = new CountingPanel(DockPanel::Redraw::Now, DockPanel::Behind::Works);
  auto* a = new QDockWidget("resting", &w);
  auto* b = new QDockWidget("working", &w);
  a->setObjectName("resting");
  b->setObjectName("working");
  a->setWidget(resting);
  b->setWidget(working);
  w.addDockWidget(Qt::RightDockWidgetArea, a);
  w.tabifyDockWidget(a, b);
  w.resize(800, 600);
  w.show();
  b->raise();
  settle();
  // The resting panel is "visible" behind the tab, but not seen.
  ASSERT_TRUE(resting->isVisible());
  EXPECT_FALSE(resting->shown());
  EXPECT_TRUE(working->shown());
  const int restingBefore = resting->computed, workingBefore = working->computed;
  resting->edit();
  working->edit();
  EXPECT_EQ(resting->computed, restingBefore);
  EXPECT_EQ(working->computed, workingBefore + 1);
  // In front: computed once, and the other, behind, works on.
  a->raise();
  settle();
  EXPECT_TRUE(resting->shown());
  EXPECT_EQ(resting->computed, restingBefore + 1);
  working->edit();
  EXPECT_EQ(working->computed, workingBefore + 2);
  // Behind again: told it left the view.
  const int left = resting->left;
  b->raise();
  settle();
  EXPECT_FALSE(resting->shown());
  EXPECT_GT(resting->left, left);
}

}  // namespace
}  // namespace linkage::ui
