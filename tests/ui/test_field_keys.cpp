// Keys typed into fields (issue 26, item 9): a field with the keyboard owns the keys typed
// there. Letters typed into a number ("abc" in Mass) are dropped with the reason, never taken
// by the window's single-letter keys (B chose the Slider block tool, E the Gear tool); in a
// text field they are the text's; in the docks' number boxes they are refused. The one key a
// number field hands on is a window's key right after a number typed there (issue 19: L after
// "-29.34" commits it and takes the Link tool; test_drafting.cpp), not after a slip.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QTest>
#include <QUndoStack>

#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "cycle/cycle_panel.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/io/model_file.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/features.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

// The window's one-letter keys that act at once: Select (S), flip (X), the instant centres (I),
// fit (F), the grid (#), then the tools (L G T B P M O): one left chosen would show.
const QString kWindowKeys = QStringLiteral("sxif#lgtbpmo");

QLineEdit* fieldOf(MainWindow& w, const QString& label) {
  return qobject_cast<QLineEdit*>(w.properties().panel()->field(label));
}

bool selecting(MainWindow& w) {
  return w.tools().toolbox()->toolAction("select")->isChecked();
}

// What typing into a field must leave as it was: the tool, the document and its history, the
// overlays.
struct Untouched {
  MainWindow& w;
  std::string design = serializeMechanism(w.document()->design());
  int undo = w.document()->undoStack()->count();
  bool grid = w.canvas()->gridVisible();
  void expect(const QString& where) const {
    SCOPED_TRACE(where.toStdString());
    EXPECT_TRUE(selecting(w)) << "a key typed in the field chose a tool";
    EXPECT_EQ(serializeMechanism(w.document()->design()), design);
    EXPECT_EQ(w.document()->undoStack()->count(), undo);
    EXPECT_FALSE(w.scene()->centresVisible());
    EXPECT_EQ(w.canvas()->gridVisible(), grid);
    EXPECT_FALSE(w.canvas()->hasFocus()) << "the keyboard left the field";
  }
};

// The window's keys typed into `field` (its text selected first): nothing but the field sees
// them. A number box keeps its value; a text field has them as its text (put back after).
void typeWindowKeys(MainWindow& w, QWidget* field, const QString& where, bool numberBox) {
  ASSERT_TRUE(field) << where.toStdString();
  auto* line = qobject_cast<QLineEdit*>(field);
  auto* spin = qobject_cast<QAbstractSpinBox*>(field);
  const QString before = line ? line->text() : spin->text();
  const Untouched untouched{w};
  field->setFocus();
  ASSERT_TRUE(field->hasFocus()) << where.toStdString();
  line ? line->selectAll() : spin->selectAll();
  QTest::keyClicks(field, kWindowKeys);
  untouched.expect(where);
  const QString after = line ? line->text() : spin->text();
  if (numberBox)
    EXPECT_EQ(after, before) << where.toStdString();
  else
    EXPECT_EQ(after, kWindowKeys) << where.toStdString();
  if (line) line->setText(before);  // leaving it commits nothing new
}

