// Drawing with the mouse and the keyboard only: a four-bar from nothing, saved and checked by
// the command line; undo and redo of every kind of edit give back the identical file.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QProcess>
#include <QStatusBar>
#include <QTemporaryDir>

#include "canvas/canvas_scene.h"
#include "document/commands.h"
#include "document/document.h"
#include "drawing.h"
#include "linkage/io/model_file.h"
#include "linkage/io/model_lookup.h"
#include "plots/plots_panel.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"
#include "tools/toolbox.h"
#include "window/message_strip.h"
#include "window/plots_feature.h"

namespace linkage::ui {
namespace {

// Runs linkage-cli; its exit status and output.
std::pair<int, QString> cli(const QStringList& args) {
  QProcess p;
  p.start(QStringLiteral(LINKAGE_CLI), args);
  p.waitForFinished(30000);
  return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError())};
}

// The four-bar's pivots and links, its crank's pivot the driver (no output point chosen).
void drawFourBarLinks(test::Draw& d) {
  d.key("G");
  d.click(0, 0);
  d.click(60, 0);
  d.link({{0, 0}, {10, 20}});
  d.link({{10, 20}, {70, 50}});
  d.link({{70, 50}, {60, 0}});
  d.key("M");
  d.click(0, 0);
}

// Ground pivots at (0, 0) and (60, 0), crank to (10, 20), coupler to (70, 50), rocker down to
// the second pivot, the crank's pivot the driver: a crank-rocker.
void drawFourBar(MainWindow& w) {
  test::Draw d{w};
  drawFourBarLinks(d);
  d.key("O");
  d.click(70, 50);
  d.key("S");
}

TEST(Draw, FourBarWithMouseAndKeysIsSavedAndTurnsFully) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(5);
  w.canvas()->centerOn(30, 25);
  drawFourBar(w);
  shot(&w, "draw-four-bar");
  Document* doc = w.document();
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  EXPECT_EQ(doc->design().bodies.size(), 4u) << serializeMechanism(doc->design());
  EXPECT_EQ(doc->design().joints.size(), 4u);
  ASSERT_TRUE(doc->design().driver);
  QTemporaryDir dir;
  const QString path = dir.filePath("four-bar.linkage.json");
  QString why;
  ASSERT_TRUE(doc->save(path, &why)) << why.toStdString();
  const auto [code, info] = cli({"info", path});
  EXPECT_EQ(code, 0) << info.toStdString();
  EXPECT_NE(info.indexOf("bodies: 4, joints: 4"), -1) << info.toStdString();
  EXPECT_EQ(info.count(QStringLiteral("(pin ")), 5) << info.toStdString();  // 4 + the driver line
  EXPECT_NE(info.indexOf("degrees of freedom: 1 "), -1) << info.toStdString();
  const auto [turns, table] = cli({"analyze", path, "--steps", "72"});
  EXPECT_EQ(turns, 0) << table.right(400).toStdString();
  EXPECT_EQ(table.count('\n'), 1 + 73);  // the header and every 5 degrees of a revolution
}

// A four-bar drawn from nothing (G, L x3, M, no output yet) plots a point that moves: the
// coupler's and rocker's pin at (70, 50), not ground.A (three flat lines), nor the crank's pin
// (a circle); the first output once there is one; and a point the user chose stays chosen.
TEST(Draw, ANewDrawingPlotsAMovingPointUntilTheUserChooses) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(5);
  w.canvas()->centerOn(30, 25);
  test::Draw d{w};
  drawFourBarLinks(d);
  d.key("S");
  Document* doc = w.document();
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  ASSERT_TRUE(doc->design().outputs.empty());
  PlotsPanel* plots = w.plots().panel();
  auto plotted = [&] {
    const std::optional<PointId> p = doc->design().findPoint(plots->request().target.toStdString());
    return p ? doc->design().point(*p) : nullptr;
  };
  ASSERT_TRUE(plotted()) << plots->request().target;
  EXPECT_FALSE(plots->request().body);
  EXPECT_LT((plotted()->pos - Vec2(70, 50)).norm(), 1e-9) << plots->request().target;
  EXPECT_FALSE(doc->design().body(plotted()->body)->ground);
  // Its curves move: the position's extremes are apart.
  QTest::qWait(50);
  ASSERT_NE(plots->curves(0), nullptr);
  const Extremes& e = plots->curves(0)->extremes(Order::Position);
  ASSERT_TRUE(e.status.ok()) << e.status.message;
  EXPECT_GT(e.max.value - e.min.value, 10);
  // An output point drawn: it is plotted.
  d.key("O");
  d.click(10, 20);
  d.key("S");
  ASSERT_EQ(doc->design().outputs.size(), 1u);
  EXPECT_EQ(plots->request().target,
            QString::fromStdString(doc->design().pointLabel(doc->design().outputs[0])));
  // The user's choice (the list, by the keyboard) stays through the next edits.
  auto* target = plots->findChild<QComboBox*>("plotTarget");
  ASSERT_TRUE(target);
  target->setFocus();
  QTest::keyClick(target, Qt::Key_Down);
  const QString chosen = plots->request().target;
  ASSERT_NE(chosen, QString::fromStdString(doc->design().pointLabel(doc->design().outputs[0])));
  d.key("O");
  d.click(70, 50);
  d.key("S");
  ASSERT_EQ(doc->design().outputs.size(), 2u);
  EXPECT_EQ(plots->request().target, chosen);
}

