#include "window/cycle_feature.h"

#include <QAction>
#include <QDockWidget>

#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "canvas/clearance_marks.h"
#include "cycle/cycle_panel.h"
#include "document/document.h"
#include "tools/toolbox.h"
#include "window/main_window.h"
#include "window/message_strip.h"
#include "window/plots_feature.h"
#include "window/tools_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

CycleFeature::CycleFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  makeDock();
  makeActions();
  layout.add(Slot::ViewCycleDock, dock->toggleViewAction());
  layout.add(Slot::AnalysisCycleDock, showPanel);
  layout.add(Slot::AnalysisWatchClearance, watchClearance);
  layout.add(Slot::ExportCycleFigure, exportFigure);
  layout.add(Slot::ExportTimingTable, exportTable);
}

void CycleFeature::makeDock() {
  panel_ = new CyclePanel(w_.document());
  dock = addDock(&w_, "cycle", tr("Cycle"), panel_, Qt::BottomDockWidgetArea);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  // Hidden until asked for (its diagram is computed while it is shown), then a tab of the plots.
  dock->hide();
  w_.tabifyDockWidget(w_.plots().dock, dock);
  showPanel = raisingToggle(dock, "showCyclePanel", QKeySequence(tr("Shift+C")),
                            tr("The machine's cycle diagram: rows, windows, conflicts and "
                               "clearances over a turn of the main shaft"));
  Animator* animator = w_.animator();
  Document* doc = w_.document();
  connect(panel_, &CyclePanel::crankAngleRequested, this, [animator, doc](double deg) {
    animator->setPlaying(false);
    if (doc->solved()) doc->setCrankDeg(deg);
  });
  // The window form's Pick: the canvas's next click on a point is the window's point.
  connect(panel_, &CyclePanel::pickPointRequested, this, [this](bool on) {
    Toolbox* tools = w_.tools().toolbox();
    if (!on) {
      if (tools->picking()) tools->setTool(QStringLiteral("select"));
      return;
    }
    tools->pickPoint(
        tr("the window's point"), [this](PointId p) { panel_->pointPicked(p); },
        [this] { panel_->pickEnded(); });
  });
  marks_ = new ClearanceMarksItem(w_.scene()->context());
  w_.scene()->addOverlay(marks_);
  connect(panel_, &CyclePanel::marksChanged, this,
          [this](const std::vector<ClearanceMark>& m) { marks_->setMarks(m); });
}

void CycleFeature::makeActions() {
  watchClearance = makeAction(
      &w_, "watchClearance", tr("&Watch Clearance"), QKeySequence(tr("Shift+W")),
      tr("Watch the clearance of what is selected over the cycle: two points, a point and a "
         "slot, or a point and two points of another body (the segment between them: a needle, "
         "a blade; Shift+click adds to the selection); its closest approach in the Cycle dock "
         "and on the canvas"));
  connect(watchClearance, &QAction::triggered, this, [this] {
    QString why;
    if (!panel_->watchSelection(*w_.tools().selection(), &why)) {
      w_.messageStrip()->setMessage(why, true);
      return;
    }
    dock->show();
    dock->raise();
  });
  exportFigure = makeAction(&w_, "exportCycleFigure", tr("C&ycle Diagram..."), QKeySequence(),
                            tr("Write the machine's cycle diagram as a PNG, PDF or SVG figure"));
  connect(exportFigure, &QAction::triggered, panel_, &CyclePanel::saveFigureAs);
  exportTable = makeAction(&w_, "exportTimingTable", tr("T&iming Table (CSV)..."), QKeySequence(),
                           tr("Write the windows' crank angles and the conflicts' overlaps as a "
                              "CSV table (what linkage-cli timing writes)"));
  connect(exportTable, &QAction::triggered, panel_, &CyclePanel::saveTableAs);
}

}  // namespace linkage::ui