TEST(FieldKeys, LettersTypedIntoANumberAreDroppedWithTheReasonNotTakenByTheWindow) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "slider-crank-22a-masses"));
  w.tools().selection()->add(w.document()->design().bodyNamed("crank")->id);
  QApplication::processEvents();  // the rows made for it shown
  QLineEdit* mass = fieldOf(w, "Mass [kg]");
  ASSERT_TRUE(mass);
  Untouched untouched{w};
  mass->setFocus();
  mass->selectAll();
  QTest::keyClicks(mass, "abc");  // B: the Slider block tool's key
  untouched.expect("abc in Mass");
  EXPECT_EQ(mass->text(), "0.15");
  EXPECT_TRUE(w.messageStrip()->message().startsWith("Mass [kg] takes a number"))
      << w.messageStrip()->message();
  // "e" is a number's exponent, not the Gear tool's key: typed, then refused as no number.
  mass->selectAll();
  QTest::keyClicks(mass, "e");
  untouched.expect("e in Mass");
  EXPECT_EQ(mass->text(), "e");
  QTest::keyClick(mass, Qt::Key_Return);
  untouched.expect("e in Mass, entered");
  EXPECT_EQ(fieldOf(w, "Mass [kg]")->text(), "0.15");
  // A slip after a number: what follows is no command either ("12abc": not the B of a tool).
  QApplication::processEvents();
  mass = fieldOf(w, "Mass [kg]");
  mass->setFocus();
  mass->selectAll();
  QTest::keyClicks(mass, "0.2abc");
  untouched.expect("0.2abc in Mass");
  EXPECT_EQ(mass->text(), "0.2");
  // A key no window has, after a number: dropped, the number not committed by it.
  mass->selectAll();
  QTest::keyClicks(mass, "0.3q");
  untouched.expect("0.3q in Mass");
  EXPECT_EQ(mass->text(), "0.3");
  // After the slip, L is no command; a number's key typed again, a tool's key right after it
  // commits the number and takes the tool (issue 19).
  QTest::keyClick(mass, Qt::Key_L);
  untouched.expect("0.3qL in Mass");
  QTest::keyClicks(mass, "5");
  QTest::keyClick(mass, Qt::Key_L);
  EXPECT_TRUE(w.tools().toolbox()->toolAction("link")->isChecked());
  EXPECT_EQ(w.document()->design().bodyNamed("crank")->mass->kg, 0.35);
  EXPECT_EQ(w.document()->undoStack()->count(), untouched.undo + 1);
}

TEST(FieldKeys, TheWindowsKeysTypedIntoEveryKindOfFieldChooseNoTool) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "slider-crank-22a-masses"));
  w.cycle().dock->show();
  QApplication::processEvents();
  const Mechanism& m = w.document()->design();
  // The mechanism's: a name, a number (speed), an angle.
  for (const char* label : {"Name", "Driver speed [rpm]", "Start angle [\u00b0]"})
    typeWindowKeys(w, fieldOf(w, label), label, QString(label) != "Name");
  // A link's: its mass, its centre of mass (x, y), its moment of inertia.
  w.tools().selection()->add(m.bodyNamed("rod")->id);
  QApplication::processEvents();
  typeWindowKeys(w, fieldOf(w, "Mass [kg]"), "Mass", true);
  typeWindowKeys(w, fieldOf(w, "Centre of mass"), "Centre of mass", false);
  typeWindowKeys(w, fieldOf(w, "Moment of inertia [kg\u00b7mm\u00b2]"), "inertia", true);
  // A point's coordinates.
  w.tools().selection()->clear();
  w.tools().selection()->add(*m.findPoint("rod.B"));
  QApplication::processEvents();
  typeWindowKeys(w, fieldOf(w, "x [mm]"), "x", true);
  // The docks': the crank's angle and step, the plots' revolutions and steps, the cycle's line.
  for (const char* box : {"crankAngle", "crankStep", "plotRevs", "plotSteps"})
    typeWindowKeys(w, w.findChild<QAbstractSpinBox*>(box), box, true);
  typeWindowKeys(w, w.cycle().panel()->entryLine(), "cycle line", false);
}

// A choice box (a gear's Type, the Cycle dock's kind) finds its entries by the letters typed in
// it; none of them is the window's (the B typed in a gear's Type box chose the Slider block
// tool).
TEST(FieldKeys, LettersTypedIntoAChoiceBoxAreTheBoxs) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "gear-four-bar"));
  const Mechanism& m = w.document()->design();
  JointId gear;
  for (const Joint& j : m.joints)
    if (j.type == JointType::Gear) gear = j.id;
  ASSERT_TRUE(gear);
  w.tools().selection()->add(gear);
  QApplication::processEvents();
  auto* type = qobject_cast<QComboBox*>(w.properties().panel()->field("Type"));
  ASSERT_TRUE(type);
  const Untouched untouched{w};
  type->setFocus();
  ASSERT_TRUE(type->hasFocus());
  QTest::keyClicks(type, kWindowKeys);
  untouched.expect("gear Type");
  // The box itself found its entry by its first letter: "belt".
  QTest::qWait(1100);  // the box's search starts again after a pause
  QTest::keyClicks(type, "b");
  EXPECT_TRUE(type->currentText().startsWith("belt", Qt::CaseInsensitive)) << type->currentText();
}

}  // namespace
}  // namespace linkage::ui
