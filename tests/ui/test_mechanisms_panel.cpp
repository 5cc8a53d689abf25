// The Mechanisms dock (issue 18): renaming, colouring and hiding a mechanism are undo steps kept
// in the file; a hidden mechanism is not in the scene; a row selects its bodies. And slot
// travel: a slider-crank whose slot is drawn too short is drawn in the warning colour and the
// design status says by how much, checked against the closed form.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QApplication>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <cmath>

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "elements/gear_item.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "mechanisms.h"
#include "mechanisms/mechanisms_panel.h"
#include "tools/selection.h"
#include "window/main_window.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

struct Machine {
  Document doc;
  Selection selection;
  CanvasScene scene;
  MechanismsPanel panel;
  Machine() {
    QString err;
    EXPECT_TRUE(doc.open(QString::fromStdString(*resolveModel("lockstitch-machine")), &err)) << err;
    scene.setDocument(&doc);
    panel.setDocument(&doc, &selection);
  }
  BodyItem* body(const char* name) { return scene.bodyItem(doc.design().bodyNamed(name)->id); }
  std::vector<SubMechanism> all() const { return subMechanisms(doc.design()); }
};

TEST(MechanismsPanel, ListsEachMechanismWithItsNameAndVisibility) {
  Machine m;
  QTreeWidget* list = m.panel.list();
  ASSERT_EQ(list->topLevelItemCount(), 5);
  EXPECT_EQ(list->topLevelItem(1)->text(0), "rod");
  EXPECT_EQ(list->topLevelItem(1)->text(2), "rod, needlebar");
  EXPECT_EQ(list->topLevelItem(3)->checkState(0), Qt::Checked);
}

TEST(MechanismsPanel, RenameColourAndHideAreUndoableAndSaved) {
  Machine m;
  QUndoStack* undo = m.doc.undoStack();
  m.doc.setCrankDeg(70);
  const PointId needle = *m.doc.design().findPoint("needlebar.N");
  const Vec2 at = m.doc.kinematics().position(needle);
  ASSERT_TRUE(m.panel.rename(1, "needle bar"));
  EXPECT_EQ(m.all()[1].name, "needle bar");
  EXPECT_EQ(m.panel.list()->topLevelItem(1)->text(0), "needle bar");
  ASSERT_TRUE(m.panel.setColour(1, QColor("#1f77b4")));
  EXPECT_EQ(m.body("rod")->colour(), QColor("#1f77b4"));
  EXPECT_EQ(m.body("needlebar")->colour(), QColor("#1f77b4"));
  EXPECT_NE(m.body("takeup")->colour(), QColor("#1f77b4"));
  ASSERT_EQ(m.scene.blockItems().size(), 1u);  // the needle bar's block
  EXPECT_EQ(m.scene.blockItems()[0]->colour(), QColor("#1f77b4"));
  // The feed shaft's belt pulley is the feed mechanism's; the arm shaft's end keeps its own.
  ASSERT_TRUE(m.panel.setColour(4, QColor("#2ca02c")));
  int belts = 0;
  for (JointItem* j : m.scene.jointItems())
    if (auto* g = dynamic_cast<GearItem*>(j); g && g->body(1) == m.body("feedshaft")->id()) {
      ++belts;
      EXPECT_EQ(g->bodyColour(1), QColor("#2ca02c"));
      EXPECT_NE(g->bodyColour(0), QColor("#2ca02c"));
    }
  EXPECT_EQ(belts, 1);
  undo->undo();
  ASSERT_TRUE(m.panel.setHidden(3, true));  // the hook
  EXPECT_EQ(undo->count(), 3);
  EXPECT_FALSE(m.panel.setHidden(3, true));  // nothing to change: no undo step
  EXPECT_EQ(undo->count(), 3);
  // The motion is the same: nothing of the geometry changed.
  ASSERT_TRUE(m.doc.solved());
  EXPECT_NEAR(m.doc.crankDeg(), 70, 1e-9);
  EXPECT_NEAR((m.doc.kinematics().position(needle) - at).norm(), 0,
              1e-9 * m.doc.kinematics().size());

  QTemporaryDir dir;
  const QString path = dir.filePath("machine.linkage.json");
  QString err;
  ASSERT_TRUE(m.doc.save(path, &err)) << err;
  Document again;
  ASSERT_TRUE(again.open(path, &err)) << err;
  const std::vector<SubMechanism> read = subMechanisms(again.design());
  EXPECT_EQ(read[1].name, "needle bar");
  EXPECT_EQ(read[1].colour, "#1f77b4");
  EXPECT_TRUE(read[3].hidden);
  EXPECT_EQ(mechanismDifference(again.design(), m.doc.design()), "");

  undo->undo();
  EXPECT_FALSE(m.all()[3].hidden);
  EXPECT_TRUE(m.body("hook")->isVisible());
  undo->undo();
  EXPECT_EQ(m.all()[1].colour, "");
  EXPECT_NE(m.body("rod")->colour(), QColor("#1f77b4"));
  undo->undo();
  EXPECT_EQ(m.all()[1].name, "rod");
  EXPECT_TRUE(m.doc.design().mechanismEntries.empty());
  undo->redo();
  undo->redo();
  undo->redo();
  EXPECT_EQ(m.all()[1].name, "needle bar");
  EXPECT_EQ(m.all()[1].colour, "#1f77b4");
  EXPECT_TRUE(m.all()[3].hidden);
}

