// Drafting comfort: tool keys where a user means them, the start angle's meaning shown, file
// dialogs beside the file.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>

#include "canvas/canvas_view.h"
#include "dialogs.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/io/model_lookup.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/main_window.h"

namespace linkage::ui {
namespace {

QLineEdit* fieldOf(MainWindow& w, const QString& label) {
  return qobject_cast<QLineEdit*>(w.properties()->field(label));
}

TEST(Drafting, AToolKeyTypedInANumberFieldChoosesTheToolAndKeepsTheValue) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const PointId p = *w.document()->design().findPoint("coupler.P");
  w.selection()->add(p);
  QLineEdit* x = fieldOf(w, "x [mm]");
  ASSERT_NE(x, nullptr);
  x->setFocus();
  x->selectAll();
  QTest::keyClicks(x, "-29.34");
  QTest::keyClick(x, Qt::Key_L);  // meant for the Link tool
  EXPECT_TRUE(w.action("tool:link")->isChecked());
  EXPECT_TRUE(w.canvas()->hasFocus());
  EXPECT_EQ(w.document()->design().point(p)->pos.x(), -29.34);
  EXPECT_EQ(w.document()->undoStack()->count(), 1);
  // A letter that is no shortcut is dropped, not typed into the number.
  w.action("tool:select")->trigger();
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
  EXPECT_TRUE(w.action("tool:select")->isChecked());
}

TEST(Drafting, AStartAngleTurnsTheCrankThereAndSaysWhatItMeans) {
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  const BodyId crank = w.document()->design().bodyNamed("crank")->id;
  QLineEdit* start = fieldOf(w, QStringLiteral("Start angle [\u00b0]"));
  ASSERT_NE(start, nullptr);
  EXPECT_FALSE(start->toolTip().isEmpty());
  auto* meaning = qobject_cast<QLabel*>(w.properties()->field("Crank 0 is"));
  ASSERT_NE(meaning, nullptr);
  EXPECT_EQ(meaning->text(), "the drawing as it is");
  start->setFocus();
  start->selectAll();
  QTest::keyClicks(start, "30");
  QTest::keyClick(start, Qt::Key_Return);
  // Crank angle 0, the disk 30 degrees on (counter-clockwise, its driving direction).
  EXPECT_EQ(w.document()->crankDeg(), 0);
  EXPECT_NEAR(w.document()->kinematics().bodyAngle(crank) * 180 / M_PI, 30, 1e-9);
  EXPECT_EQ(w.properties()->field("Crank 0 is")
                ? qobject_cast<QLabel*>(w.properties()->field("Crank 0 is"))->text()
                : QString(),
            QStringLiteral("the drawing turned 30\u00b0 counter-clockwise"));
  // The drawing itself is as it was drawn.
  EXPECT_EQ(w.document()->design().point(*w.document()->design().findPoint("crank.A"))->pos,
            Vec2(10, 17.320508075688775));
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

}  // namespace
}  // namespace linkage::ui