TEST(Draw, UndoAndRedoOfEveryEditGiveBackTheIdenticalFile) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(5);
  w.canvas()->centerOn(30, 25);
  Document* doc = w.document();
  std::vector<std::string> files{serializeMechanism(doc->design())};
  auto record = [&] { files.push_back(serializeMechanism(doc->design())); };
  test::Draw d{w};
  // Each kind of edit, one after the other.
  d.key("G");
  d.click(0, 0);
  record();
  d.click(60, 0);
  record();
  d.link({{0, 0}, {10, 20}});
  record();
  d.link({{10, 20}, {70, 50}, {40, 60}});  // three points: a plate
  record();
  d.link({{70, 50}, {60, 0}});
  record();
  d.key("M");
  d.click(0, 0);
  record();
  d.key("O");
  d.click(40, 60);
  record();
  d.key("T");
  d.click(20, -20);
  d.click(50, -20);
  record();  // a slot in the ground
  d.key("S");
  d.click(40, 60);
  d.key(Qt::Key_Delete);
  record();
  shot(&w, "draw-every-edit");
  ASSERT_EQ(doc->undoStack()->count(), int(files.size()) - 1);
  for (int i = int(files.size()) - 2; i >= 0; --i) {
    w.edit().undo->trigger();
    EXPECT_EQ(serializeMechanism(doc->design()), files[i]) << "undo to step " << i;
  }
  for (size_t i = 1; i < files.size(); ++i) {
    w.edit().redo->trigger();
    EXPECT_EQ(serializeMechanism(doc->design()), files[i]) << "redo to step " << i;
  }
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

