// Drafting comfort: tool keys where a user means them, the start angle's meaning shown, file
// dialogs beside the file.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "canvas/canvas_view.h"
#include "dialogs.h"
#include "document/commands.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/edits.h"
#include "linkage/guide.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "plots/curve_set.h"
#include "plots/plots_panel.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/features.h"
#include "window/message_strip.h"

namespace linkage::ui {
namespace {

QLineEdit* fieldOf(MainWindow& w, const QString& label) {
  return qobject_cast<QLineEdit*>(w.properties().panel()->field(label));
}

TEST(Drafting, AToolKeyTypedInANumberFieldChoosesTheToolAndKeepsTheValue) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const PointId p = *w.document()->design().findPoint("coupler.P");
  w.tools().selection()->add(p);
  QLineEdit* x = fieldOf(w, "x [mm]");
  ASSERT_NE(x, nullptr);
  x->setFocus();
  x->selectAll();
  QTest::keyClicks(x, "-29.34");
  QTest::keyClick(x, Qt::Key_L);  // meant for the Link tool
  EXPECT_TRUE(w.tools().toolbox()->toolAction("link")->isChecked());
  EXPECT_TRUE(w.canvas()->hasFocus());
  EXPECT_EQ(w.document()->design().point(p)->pos.x(), -29.34);
  EXPECT_EQ(w.document()->undoStack()->count(), 1);
  // A letter that is no shortcut is dropped, not typed into the number.
  w.tools().toolbox()->toolAction("select")->trigger();
  x = fieldOf(w, "x [mm]");
  x->setFocus();
  x->selectAll();
  QTest::keyClicks(x, "12q.5");
  EXPECT_EQ(x->text(), "12.5");
  QTest::keyClicks(x, "e1");  // an exponent stays a number
  EXPECT_EQ(x->text(), "12.5e1");
  QTest::keyClick(x, Qt::Key_Return);
  EXPECT_EQ(w.document()->design().point(p)->pos.x(), 125);
  // In a name, letters are the name's: no tool takes them.
  QLineEdit* name = fieldOf(w, "Name");
  name->setFocus();
  name->selectAll();
  QTest::keyClicks(name, "pl");
  EXPECT_EQ(name->text(), "pl");
  EXPECT_TRUE(w.tools().toolbox()->toolAction("select")->isChecked());
}

// Issue 26: an arc slot's typed point changed, the block in it kept coordinates off the new arc,
// and the file written then did not close (every tool said the body was moved 20.08 mm to
// assemble it). The edit keeps the drawing assembled: the block is drawn on the arc, and the
// file loads with nothing moved.
TEST(Drafting, ATypedArcKeepsTheBlockInItAndTheFileCloses) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "curved-guide"));
  const Mechanism& m0 = w.document()->design();
  const SlotId guide = m0.slotNamed(m0.ground()->id, "guide")->id;
  w.tools().selection()->add(guide);
  QLineEdit* xm = fieldOf(w, "xm [mm]");
  ASSERT_NE(xm, nullptr);
  xm->setFocus();
  xm->selectAll();
  QTest::keyClicks(xm, "9");
  QTest::keyClick(xm, Qt::Key_Return);
  const Mechanism& m = w.document()->design();
  ASSERT_EQ(m.slot(guide)->mid->x(), 9);
  ASSERT_TRUE(w.document()->solveStatus().ok()) << w.document()->solveStatus().message;
  const Guide g = *guideOf(*m.slot(guide));
  const Vec2 b = m.pointNamed(m.bodyNamed("block")->id, "B")->pos;
  EXPECT_LT(std::abs((b - g.centre).norm() - g.radius), 1e-9);
  LoadResult saved = parseMechanism(serializeMechanism(m));
  ASSERT_TRUE(saved.mechanism) << saved.error;
  Kinematics k;
  ASSERT_TRUE(k.load(*saved.mechanism).ok());
  EXPECT_LT(k.assembly().maxMove, 1e-9);
  EXPECT_EQ(w.document()->undoStack()->count(), 1);
}

