// The gear and the arc slot in the editor, with mouse and key events: the Gear tool (E) couples
// two pivoted bodies (Shift: a belt), the ratio is typed in the panel (0 refused), "Couple
// to..." starts the tool from a body; the Slot tool draws an arc with Shift and a third click,
// whose centre and radius are typed in the panel; each is one undo step; the canvas draws them.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QApplication>
#include <QComboBox>
#include <QMenu>
#include <QTest>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "canvas/gear_item.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/elements.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

void type(MainWindow& w, const QString& label, const QString& text) {
  QWidget* f = w.properties().panel()->field(label);
  ASSERT_TRUE(f) << label.toStdString() << " in " << w.properties().panel()->title().toStdString();
  QTest::mouseClick(f, Qt::LeftButton);
  QTest::keyClick(f, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(f, text);
  QTest::keyClick(f, Qt::Key_Return);
}

const Joint* gearOf(const Mechanism& m) {
  for (const Joint& j : m.joints)
    if (j.type == JointType::Gear) return &j;
  return nullptr;
}

// Two shafts on ground pivots, the first driven: (0, 0) with a crank to (10, 0), (-40, -20)
// with an arm to (-30, -20).
void twoShafts(MainWindow& w, test::Draw& d) {
  w.resize(1300, 900);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(4);
  w.canvas()->centerOn(0, 0);
  d.key("G");
  d.click(0, 0);
  d.click(-40, -20);
  d.link({{0, 0}, {10, 0}});
  d.link({{-40, -20}, {-30, -20}});
  d.key("M");
  d.click(0, 0);
  d.key("S");
}

TEST(ElementsUi, GearToolCouplesTwoShaftsAndTheRatioIsTyped) {
  MainWindow w;
  test::Draw d{w};
  twoShafts(w, d);
  Document* doc = w.document();
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  const int before = doc->undoStack()->index();
  d.key("E");
  d.click(6, 0);
  d.click(-34, -20, Qt::ShiftModifier);  // a belt
  const Joint* g = gearOf(doc->design());
  ASSERT_TRUE(g);
  EXPECT_EQ(g->ratio, 1);
  EXPECT_EQ(doc->design().pointLabel(g->a), "link2.A");
  EXPECT_EQ(doc->undoStack()->index(), before + 1);
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  // Selected: the panel edits its ratio.
  EXPECT_NE(w.properties().panel()->title().indexOf("gear"), -1)
      << w.properties().panel()->title().toStdString();
  type(w, "Ratio", "-2");
  EXPECT_EQ(gearOf(doc->design())->ratio, -2);
  ASSERT_TRUE(doc->solved());
  ASSERT_TRUE(doc->setCrankDeg(30).ok());
  const BodyId arm = doc->design().bodyNamed("link3")->id;
  EXPECT_NEAR(doc->kinematics().bodyAngle(arm), -2 * 30 * M_PI / 180, 1e-12);
  // Drawn as two pitch circles touching at the pitch point.
  std::vector<JointItem*> gears;
  for (JointItem* j : w.scene()->jointItems())
    if (dynamic_cast<GearItem*>(j)) gears.push_back(j);
  EXPECT_EQ(gears.size(), 1u);
  // A ratio of 0 is refused, the design unchanged.
  const std::string kept = serializeMechanism(doc->design());
  type(w, "Ratio", "0");
  EXPECT_EQ(serializeMechanism(doc->design()), kept);
  // Undo takes the coupling away again, step by step.
  w.edit().undo->trigger();
  EXPECT_EQ(gearOf(doc->design())->ratio, 1);
  w.edit().undo->trigger();
  EXPECT_EQ(gearOf(doc->design()), nullptr);
}

TEST(ElementsUi, CoupleToOnABodysMenuStartsTheGearToolFromIt) {
  MainWindow w;
  test::Draw d{w};
  twoShafts(w, d);
  Document* doc = w.document();
  // The body's right-click menu has the entry; triggering it makes the next click the second.
  d.rightClick(-35, -20);
  QApplication::processEvents();
  QAction* couple = nullptr;
  for (QMenu* menu : w.canvas()->findChildren<QMenu*>())
    for (QAction* a : menu->actions())
      if (menu->isVisible() && a->text().startsWith("Couple to")) couple = a;
  ASSERT_TRUE(couple) << "no \"Couple to\" on the body's menu";
  couple->trigger();
  qobject_cast<QWidget*>(couple->parent())->close();
  d.click(5, 0);
  const Joint* g = gearOf(doc->design());
  ASSERT_TRUE(g);
  EXPECT_EQ(g->ratio, -1);
  EXPECT_EQ(doc->design().pointLabel(g->a), "link3.B");
}

TEST(ElementsUi, SlotToolDrawsAnArcAndThePanelTypesItsRadius) {
  MainWindow w;
  w.resize(1300, 900);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(4);
  w.canvas()->centerOn(0, 0);
  test::Draw d{w};
  Document* doc = w.document();
  d.key("T");
  d.click(40, 0);
  d.click(0, 40, Qt::ShiftModifier);  // the arc's end: a third click bends it
  EXPECT_TRUE(doc->design().slots.empty());
  d.click(28.284271247461902, 28.284271247461902);  // on the circle of 40 about the origin
  ASSERT_EQ(doc->design().slots.size(), 1u);
  const Slot& s = doc->design().slots[0];
  ASSERT_TRUE(s.arc());
  const std::optional<Guide> g = guideOf(s);
  ASSERT_TRUE(g);
  EXPECT_LT(g->centre.norm(), 0.3);  // the clicks snap to the grid, the third is free
  EXPECT_NEAR(g->radius, 40, 0.3);
  // Selected and typed: radius 50 about the same centre.
  w.tools().selection()->clear();
  w.tools().selection()->add(s.id);
  type(w, "Radius [mm]", "50");
  const std::optional<Guide> h = guideOf(doc->design().slots[0]);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->radius, 50, 1e-9);
  EXPECT_LT((h->centre - g->centre).norm(), 1e-9);
  EXPECT_NEAR(h->sweep, g->sweep, 1e-9);
  // Three points on a line are refused, the arc kept.
  const std::string kept = serializeMechanism(doc->design());
  // (xm on the chord at the height of the middle point.)
  const Slot& now = doc->design().slots[0];
  const double t = (now.mid->y() - now.p0.y()) / (now.p1.y() - now.p0.y());
  type(w, "xm [mm]", QString::number(now.p0.x() + t * (now.p1.x() - now.p0.x()), 'g', 17));
  EXPECT_EQ(serializeMechanism(doc->design()), kept);
  // Straight, then an arc again, from the panel's shape.
  auto* shape = qobject_cast<QComboBox*>(w.properties().panel()->field("Shape"));
  ASSERT_TRUE(shape);
  shape->activated(0);
  EXPECT_FALSE(doc->design().slots[0].arc());
  shape = qobject_cast<QComboBox*>(w.properties().panel()->field("Shape"));
  ASSERT_TRUE(shape);
  shape->activated(1);
  EXPECT_TRUE(doc->design().slots[0].arc());
}

}  // namespace
}  // namespace linkage::ui
