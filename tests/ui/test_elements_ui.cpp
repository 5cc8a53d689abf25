// The gear and the arc slot in the editor, with mouse and key events: the Gear tool (E) couples
// two pivoted bodies (Shift: a belt), the ratio is typed in the panel (0 refused), "Couple
// to..." starts the tool from a body; the Slot tool draws an arc with Shift and a third click,
// whose centre and radius are typed in the panel; each is one undo step; the canvas draws them.
#include <gtest/gtest.h>

#include "edge_on.h"
#include "ui_test.h"

#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "drawing.h"
#include "elements/element_ui.h"
#include "elements/gear_item.h"
#include "linkage/elements.h"
#include "linkage/gear.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
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

// A kind's tool is made by the name its ToolSpec gives (tools/tool_registry.h), registered by
// the tool's own file: each is in the toolbox, with its key, and becomes the current tool.
TEST(ElementsUi, EveryKindsToolIsMadeByTheToolRegisteredUnderItsName) {
  MainWindow w;
  Toolbox* box = w.tools().toolbox();
  int tools = 0;
  for (const ElementUi* k : elementUis()) {
    if (!k->tool.maker) continue;
    ++tools;
    QAction* a = box->toolAction(QString::fromLatin1(k->tool.name));
    ASSERT_TRUE(a) << k->tool.name << " made by " << k->tool.maker;
    EXPECT_EQ(a->shortcut(), QKeySequence(QString::fromLatin1(k->tool.key)));
    a->trigger();
    EXPECT_TRUE(a->isChecked()) << k->tool.name;
    ASSERT_TRUE(box->tool());
    EXPECT_FALSE(box->tool()->hint().isEmpty()) << k->tool.name;
  }
  EXPECT_EQ(tools, 3);  // the slider's block, the pin in a slot, the gear
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
  EXPECT_EQ(gearRatio(*g), 1);
  EXPECT_EQ(doc->design().pointLabel(g->a), "link2.A");
  EXPECT_EQ(doc->undoStack()->index(), before + 1);
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  // Selected: the panel edits its ratio.
  EXPECT_NE(w.properties().panel()->title().indexOf("gear"), -1)
      << w.properties().panel()->title().toStdString();
  type(w, "Ratio", "-2");
  EXPECT_EQ(gearRatio(*gearOf(doc->design())), -2);
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
  EXPECT_EQ(gearRatio(*gearOf(doc->design())), 1);
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
  EXPECT_EQ(gearRatio(*g), -1);
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

// A ground arc written in the world in a plane square to the drawing (its x, y alone are three
// points on a line): selected, the panel offers its points and their z but no circle in x, y
// (there is none to type), and its shape made straight and an arc again keeps a z for each
// point, the machine solved throughout; a bend off a chord along z, which would have no bulge,
// is refused.
TEST(ElementsUi, AGroundArcSquareToTheDrawingInThePanel) {
  QTemporaryDir dir;
  const QString path = writeEdgeOn(dir);
  ASSERT_FALSE(path.isEmpty());
  MainWindow w;
  w.resize(1300, 900);
  ASSERT_TRUE(w.document()->open(path, nullptr));
  w.show();
  QApplication::processEvents();
  Document* doc = w.document();
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  const SlotId g = doc->design().slots[0].id, z = doc->design().slots[1].id;
  w.tools().selection()->clear();
  w.tools().selection()->add(g);
  QApplication::processEvents();
  EXPECT_NE(w.properties().panel()->field("xm [mm]"), nullptr);
  EXPECT_EQ(w.properties().panel()->field("Radius [mm]"), nullptr);
  // Its points' z typed: the middle's moved along the plane (x = 0), solved again.
  type(w, "zm [mm]", "8");
  EXPECT_EQ(doc->design().slot(g)->z, (std::vector<double>{0, 8, 0}));
  EXPECT_TRUE(doc->solved()) << doc->solveStatus().message;
  // Chosen with the keys, as a user does: the box's own signal rebuilds the form (its shape
  // changes), and the box must outlive that signal (the sanitizers' build would see it freed).
  auto* shape = qobject_cast<QComboBox*>(w.properties().panel()->field("Shape"));
  ASSERT_TRUE(shape);
  ASSERT_EQ(shape->currentIndex(), 1);
  QTest::keyClick(shape, Qt::Key_Up);
  EXPECT_FALSE(doc->design().slot(g)->arc());
  EXPECT_EQ(doc->design().slot(g)->z.size(), 2u);
  EXPECT_TRUE(doc->solved()) << doc->solveStatus().message;
  QApplication::processEvents();
  shape = qobject_cast<QComboBox*>(w.properties().panel()->field("Shape"));
  ASSERT_TRUE(shape);
  QTest::keyClick(shape, Qt::Key_Down);
  EXPECT_TRUE(doc->design().slot(g)->arc());
  EXPECT_EQ(doc->design().slot(g)->z.size(), 3u);
  EXPECT_TRUE(doc->solved()) << doc->solveStatus().message;
  // The slot along z: its chord has no x, y to bend off.
  w.tools().selection()->clear();
  w.tools().selection()->add(z);
  QApplication::processEvents();
  const std::string kept = serializeMechanism(doc->design());
  shape = qobject_cast<QComboBox*>(w.properties().panel()->field("Shape"));
  ASSERT_TRUE(shape);
  // Refused: the design kept, the reason said, and the box back at what the slot is.
  QSignalSpy said(w.properties().panel(), &PropertiesPanel::message);
  shape->setCurrentIndex(1);
  shape->activated(1);
  EXPECT_EQ(serializeMechanism(doc->design()), kept);
  ASSERT_EQ(said.size(), 1);
  EXPECT_TRUE(said[0][0].toString().startsWith("The slot is not bent: "))
      << said[0][0].toString().toStdString();
  EXPECT_GT(said[0][0].toString().size(), 24);
  EXPECT_TRUE(said[0][1].toBool());
  EXPECT_EQ(shape->currentIndex(), 0);
  shot(&w, "ground_arc_on_edge_panel");
}

// The gear-four-bar example at a known zoom: the pinion on ground.I (-45, 0), pitch radius 15,
// in mesh with the gear on ground.O2 (0, 0), radius 30 (ratio -0.5: radii 45 * 1/3 and 2/3);
// the pitch point at (-30, 0). Nothing is selected.
JointId showGearPair(MainWindow& w) {
  w.resize(1300, 900);
  EXPECT_TRUE(w.openExample("gear-four-bar"));
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(4);
  w.canvas()->centerOn(-10, 0);
  w.tools().selection()->clear();
  return gearOf(w.document()->design())->id;
}

bool onlyGearSelected(MainWindow& w, JointId gear) {
  const Selection& s = *w.tools().selection();
  return s.size() == 1 && s.contains(gear);
}

TEST(ElementsUi, AGearIsSelectedByItsPitchCirclesPitchPointCentreAndBand) {
  MainWindow w;
  const JointId gear = showGearPair(w);
  test::Draw d{w};
  // Each pitch circle, a few pixels off its line.
  for (const auto& [x, y] : {std::pair{-45.0, 15.5}, {0.0, -29.5}, {30.5, 0.0}}) {
    d.click(200, 200);  // empty canvas: nothing selected
    ASSERT_TRUE(w.tools().selection()->empty());
    d.click(x, y);
    EXPECT_TRUE(onlyGearSelected(w, gear)) << "a click at " << x << ", " << y;
  }
  // Its Properties: the coupling named, its ratio and type.
  EXPECT_NE(w.properties().panel()->title().indexOf("gear pinion.I - gear.O2"), -1)
      << w.properties().panel()->title();
  EXPECT_NE(w.properties().panel()->field("Ratio"), nullptr);
  EXPECT_NE(w.properties().panel()->field("Type"), nullptr);
  // The pitch point, where the circles touch.
  d.click(200, 200);
  d.click(-30, 0);
  EXPECT_TRUE(onlyGearSelected(w, gear));
  // The centre area: inside the gear's circle, clear of its arm.
  d.click(200, 200);
  d.click(-8, -12);
  EXPECT_TRUE(onlyGearSelected(w, gear));
  // The pinion's centre is its pivot first; clicked again, what is under it in turn, the
  // pinion's gear among them.
  d.click(200, 200);
  bool reached = false;
  for (int i = 0; i < 5 && !reached; ++i) {
    d.click(-45, 0);
    reached = onlyGearSelected(w, gear);
  }
  EXPECT_TRUE(reached) << "clicks on the pinion's centre never reached its gear";
  // A band over both pitch circles holds the coupling (with what else it holds), and it is
  // seen selected: its circles traced over (the bottom of the gear's, far from any point,
  // pin or link, changes).
  d.click(200, 200);
  d.move(200, 200);
  const QRect bottom(d.at(0, -30) - QPoint(6, 6), QSize(13, 13));
  const QImage before = w.canvas()->viewport()->grab(bottom).toImage();
  d.drag(-65, -35, 35, 35);
  EXPECT_TRUE(w.tools().selection()->contains(gear));
  d.move(200, 200);
  EXPECT_NE(w.canvas()->viewport()->grab(bottom).toImage(), before)
      << "the selected gear's circle is not drawn selected";
}

// The right-click menu's entries on the canvas (the visible menu's actions, by text).
QAction* menuEntry(MainWindow& w, const QString& start) {
  for (QMenu* menu : w.canvas()->findChildren<QMenu*>())
    if (menu->isVisible())
      for (QAction* a : menu->actions())
        if (a->text().startsWith(start)) return a;
  return nullptr;
}

TEST(ElementsUi, AGearsMenuNamesItAndEditsItsRatioAndTypeAsOneStepEach) {
  MainWindow w;
  const JointId gear = showGearPair(w);
  test::Draw d{w};
  Document* doc = w.document();
  QApplication::setActiveWindow(&w);
  d.rightClick(0, -30);  // on the gear's pitch circle
  QApplication::processEvents();
  const QString name = "gear pinion.I - gear.O2";
  QAction* section = menuEntry(w, name);
  ASSERT_TRUE(section) << "the menu does not name the gear";
  EXPECT_TRUE(section->isSeparator());
  ASSERT_TRUE(menuEntry(w, "Gears in Mesh"));
  EXPECT_TRUE(menuEntry(w, "Gears in Mesh")->isChecked());
  ASSERT_TRUE(menuEntry(w, "Belt"));
  QAction* edit = menuEntry(w, "Edit &Ratio");
  ASSERT_TRUE(edit);
  qobject_cast<QWidget*>(edit->parent())->close();  // as a menu does: closed, then acts
  edit->trigger();
  QApplication::processEvents();
  // Selected, its Ratio field has the keyboard, its value selected to be typed over.
  EXPECT_TRUE(onlyGearSelected(w, gear));
  auto* ratio = qobject_cast<QLineEdit*>(w.properties().panel()->field("Ratio"));
  ASSERT_TRUE(ratio);
  EXPECT_TRUE(ratio->hasFocus());
  EXPECT_EQ(ratio->selectedText(), "-0.5");
  const int before = doc->undoStack()->index();
  QTest::keyClicks(ratio, "-0.25");
  QTest::keyClick(ratio, Qt::Key_Return);
  EXPECT_EQ(gearRatio(*doc->design().joint(gear)), -0.25);
  EXPECT_EQ(doc->undoStack()->index(), before + 1);
  EXPECT_EQ(doc->undoStack()->text(before), "Gear ratio");
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  // Its type: a belt (the same ratio, the same way), one step; undone.
  auto* type = qobject_cast<QComboBox*>(w.properties().panel()->field("Type"));
  ASSERT_TRUE(type);
  EXPECT_EQ(type->currentIndex(), 0);
  type->setCurrentIndex(1);
  emit type->activated(1);
  EXPECT_EQ(gearRatio(*doc->design().joint(gear)), 0.25);
  EXPECT_EQ(doc->undoStack()->index(), before + 2);
  doc->undoStack()->undo();
  EXPECT_EQ(gearRatio(*doc->design().joint(gear)), -0.25);
  EXPECT_EQ(type->currentIndex(), 0);
}

}  // namespace
}  // namespace linkage::ui