TEST(Drafting, AStartAngleTurnsTheCrankThereAndSaysWhatItMeans) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const BodyId crank = w.document()->design().bodyNamed("crank")->id;
  QLineEdit* start = fieldOf(w, QStringLiteral("Start angle [\u00b0]"));
  ASSERT_NE(start, nullptr);
  EXPECT_FALSE(start->toolTip().isEmpty());
  auto* meaning = qobject_cast<QLabel*>(w.properties().panel()->field("Crank 0 is"));
  ASSERT_NE(meaning, nullptr);
  EXPECT_EQ(meaning->text(), "the drawing as it is");
  start->setFocus();
  start->selectAll();
  QTest::keyClicks(start, "30");
  QTest::keyClick(start, Qt::Key_Return);
  // Crank angle 0, the disk 30 degrees on (counter-clockwise, its driving direction).
  EXPECT_EQ(w.document()->crankDeg(), 0);
  EXPECT_NEAR(w.document()->kinematics().bodyAngle(crank) * 180 / M_PI, 30, 1e-9);
  EXPECT_EQ(w.properties().panel()->field("Crank 0 is")
                ? qobject_cast<QLabel*>(w.properties().panel()->field("Crank 0 is"))->text()
                : QString(),
            QStringLiteral("the drawing turned 30\u00b0 counter-clockwise"));
  // The drawing itself is as it was drawn.
  EXPECT_EQ(w.document()->design().point(*w.document()->design().findPoint("crank.A"))->pos,
            Vec2(10, 17.320508075688775));
}

// Types `typed` into the field `label` of coupler.P (or of the mechanism: `point` empty),
// commits it with Return, then Ctrl+Z in the field: the document's edit is undone (one entry in
// the history, redo kept), the field shows the value undone, leaving the field commits nothing
// and Ctrl+Shift+Z redoes the edit.
void expectCtrlZUndoesTheEdit(const QString& label, const QString& typed, const char* point) {
  SCOPED_TRACE(label.toStdString());
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
  Document* doc = w.document();
  QUndoStack* undo = doc->undoStack();
  if (*point) w.tools().selection()->add(*doc->design().findPoint(point));
  QLineEdit* f = fieldOf(w, label);
  ASSERT_NE(f, nullptr);
  const QString before = f->text();
  const std::string file = serializeMechanism(doc->design());
  f->setFocus();
  f->selectAll();
  QTest::keyClicks(f, typed);
  QTest::keyClick(f, Qt::Key_Return);
  ASSERT_EQ(undo->count(), 1);
  ASSERT_EQ(f->text(), typed);
  QTest::keyClick(f, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(undo->index(), 0);
  EXPECT_EQ(serializeMechanism(doc->design()), file);
  EXPECT_FALSE(doc->isModified());
  ASSERT_EQ(fieldOf(w, label), f);
  EXPECT_EQ(f->text(), before);
  // Leaving the field takes nothing again.
  QTest::keyClick(f, Qt::Key_Tab);
  EXPECT_FALSE(f->hasFocus());
  EXPECT_EQ(undo->count(), 1);
  EXPECT_EQ(undo->index(), 0);
  EXPECT_FALSE(doc->isModified());
  EXPECT_EQ(f->text(), before);
  // Back in the field: Ctrl+Shift+Z redoes the edit, the field shows it.
  f->setFocus();
  QTest::keyClick(f, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
  EXPECT_EQ(undo->index(), 1);
  EXPECT_EQ(f->text(), typed);
  EXPECT_TRUE(doc->isModified());
  // While a value is being typed, Ctrl+Z takes back the typing, not the document's edit.
  QTest::keyClicks(f, "5");
  QTest::keyClick(f, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(f->text(), typed);
  EXPECT_EQ(undo->index(), 1);
}

TEST(Drafting, CtrlZInACommittedFieldUndoesTheDocumentsEdit) {
  expectCtrlZUndoesTheEdit("x [mm]", "31", "coupler.P");  // a number
  expectCtrlZUndoesTheEdit("Name", "Q", "coupler.P");     // a name
  expectCtrlZUndoesTheEdit(QStringLiteral("Start angle [\u00b0]"), "30", "");
  expectCtrlZUndoesTheEdit("Name", "another name", "");  // the mechanism's
}

TEST(Drafting, CtrlZInAChoiceUndoesTheDocumentsEdit) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&w));
  auto* box = qobject_cast<QComboBox*>(w.properties().panel()->field("Direction"));
  ASSERT_NE(box, nullptr);
  box->setFocus();
  QTest::keyClick(box, Qt::Key_Down);
  ASSERT_EQ(w.document()->design().driver->direction, Direction::Cw);
  ASSERT_EQ(w.document()->undoStack()->count(), 1);
  QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
  EXPECT_EQ(w.document()->design().driver->direction, Direction::Ccw);
  EXPECT_EQ(w.document()->undoStack()->index(), 0);
  EXPECT_EQ(box->currentIndex(), 0);
}

