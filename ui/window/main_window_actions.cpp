// The window's actions, menus and toolbars.
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QToolBar>
#include <QUndoStack>

#include "animation/animator.h"
#include "animation/crank_bar.h"
#include "canvas/canvas_scene.h"
#include "canvas/canvas_view.h"
#include "document/document.h"
#include "tools/toolbox.h"
#include "window/main_window.h"

namespace linkage::ui {

void MainWindow::createActions() {
  createFileActions();
  createEditActions();
  createViewActions();
  createAnimationActions();
  connect(makeAction("about", tr("&About Linkage"), QKeySequence(), tr("About this program")),
          &QAction::triggered, this, [this] {
            QMessageBox::about(this, tr("About Linkage"),
                               tr("<b>Linkage</b><br>A planar linkage editor with an exact "
                                  "kinematic core: positions, velocities and accelerations from "
                                  "the constraint Jacobian, instant centres by "
                                  "Kennedy-Aronhold."));
          });
}

void MainWindow::createFileActions() {
  connect(makeAction("new", tr("&New"), QKeySequence::New, tr("Start a new mechanism")),
          &QAction::triggered, this, [this] {
            if (maybeSave()) doc_->clear();
          });
  connect(makeAction("newWindow", tr("New &Window"), QKeySequence(tr("Ctrl+Shift+N")),
                     tr("Open another window, to compare two mechanisms side by side")),
          &QAction::triggered, this, [] {
            auto* w = new MainWindow;
            w->show();
          });
  connect(makeAction("open", tr("&Open..."), QKeySequence::Open, tr("Open a mechanism file")),
          &QAction::triggered, this, [this] {
            if (!maybeSave()) return;
            const QString path = QFileDialog::getOpenFileName(
                this, tr("Open Mechanism"), fileFolder(),
                tr("Mechanisms (*.linkage.json);;JSON files (*.json);;All files (*)"));
            if (!path.isEmpty()) openFile(path);
          });
  connect(makeAction("save", tr("&Save"), QKeySequence::Save, tr("Save the mechanism")),
          &QAction::triggered, this, &MainWindow::save);
  connect(makeAction("saveAs", tr("Save &As..."), QKeySequence(tr("Ctrl+Shift+S")),
                     tr("Save the mechanism under another name")),
          &QAction::triggered, this, &MainWindow::saveAs);
  connect(makeAction("exportTable", tr("Motion &Table (CSV)..."), QKeySequence(),
                     tr("Write the motion of the output points over revolutions as a CSV table")),
          &QAction::triggered, this, &MainWindow::exportMotionTable);
  connect(makeAction("exportFigure", tr("&Plot Figure..."), QKeySequence(),
                     tr("Write the plots as a PNG, PDF or SVG figure")),
          &QAction::triggered, this, &MainWindow::exportFigure);
  connect(makeAction("exportAnimation", tr("&Animation..."), QKeySequence(),
                     tr("Write the animation as a GIF or a numbered PNG sequence")),
          &QAction::triggered, this, &MainWindow::exportAnimation);
  connect(
      makeAction("closeWindow", tr("&Close Window"), QKeySequence::Close, tr("Close this window")),
      &QAction::triggered, this, &QWidget::close);
  QAction* quit = makeAction("quit", tr("&Quit"), QKeySequence::Quit, tr("Close every window"));
  quit->setMenuRole(QAction::QuitRole);
  connect(quit, &QAction::triggered, qApp, &QApplication::closeAllWindows);
}

void MainWindow::createEditActions() {
  QAction* undo = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setObjectName("undo");
  undo->setShortcut(QKeySequence::Undo);
  undo->setStatusTip(tr("Undo the last edit"));
  addAction(undo);
  QAction* redo = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setObjectName("redo");
  redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  redo->setStatusTip(tr("Redo the edit undone last"));
  addAction(redo);
}

void MainWindow::createViewActions() {
  connect(
      makeAction("fit", tr("&Fit to View"), QKeySequence(tr("F")), tr("Show the whole mechanism")),
      &QAction::triggered, view_, &CanvasView::fitToMechanism);
  connect(makeAction("zoomIn", tr("Zoom &In"), QKeySequence::ZoomIn, tr("Zoom in")),
          &QAction::triggered, this, [this] { view_->zoomBy(1.25); });
  connect(makeAction("zoomOut", tr("Zoom &Out"), QKeySequence::ZoomOut, tr("Zoom out")),
          &QAction::triggered, this, [this] { view_->zoomBy(0.8); });
  connect(makeAction("actualSize", tr("&Actual Size"), QKeySequence(tr("Ctrl+1")),
                     tr("A millimetre on the screen for a millimetre of the mechanism")),
          &QAction::triggered, this,
          [this] { view_->zoomBy(view_->actualSizeZoom() / view_->zoom()); });
  createOverlayActions();
  QAction* dark = makeAction("darkPalette", tr("&Dark Palette"), QKeySequence(),
                             tr("Light text on a dark background, for every window"));
  dark->setCheckable(true);
  connect(dark, &QAction::toggled, this, &MainWindow::setDarkPalette);
  QAction* detach = makeAction("detachablePanels", tr("&Detachable Panels"), QKeySequence(),
                               tr("Let the panels float out of the window"));
  detach->setCheckable(true);
  connect(detach, &QAction::toggled, this, [this](bool on) {
    for (QDockWidget* d : findChildren<QDockWidget*>())
      d->setFeatures(d->features().setFlag(QDockWidget::DockWidgetFloatable, on));
  });
}

// What is drawn over the mechanism, each toggled.
void MainWindow::createOverlayActions() {
  QAction* grid =
      makeAction("showGrid", tr("&Grid"), QKeySequence(tr("#")), tr("Show the millimetre grid"));
  grid->setCheckable(true);
  connect(grid, &QAction::toggled, view_, &CanvasView::setGridVisible);
  QAction* ics = makeAction("showCentres", tr("&Instant Centres"), QKeySequence(tr("I")),
                            tr("Show every instant centre; hover one for its Kennedy lines"));
  ics->setCheckable(true);
  connect(ics, &QAction::toggled, scene_, &CanvasScene::setCentresVisible);
  QAction* traces = makeAction("showTraces", tr("&Traced Paths"), QKeySequence(tr("Shift+T")),
                               tr("Show the paths of the output points over a revolution"));
  traces->setCheckable(true);
  connect(traces, &QAction::toggled, scene_, &CanvasScene::setTracesVisible);
  QAction* forces =
      makeAction("showForces", tr("&Forces"), QKeySequence(tr("Shift+F")),
                 tr("Show each joint's reaction at this angle, on one scale for the whole turn"));
  forces->setCheckable(true);
  connect(forces, &QAction::toggled, scene_, &CanvasScene::setForcesVisible);
}

void MainWindow::createAnimationActions() {
  QAction* play =
      makeAction("play", tr("&Play"), QKeySequence(tr("Space")), tr("Play or pause the animation"));
  play->setCheckable(true);
  connect(play, &QAction::triggered, this, [this, play](bool on) {
    animator_->setPlaying(on);
    // A refused start leaves the button unchecked (checked, the next press would pause).
    play->setChecked(animator_->playing());
  });
  connect(makeAction("stepForward", tr("Step &Forward"), QKeySequence(tr("Right")),
                     tr("Turn the crank one increment forward")),
          &QAction::triggered, this, [this] { animator_->step(+1); });
  connect(makeAction("stepBack", tr("Step &Back"), QKeySequence(tr("Left")),
                     tr("Turn the crank one increment back")),
          &QAction::triggered, this, [this] { animator_->step(-1); });
  connect(makeAction("toStart", tr("Back to &Start"), QKeySequence(tr("Home")),
                     tr("Turn the crank back to angle 0")),
          &QAction::triggered, this, [this] {
            animator_->setPlaying(false);
            if (doc_->solved()) doc_->setCrankDeg(0);
          });
  connect(makeAction("slower", tr("S&lower"), QKeySequence(tr("[")), tr("Slower slow motion")),
          &QAction::triggered, this,
          [this] { crankBar_->setSpeedIndex(crankBar_->speedBox()->currentIndex() + 1); });
  connect(makeAction("faster", tr("F&aster"), QKeySequence(tr("]")),
                     tr("Faster slow motion, up to real time")),
          &QAction::triggered, this,
          [this] { crankBar_->setSpeedIndex(crankBar_->speedBox()->currentIndex() - 1); });
}

void MainWindow::createMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(action("new"));
  file->addAction(action("newWindow"));
  file->addAction(action("open"));
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
  examplesMenu_ = file->addMenu(tr("&Examples"));
  fillExamplesMenu();
  file->addSeparator();
  file->addAction(action("save"));
  file->addAction(action("saveAs"));
  QMenu* exports = file->addMenu(tr("E&xport"));
  for (const char* a : {"exportTable", "exportFigure", "exportAnimation"})
    exports->addAction(action(a));
  file->addSeparator();
  file->addAction(action("closeWindow"));
  file->addAction(action("quit"));

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  edit->addAction(action("undo"));
  edit->addAction(action("redo"));
  edit->addSeparator();
  QAction* history = dock("history")->toggleViewAction();
  history->setObjectName("showHistory");
  history->setStatusTip(tr("Show every edit; click one to go back to it"));
  edit->addAction(history);

