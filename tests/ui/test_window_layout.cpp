// The menus and toolbars as the features place them (ui/window/window_layout.h): every entry in
// the order the window had before the features made their own (issue 19), written out here by
// hand from that window's menus; and the typed handles are the entries of those names.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>
#include <QWidgetAction>

#include "tools/toolbox.h"
#include "window/features.h"

namespace linkage::ui {
namespace {

// An entry as a word: the action's object name, else its text; "-" a separator, "[Title]" a
// submenu, "widget" a widget in a toolbar.
QString word(QAction* a) {
  if (a->isSeparator()) return QStringLiteral("-");
  if (a->menu()) return QStringLiteral("[%1]").arg(a->text().remove('&'));
  if (qobject_cast<QWidgetAction*>(a)) return QStringLiteral("widget");
  return a->objectName().isEmpty() ? a->text().remove('&') : a->objectName();
}

QStringList words(const QWidget* w) {
  QStringList out;
  for (QAction* a : w->actions()) out << word(a);
  return out;
}

QMenu* menu(const QWidget* parent, const QString& title) {
  for (QAction* a : parent->actions())
    if (a->menu() && a->text().remove('&') == title) return a->menu();
  return nullptr;
}

QStringList tools(const MainWindow& w) {
  QStringList out;
  for (QAction* a : w.tools().toolbox()->toolActions()) out << a->objectName();
  return out;
}

TEST(WindowLayout, EveryMenuHoldsItsEntriesInOrder) {
  MainWindow w;
  QMenuBar* bar = w.menuBar();
  EXPECT_EQ(words(bar), QStringList({"[File]", "[Edit]", "[Tools]", "[View]", "[Animation]",
                                     "[Analysis]", "[Help]"}));
  QMenu* file = menu(bar, "File");
  ASSERT_TRUE(file);
  EXPECT_EQ(words(file),
            QStringList({"new", "newWindow", "open", "[Open Recent]", "[Examples]", "-", "save",
                         "saveAs", "[Export]", "-", "closeWindow", "quit"}));
  ASSERT_TRUE(menu(file, "Export"));
  EXPECT_EQ(words(menu(file, "Export")),
            QStringList({"exportTable", "exportFigure", "exportAnimation", "exportForcesTable",
                         "exportForcesFigure", "exportCycleFigure", "exportTimingTable"}));
  EXPECT_EQ(words(menu(bar, "Edit")), QStringList({"undo", "redo", "-", "showHistory", "-",
                                                   "delete", "flip", "addPlane", "addBallRod"}));
  ASSERT_EQ(tools(w).size(), 6 + 3);  // select link ground slot driver output, three kinds'
  EXPECT_EQ(words(menu(bar, "Tools")), tools(w) + QStringList({"-", "snapGrid"}));
  EXPECT_EQ(words(menu(bar, "View")), QStringList({"fit",
                                                   "zoomIn",
                                                   "zoomOut",
                                                   "actualSize",
                                                   "-",
                                                   "showGrid",
                                                   "showCentres",
                                                   "showTraces",
                                                   "showForces",
                                                   "showExtremes",
                                                   "showTransmission",
                                                   "darkPalette",
                                                   "detachablePanels",
                                                   "hideOtherPlanes",
                                                   "[3D View Direction]",
                                                   "-",
                                                   "Properties",
                                                   "Instant Centres",
                                                   "showPlots",
                                                   "showForcesPanel",
                                                   "showDesignChecks",
                                                   "showMechanisms",
                                                   "showCyclePanel",
                                                   "showCamPanel",
                                                   "showSensitivity",
                                                   "show3dView"}));
  EXPECT_EQ(words(menu(bar, "Animation")),
            QStringList({"play", "stepBack", "stepForward", "toStart", "-", "slower", "faster"}));
  EXPECT_EQ(
      words(menu(bar, "Analysis")),
      QStringList({"showDesignChecks", "parameterStudy", "showSensitivity", "findDimensions", "-",
                   "showExtremes", "showTransmission", "-", "showForcesPanel", "showForces",
                   "balance", "-", "showCyclePanel", "watchClearance", "-", "showCamPanel"}));
  EXPECT_EQ(words(menu(bar, "Help")), QStringList({"about"}));
}

// Issue 26: View and Analysis held two entries both called "Forces" (Shift+F, the reactions on
// the canvas; Shift+G, the dock of force plots), and View two "Instant Centres" (I, the canvas's;
// the dock). No menu holds two entries of one text, and each says what it shows.
TEST(WindowLayout, NoMenuHoldsTwoEntriesOfOneName) {
  MainWindow w;
  const QList<QMenu*> menus = w.menuBar()->findChildren<QMenu*>();
  ASSERT_GE(menus.size(), 7);
  for (QMenu* m : menus) {
    QStringList seen;
    for (QAction* a : m->actions()) {
      if (a->isSeparator()) continue;
      const QString text = a->text().remove('&');
      EXPECT_FALSE(seen.contains(text)) << m->title() << ": \"" << text << "\" twice";
      seen << text;
    }
  }
  QAction* reactions = w.findChild<QAction*>("showForces");
  ASSERT_TRUE(reactions);
  EXPECT_EQ(reactions->shortcut(), QKeySequence("Shift+F"));
  EXPECT_EQ(reactions->text().remove('&'), "Joint Reactions");
  QAction* dock = nullptr;
  for (QAction* a : w.findChildren<QAction*>())
    if (a->objectName() == "showForcesPanel") dock = a;
  ASSERT_TRUE(dock);
  EXPECT_EQ(dock->shortcut(), QKeySequence("Shift+G"));
  EXPECT_EQ(dock->text().remove('&'), "Forces");
  // The same in the View menu: the centres drawn on the canvas (I) beside their dock.
  QAction* centres = w.findChild<QAction*>("showCentres");
  ASSERT_TRUE(centres);
  EXPECT_EQ(centres->text().remove('&'), "Instant Centres on Canvas");
}

TEST(WindowLayout, EveryToolbarHoldsItsEntriesInOrder) {
  MainWindow w;
  std::map<QString, QStringList> bars;
  // The window's own (a dock's widgets may have toolbars of theirs).
  for (QToolBar* t : w.findChildren<QToolBar*>(Qt::FindDirectChildrenOnly))
    bars[t->objectName()] = words(t);
  EXPECT_EQ(bars.size(), 4u);
  EXPECT_EQ(bars["fileToolBar"], QStringList({"new", "open", "save", "undo", "redo"}));
  EXPECT_EQ(bars["toolsToolBar"], tools(w) + QStringList({"-", "delete", "flip"}));
  // The plane chooser last (shown for a machine in space only).
  EXPECT_EQ(bars["viewToolBar"],
            QStringList({"fit", "showGrid", "showCentres", "showTraces", "widget"}));
  EXPECT_EQ(bars["animationToolBar"],
            QStringList({"play", "stepBack", "stepForward", "toStart", "widget"}));
  EXPECT_EQ(w.toolBarArea(w.findChild<QToolBar*>("toolsToolBar")), Qt::LeftToolBarArea);
  EXPECT_EQ(w.toolBarArea(w.findChild<QToolBar*>("animationToolBar")), Qt::BottomToolBarArea);
}

// The handles are the window's actions and docks of the names QSettings and saveState know.
TEST(WindowLayout, TheTypedHandlesAreTheNamedActionsAndDocks) {
  MainWindow w;
  const std::pair<QObject*, const char*> named[] = {
      {w.file().newDocument, "new"},
      {w.file().newWindow, "newWindow"},
      {w.file().closeWindow, "closeWindow"},
      {w.file().quit, "quit"},
      {w.file().about, "about"},
      {w.edit().redo, "redo"},
      {w.edit().showHistory, "showHistory"},
      {w.edit().historyDock, "history"},
      {w.view().zoomIn, "zoomIn"},
      {w.view().zoomOut, "zoomOut"},
      {w.view().actualSize, "actualSize"},
      {w.view().showGrid, "showGrid"},
      {w.view().showTraces, "showTraces"},
      {w.view().darkPalette, "darkPalette"},
      {w.view().detachablePanels, "detachablePanels"},
      {w.animation().toStart, "toStart"},
      {w.animation().slower, "slower"},
      {w.animation().faster, "faster"},
      {w.properties().dock, "properties"},
      {w.centres().dock, "centres"},
      {w.plots().dock, "plots"},
      {w.plots().show, "showPlots"},
      {w.designChecks().dock, "designChecks"},
      {w.designChecks().show, "showDesignChecks"},
      {w.designChecks().showExtremes, "showExtremes"},
      {w.designChecks().showTransmission, "showTransmission"},
      {w.designChecks().parameterStudy, "parameterStudy"},
      {w.exports().table, "exportTable"},
      {w.exports().figure, "exportFigure"},
      {w.exports().animation, "exportAnimation"},
      {w.forces().dock, "forces"},
      {w.mechanisms().dock, "mechanisms"},
      {w.mechanisms().show, "showMechanisms"},
      {w.tools().toolbox()->toolAction("link"), "tool:link"}};
  for (const auto& [object, name] : named) {
    ASSERT_TRUE(object) << name;
    EXPECT_EQ(object->objectName(), QString::fromLatin1(name));
    EXPECT_EQ(w.findChild<QObject*>(QString::fromLatin1(name)), object) << name;
  }
  EXPECT_EQ(w.plots().show, w.plots().dock->toggleViewAction());
  EXPECT_EQ(w.forces().showPanel, w.forces().dock->toggleViewAction());
  EXPECT_EQ(w.tools().toolbox()->toolAction("no such tool"), nullptr);
}

}  // namespace
}  // namespace linkage::ui