// A value refused turns its field red while the message saying why is shown: it goes with the
// message (the next edit, undo, selection or turn of the crank), not later.
TEST(Drafting, ARefusedFieldIsRedWhileItsMessageIsShown) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  auto refuse = [&w] {
    QLineEdit* f = fieldOf(w, QStringLiteral("Start angle [\u00b0]"));
    f->setFocus();
    f->selectAll();
    QTest::keyClicks(f, "1e300");
    QTest::keyClick(f, Qt::Key_Return);
    return f;
  };
  QLineEdit* f = refuse();
  ASSERT_EQ(w.properties().panel()->refusedField(), f);
  EXPECT_FALSE(f->styleSheet().isEmpty());
  EXPECT_EQ(f->text(), "0");
  ASSERT_TRUE(w.messageStrip()->message().contains("between -3600 and 3600"));
  // Home: the crank turned, the message gone, the field no longer red.
  w.animation().toStart->trigger();
  QApplication::processEvents();
  EXPECT_TRUE(w.messageStrip()->message().isEmpty()) << w.messageStrip()->message();
  EXPECT_TRUE(f->styleSheet().isEmpty());
  EXPECT_EQ(w.properties().panel()->refusedField(), nullptr);
  // An edit and its undo.
  f = refuse();
  ASSERT_FALSE(f->styleSheet().isEmpty());
  Mechanism m = w.document()->design();
  m.driver->rpm = 90;
  editDesign(w.document(), "rpm", m);
  w.edit().undo->trigger();
  QApplication::processEvents();
  f = fieldOf(w, QStringLiteral("Start angle [\u00b0]"));
  EXPECT_TRUE(f->styleSheet().isEmpty());
  EXPECT_EQ(f->text(), "0");
  // Another refusal in another field: only that one is red.
  f = refuse();
  QLineEdit* rpm = fieldOf(w, "Driver speed [rpm]");
  ASSERT_NE(rpm, nullptr);
  rpm->setFocus();
  rpm->selectAll();
  QTest::keyClicks(rpm, "-5");
  QTest::keyClick(rpm, Qt::Key_Return);
  EXPECT_EQ(w.properties().panel()->refusedField(), rpm);
  EXPECT_TRUE(w.messageStrip()->message().contains("positive")) << w.messageStrip()->message();
  EXPECT_FALSE(rpm->styleSheet().isEmpty());
  EXPECT_TRUE(f->styleSheet().isEmpty());
}

TEST(Drafting, FileDialogsOpenBesideTheFile) {
  QTemporaryDir dir;
  const QString path = dir.filePath("m.linkage.json");
  QFile::copy(QString::fromStdString(*resolveModel(
                  "four-bar-crank-rocker", QApplication::applicationFilePath().toStdString())),
              path);
  MainWindow w;
  ASSERT_TRUE(w.openFile(path));
  EXPECT_EQ(w.fileFolder(), QFileInfo(path).absolutePath());
  QString shown;
  test::DialogAnswer answer;
  answer.expect([&shown](QWidget* d) {
    if (auto* f = qobject_cast<QFileDialog*>(d)) shown = f->directory().absolutePath();
    static_cast<QDialog*>(d)->reject();
  });
  w.saveAs();
  EXPECT_EQ(shown, QFileInfo(path).absolutePath());
  // An example (untitled): where the last file was.
  ASSERT_TRUE(w.openExample("wanzer-inversion-2"));
  EXPECT_EQ(w.fileFolder(), QFileInfo(path).absolutePath());
}

void type(QLineEdit* field, const QString& text) {
  field->setFocus();
  field->selectAll();
  QTest::keyClicks(field, text);
  QTest::keyClick(field, Qt::Key_Return);
}

// The homework's triangle: sides typed, the mechanism re-solved at once.
TEST(Drafting, APlateIsGivenByItsSideLengths) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const Mechanism& m = w.document()->design();
  const BodyId coupler = m.bodyNamed("coupler")->id;
  w.tools().selection()->add(coupler);
  for (const char* side : {"Side AB [mm]", "Side BP [mm]", "Side AP [mm]"})
    ASSERT_NE(fieldOf(w, side), nullptr) << side;
  type(fieldOf(w, "Side BP [mm]"), "50");
  type(fieldOf(w, "Side AP [mm]"), "40");
  EXPECT_EQ(w.document()->undoStack()->count(), 2);
  ASSERT_TRUE(w.document()->solved()) << w.document()->solveStatus().message;
  const std::vector<double> sides = sideLengths(w.document()->design(), coupler);
  EXPECT_NEAR(sides[1], 50, 1e-12);
  EXPECT_NEAR(sides[2], 40, 1e-12);
  // Solved: the moving plate has those sides where it is now.
  const Kinematics& k = w.document()->kinematics();
  auto at = [&](const char* p) { return k.position(*w.document()->design().findPoint(p)); };
  EXPECT_NEAR((at("coupler.P") - at("coupler.A")).norm(), 40, 1e-9);
  EXPECT_NEAR((at("coupler.P") - at("coupler.B")).norm(), 50, 1e-9);
  EXPECT_EQ(fieldOf(w, "Side AP [mm]")->text(), "40");
  // No triangle: refused, red, the value as it was.
  type(fieldOf(w, "Side AP [mm]"), "500");
  EXPECT_EQ(fieldOf(w, "Side AP [mm]")->text(), "40");
  EXPECT_EQ(w.document()->undoStack()->count(), 2);
}