  edit->addSeparator();
  edit->addAction(toolbox_->deleteAction());
  edit->addAction(toolbox_->flipAction());

  QMenu* tools = menuBar()->addMenu(tr("&Tools"));
  for (QAction* a : toolbox_->toolActions()) tools->addAction(a);
  tools->addSeparator();
  tools->addAction(toolbox_->snapAction());

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (const char* a : {"fit", "zoomIn", "zoomOut", "actualSize"}) view->addAction(action(a));
  view->addSeparator();
  for (const char* a : {"showGrid", "showCentres", "showTraces", "showForces", "showExtremes",
                        "showTransmission", "darkPalette", "detachablePanels"})
    view->addAction(action(a));
  view->addSeparator();
  for (const char* d : {"properties", "centres", "plots", "forces", "designChecks", "mechanisms"})
    view->addAction(dock(d)->toggleViewAction());

  QMenu* anim = menuBar()->addMenu(tr("&Animation"));
  for (const char* a : {"play", "stepBack", "stepForward", "toStart"}) anim->addAction(action(a));
  anim->addSeparator();
  anim->addAction(action("slower"));
  anim->addAction(action("faster"));

  addForcesMenuEntries(addAnalysisMenu(), exports);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(action("about"));
}

void MainWindow::createToolBars() {
  QToolBar* file = addToolBar(tr("File"));
  file->setObjectName("fileToolBar");
  for (const char* a : {"new", "open", "save", "undo", "redo"}) file->addAction(action(a));
  QToolBar* tools = new QToolBar(tr("Tools"), this);
  tools->setObjectName("toolsToolBar");
  addToolBar(Qt::LeftToolBarArea, tools);
  for (QAction* a : toolbox_->toolActions()) tools->addAction(a);
  tools->addSeparator();
  tools->addAction(toolbox_->deleteAction());
  tools->addAction(toolbox_->flipAction());
  QToolBar* view = addToolBar(tr("View"));
  view->setObjectName("viewToolBar");
  for (const char* a : {"fit", "showGrid", "showCentres", "showTraces"}) view->addAction(action(a));
  QToolBar* anim = new QToolBar(tr("Animation"), this);
  anim->setObjectName("animationToolBar");
  addToolBar(Qt::BottomToolBarArea, anim);
  for (const char* a : {"play", "stepBack", "stepForward", "toStart"}) anim->addAction(action(a));
  crankBar_ = new CrankBar(animator_);
  anim->addWidget(crankBar_);
}

}  // namespace linkage::ui