TEST(MechanismsPanel, AHiddenMechanismIsNotInTheScene) {
  Machine m;
  m.scene.setCentresVisible(true);
  m.scene.setTracesVisible(true);
  const Mechanism& d = m.doc.design();
  const int hookNumber = m.body("hook")->number();
  auto centresOfHook = [&] {
    int n = 0;
    for (const Drawing::Centre& c : m.scene.drawing().centres)
      n += (c.i == hookNumber || c.j == hookNumber) && m.scene.centresItem()->isVisible();
    return n;
  };
  ASSERT_GT(centresOfHook(), 0);
  // Through the check box, as a user does (the edit is queued out of the list's signal).
  m.panel.list()->topLevelItem(3)->setCheckState(0, Qt::Unchecked);
  QApplication::processEvents();
  ASSERT_TRUE(m.all()[3].hidden);
  EXPECT_FALSE(m.body("hook")->isVisible());
  EXPECT_TRUE(m.body("needlebar")->isVisible());
  const std::vector<JointId> hookJoints = m.all()[3].joints;
  for (JointItem* j : m.scene.jointItems()) {
    const bool ofHook =
        std::find(hookJoints.begin(), hookJoints.end(), j->joint()) != hookJoints.end();
    EXPECT_EQ(j->isVisible(), !ofHook) << jointLabel(d, j->joint());
  }
  // Nothing of it is drawn: what a paint of the scene shows is what is visible.
  for (QGraphicsItem* i : m.scene.items())
    if (auto* b = dynamic_cast<BodyItem*>(i); b && b->id() == d.bodyNamed("hook")->id)
      EXPECT_FALSE(i->isVisible());
  // Its centres are not among those drawn (the scene keeps the drawing's list whole).
  m.doc.setCrankDeg(40);
  for (const Drawing::Centre& c : m.scene.centresItem()->centres())
    EXPECT_TRUE(c.i != hookNumber && c.j != hookNumber) << c.i << "," << c.j;
  // The hook's output point K has no trace; the needle's has.
  int hookOutputs = 0;
  ASSERT_EQ(m.scene.traceItems().size(), d.outputs.size());
  for (size_t i = 0; i < d.outputs.size(); ++i) {
    const bool ofHook = d.point(d.outputs[i])->body == d.bodyNamed("hook")->id;
    hookOutputs += ofHook;
    EXPECT_EQ(m.scene.traceItems()[i]->path().isEmpty(), ofHook) << i;
    EXPECT_EQ(m.scene.outputItems()[i]->isVisible(), !ofHook) << i;
  }
  EXPECT_EQ(hookOutputs, 1);
}

TEST(MechanismsPanel, ARowSelectsItsBodies) {
  Machine m;
  m.panel.list()->setCurrentItem(m.panel.list()->topLevelItem(2));
  const Mechanism& d = m.doc.design();
  EXPECT_EQ(m.selection.bodies,
            std::vector<BodyId>({d.bodyNamed("takeup")->id, d.bodyNamed("link")->id}));
  EXPECT_TRUE(m.selection.points.empty());
}

// An offset slider-crank (crank r = 20, rod l = 70, offset e = 7) whose slot ends at y = 85:
// the block is highest when crank and rod are in line, at sqrt((l + r)^2 - e^2), on the line
// from the pivot through the block there, so at crank angle atan2(ymax, e) less the drawn 30
// degrees. It runs past the end by ymax - 85.
TEST(SlotTravelWarning, SaysByHowMuchAgainstTheClosedForm) {
  const double r = 20, l = 70, e = 7, end = 85;
  test::SliderCrank s = test::sliderCrank(r, l, e, 30);
  Slot* slot =
      s.m.slotNamed(s.ground, "guide") ? s.m.slot(s.m.slotNamed(s.ground, "guide")->id) : nullptr;
  ASSERT_TRUE(slot);
  slot->p1 = Vec2(e, end);
  MainWindow w;
  w.document()->setContents(s.m, QString(), "short slot");
  const double ymax = std::sqrt((l + r) * (l + r) - e * e);
  double deg = std::atan2(ymax, e) * 180 / M_PI - 30;
  deg -= 360 * std::floor(deg / 360);
  const std::vector<SlotWarning>& warnings = w.scene()->slotWarnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NEAR(warnings[0].byMm, ymax - end, 1e-9 * (ymax - end));
  EXPECT_NEAR(warnings[0].atDeg, deg, 1e-7);
  EXPECT_TRUE(warnings[0].pastEnd);
  const QString text = w.messageStrip()->problem();
  EXPECT_NE(text.indexOf(QStringLiteral("block 'slider.B' leaves slot 'ground.guide' by %1 mm")
                             .arg(ymax - end, 0, 'f', 2)),
            -1)
      << text;
  EXPECT_NE(text.indexOf(QStringLiteral("at crank %1\u00b0").arg(deg, 0, 'f', 1)), -1) << text;
  // The block and its slot in the warning colour.
  int flagged = 0;
  for (BlockItem* b : w.scene()->blockItems()) flagged += b->flagged();
  EXPECT_EQ(flagged, 1);
  EXPECT_TRUE(w.scene()->bodyItem(s.ground)->slotFlagged(slot->id));
  // Fixed (the slot drawn long enough): the warning goes.
  Mechanism fixed = w.document()->design();
  fixed.slot(slot->id)->p1 = Vec2(e, 95);
  commitEdit(w.document(), "longer slot", fixed);
  EXPECT_TRUE(w.scene()->slotWarnings().empty());
  EXPECT_EQ(w.messageStrip()->problem(), "");
  EXPECT_FALSE(w.scene()->bodyItem(s.ground)->slotFlagged(slot->id));
  for (BlockItem* b : w.scene()->blockItems()) EXPECT_FALSE(b->flagged());
}

}  // namespace
}  // namespace linkage::ui