// Types a value into a field of the properties panel as a user does: click in it, select all,
// type, Enter.
void type(MainWindow& w, const QString& label, const QString& text) {
  QWidget* f = w.properties().panel()->field(label);
  ASSERT_TRUE(f) << label.toStdString() << " in " << w.properties().panel()->title().toStdString();
  QTest::mouseClick(f, Qt::LeftButton);
  QTest::keyClick(f, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(f, text);
  QTest::keyClick(f, Qt::Key_Return);
}

// The Wanzer needle bar's bodies drawn with the tools at about their places: a disk pinned to
// the ground with two slots, the triangle with its points on them, the needle bar's guide.
void drawWanzerSketch(test::Draw& d) {
  d.key("G");
  d.click(0, 0);  // ground point A
  d.key("T");
  d.click(0, 0);  // on A, in the ground: the needle bar's guide D
  d.click(0, -100);
  d.key("L");
  d.click(0, 0);  // the disk, pinned to the ground at A
  d.click(10, 30);
  d.key(Qt::Key_Return);
  d.key("T");
  d.click(10, 30);  // on the disk's point: slot B in the disk
  d.click(10, -30);
  d.key("T");
  d.click(-30, 10);  // inside the disk (now drawn as one): slot C
  d.click(30, 10);
  d.key("L");
  d.click(10, 20);    // on slot B's line: E
  d.click(22.5, 10);  // on slot C's line: F
  d.click(0, -40);    // on the guide's line: G
  d.key(Qt::Key_Return);
}

void selectAt(test::Draw& d, double x, double y) {
  d.key("S");
  d.click(x, y);
}

// Exact numbers: the slots' ends and the triangle's points.
void typeWanzerDimensions(MainWindow& w, test::Draw& d) {
  selectAt(d, 10, -15);
  type(w, "x0 [mm]", "10");
  type(w, "y0 [mm]", "-31");
  type(w, "x1 [mm]", "10");
  type(w, "y1 [mm]", "31");
  selectAt(d, -20, 10);
  type(w, "x0 [mm]", "-31");
  type(w, "x1 [mm]", "31");
  selectAt(d, 10, 20);
  type(w, "y [mm]", "19.927945624162106");
  selectAt(d, 22.5, 10);
  type(w, "x [mm]", "22.547346160988806");
  selectAt(d, 0, -40);
  type(w, "y [mm]", "-41.260288538951315");
}

// The slider blocks (a point, then the slot it slides in), the motor at 240 rpm clockwise on
// the disk, and the needle's point as the output.
void addBlocksDriverAndOutput(MainWindow& w, test::Draw& d) {
  d.key("B");
  d.click(10, 19.93);
  d.click(10, -15);
  d.key("B");
  d.click(22.55, 10);
  d.click(-20, 10);
  d.key("B");
  d.click(0, -41.26);
  d.click(0, -80);
  d.key("M");
  d.click(0, 0);
  selectAt(d, 0, 0);
  type(w, "Driver speed [rpm]", "240");
  auto* dir = qobject_cast<QComboBox*>(w.properties().panel()->field("Direction"));
  ASSERT_TRUE(dir);
  dir->setFocus();
  QTest::keyClick(dir, Qt::Key_Down);  // clockwise
  d.key("O");
  d.click(0, -41.26);
}

// The motion of the drawn mechanism's output over a revolution equals the example's.
void expectMovesAsWanzerExample(const Mechanism& drawn) {
  const Mechanism ref = *loadMechanismFile(*resolveModel("wanzer-inversion-2")).mechanism;
  Kinematics a, b;
  ASSERT_TRUE(a.load(drawn).ok());
  ASSERT_TRUE(b.load(ref).ok());
  const PointId ga = drawn.outputs[0], gb = ref.outputs[0];
  for (double deg = 0; deg <= 360; deg += 7.5) {
    ASSERT_TRUE(a.moveTo(deg).ok());
    ASSERT_TRUE(b.moveTo(deg).ok());
    const auto ma = a.motion(ga), mb = b.motion(gb);
    EXPECT_LT((ma.position - mb.position).norm(), 1e-9) << deg;
    EXPECT_LT((ma.velocity - mb.velocity).norm(), 1e-9 * mb.velocity.norm() + 1e-9) << deg;
    EXPECT_LT((ma.acceleration - mb.acceleration).norm(), 1e-9 * mb.acceleration.norm() + 1e-9)
        << deg;
  }
}

// The Wanzer needle bar, inversion 2, drawn with the tools (a disk with two slots, the
// triangle, two slider blocks, the needle bar in a ground slot) and its exact dimensions typed
// in: its motion equals the example file's.
TEST(Draw, WanzerInversion2DrawnWithTheToolsMovesAsTheExample) {
  MainWindow w;
  w.resize(1300, 900);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(3.5);
  w.canvas()->centerOn(0, -35);
  test::Draw d{w};
  Document* doc = w.document();
  drawWanzerSketch(d);
  shot(&w, "wanzer-drawn");
  typeWanzerDimensions(w, d);
  ASSERT_NO_FATAL_FAILURE(addBlocksDriverAndOutput(w, d));
  shot(&w, "wanzer-done");
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  const Mechanism& drawn = doc->design();
  EXPECT_EQ(drawn.bodies.size(), 6u) << serializeMechanism(drawn);
  EXPECT_EQ(drawn.joints.size(), 7u) << serializeMechanism(drawn);
  ASSERT_TRUE(drawn.driver);
  EXPECT_EQ(drawn.driver->direction, Direction::Cw);
  EXPECT_EQ(drawn.driver->rpm, 240);
  ASSERT_EQ(drawn.outputs.size(), 1u);
  expectMovesAsWanzerExample(drawn);
}

}  // namespace
}  // namespace linkage::ui