TEST(Drafting, APointIsPlacedByItsDistanceAndAngleFromAnother) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const PointId p = *w.document()->design().findPoint("coupler.P");
  const Vec2 a = w.document()->design().point(*w.document()->design().findPoint("coupler.A"))->pos;
  w.tools().selection()->add(p);
  auto* from = qobject_cast<QComboBox*>(w.properties().panel()->field("From"));
  ASSERT_NE(from, nullptr);
  EXPECT_EQ(from->currentText(), "A");
  type(fieldOf(w, "Angle [\u00b0]"), "90");
  type(fieldOf(w, "Distance [mm]"), "30");
  EXPECT_EQ(w.document()->design().point(p)->pos, Vec2(a.x(), a.y() + 30));
  EXPECT_TRUE(w.document()->solved());
}

// The monkey test found it: the rows of a point's distance and angle read the point they are
// measured from; an undo that takes that point away must make them again, not read it.
TEST(Drafting, UndoingThePointADistanceIsMeasuredFromRemakesTheRows) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  Document* doc = w.document();
  const PointId p = *doc->design().findPoint("coupler.P");
  Mechanism next = doc->design();
  const PointId extra = addBodyPoint(next, next.point(p)->body, Vec2(1, 2));
  commitEdit(doc, "Add point", next);
  w.tools().selection()->add(p);
  auto* from = qobject_cast<QComboBox*>(w.properties().panel()->field("From"));
  ASSERT_NE(from, nullptr);
  const QString extraName = QString::fromStdString(doc->design().point(extra)->name);
  const int i = from->findText(extraName);
  ASSERT_GE(i, 0);
  from->setCurrentIndex(i);
  doc->undoStack()->undo();
  QCoreApplication::processEvents();
  ASSERT_FALSE(doc->design().contains(extra));
  from = qobject_cast<QComboBox*>(w.properties().panel()->field("From"));
  ASSERT_NE(from, nullptr);
  EXPECT_EQ(from->findText(extraName), -1);
  EXPECT_FALSE(fieldOf(w, "Distance [mm]")->text().isEmpty());
  doc->undoStack()->redo();
  QCoreApplication::processEvents();
  EXPECT_TRUE(doc->design().contains(extra));
}

TEST(Drafting, ASliderBlockIsSelectedByAClickAgainAndRenamed) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "slider-crank-22a-lambda-0.3"));
  const BodyId block = w.document()->design().bodyNamed("needlebar")->id;
  const Vec2 at =
      w.document()->kinematics().position(*w.document()->design().findPoint("needlebar.B"));
  test::Draw d{w};
  d.click(at.x(), at.y());
  EXPECT_EQ(w.tools().selection()->joints.size(), 1u);  // first the pin
  d.click(at.x(), at.y());
  EXPECT_EQ(w.tools().selection()->points.size(), 1u);  // then the point
  d.click(at.x(), at.y());
  ASSERT_EQ(w.tools().selection()->bodies.size(), 1u);  // then the block
  EXPECT_EQ(w.tools().selection()->bodies[0], block);
  EXPECT_TRUE(w.properties().panel()->title().contains("needlebar"));
  type(fieldOf(w, "Name"), "slider");
  EXPECT_EQ(w.document()->design().body(block)->name, "slider");
}

TEST(Drafting, AnotherWindowIsComparedAtThePointChosen) {
  MainWindow a;
  ASSERT_TRUE(test::showExample(a, "four-bar-crank-rocker"));
  auto* b = new MainWindow;
  b->setAttribute(Qt::WA_DeleteOnClose, false);
  ASSERT_TRUE(b->openExample("wanzer-inversion-2"));
  a.plots().dock->show();
  a.plots().panel()->setCompare(PlotsPanel::Compare::Overlay);
  QTest::qWait(80);
  // No point of the same name there: that mechanism's first output, not "no point".
  ASSERT_NE(a.plots().panel()->curves(1), nullptr);
  EXPECT_EQ(a.plots().panel()->curves(1)->request().target, "needlebar.G");
  EXPECT_TRUE(a.plots().panel()->curves(1)->status().ok())
      << a.plots().panel()->curves(1)->status().message;
  // Another point chosen.
  a.plots().panel()->setComparisonTarget("triangle.G");
  QTest::qWait(80);
  EXPECT_EQ(a.plots().panel()->curves(1)->request().target, "triangle.G");
  EXPECT_TRUE(a.plots().panel()->curves(1)->status().ok());
  delete b;
}

}  // namespace
}  // namespace linkage::ui