namespace linkage::ui {
namespace {

QString statusText(const MainWindow& w) {
  QString all;
  for (QLabel* l : w.statusBar()->findChildren<QLabel*>()) all += l->text() + "\n";
  const MessageStrip* m = w.messageStrip();
  return all + m->hint() + "\n" + m->problem() + "\n" + m->message() + "\n";
}

// Issue 26: the first ground pivot of a new drawing said, in red, "the drawing's extent is below
// 1e-9 of its size": a single point is a valid start of a drawing.
TEST(Draw, TheFirstGroundPivotOfANewDrawingIsNoError) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  test::Draw d{w};
  d.key("G");
  d.click(20, 10);
  QApplication::processEvents();
  ASSERT_EQ(w.document()->design().points.size(), 1u);
  EXPECT_TRUE(w.document()->solveStatus().ok()) << w.document()->solveStatus().message;
  EXPECT_EQ(w.messageStrip()->problem(), "");
  EXPECT_FALSE(statusText(w).contains("extent")) << statusText(w);
  EXPECT_FALSE(statusText(w).contains("rounding")) << statusText(w);
  d.click(20, 10);  // the same place again: a second pivot on it, still nothing wrong
  QApplication::processEvents();
  EXPECT_EQ(w.messageStrip()->problem(), "");
}

// Over-constrained: a second coupler beside the first says the same thing twice; the solver
// names the redundant joint, the canvas draws it in the warning colour and the status bar
// says so. Under-constrained: a link hanging from the crank is free with the crank held.
TEST(Draw, RedundantJointsAndFreeBodiesAreNamedAndShown) {
  MainWindow w;
  w.resize(1200, 800);
  w.show();
  QApplication::processEvents();
  w.canvas()->setZoom(5);
  w.canvas()->centerOn(30, 25);
  drawFourBar(w);
  test::Draw d{w};
  d.link({{10, 20}, {70, 50}});
  Document* doc = w.document();
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  const StructureReport r = doc->kinematics().structure();
  ASSERT_FALSE(r.redundantJoints.empty());
  EXPECT_EQ(r.mobility, 1);
  EXPECT_EQ(r.gruebler, 0);
  int flagged = 0;
  for (PinItem* p : w.scene()->pinItems()) flagged += p->flagged();
  EXPECT_EQ(flagged, int(r.redundantJoints.size()));
  EXPECT_NE(statusText(w).indexOf("redundant"), -1) << statusText(w).toStdString();
  EXPECT_NE(statusText(w).indexOf("Gruebler 0"), -1) << statusText(w).toStdString();
  w.edit().undo->trigger();
  // A link hanging from the crank's pin, its other end free.
  d.link({{10, 20}, {-20, 40}});
  ASSERT_TRUE(doc->solved()) << doc->solveStatus().message;
  const StructureReport u = doc->kinematics().structure();
  ASSERT_EQ(u.freeBodies.size(), 1u);
  EXPECT_TRUE(w.scene()->bodyItem(u.freeBodies[0])->flagged());
  EXPECT_EQ(doc->design().body(u.freeBodies[0])->name, "link5");
}

// The panel's rows are made for what is selected: a bar shows its length; when an edit or an
// undo turns it into a plate, or takes one of its points, the rows are made again (the old ones
// read the bar's second point: after Ctrl+Z of a new point they read a point that was gone; the
// random-input test found it).
TEST(Draw, PropertiesFollowABarThatBecomesAPlateOrLosesAPoint) {
  MainWindow w;
  ASSERT_TRUE(w.openExample("four-bar-crank-rocker"));
  w.show();
  w.properties().dock->raise();
  Document* doc = w.document();
  const BodyId crank = doc->design().bodyNamed("crank")->id;
  w.tools().selection()->add(crank);
  QApplication::processEvents();
  ASSERT_NE(w.properties().panel()->field("Length [mm]"), nullptr);
  // A third point: a plate, no length.
  Mechanism plate = doc->design();
  plate.addPoint(crank, "C", Vec2(5, 5));
  editDesign(doc, "Add point", plate);
  QApplication::processEvents();
  EXPECT_EQ(w.properties().panel()->field("Length [mm]"), nullptr);
  doc->undoStack()->undo();
  QApplication::processEvents();
  ASSERT_NE(w.properties().panel()->field("Length [mm]"), nullptr);
  // The bar's second point gone (and its pin with it), the link kept: one point, no length.
  Mechanism lost = doc->design();
  lost.remove(*lost.findPoint("crank.A"));
  editDesign(doc, "Remove point", lost);
  w.tools().selection()->add(crank);
  QApplication::processEvents();
  EXPECT_EQ(w.properties().panel()->field("Length [mm]"), nullptr);
  doc->undoStack()->undo();
  QApplication::processEvents();
  EXPECT_NE(w.properties().panel()->field("Length [mm]"), nullptr);
}

}  // namespace
}  // namespace linkage::ui
