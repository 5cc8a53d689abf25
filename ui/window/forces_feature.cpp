#include "window/forces_feature.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>

#include "animation/animator.h"
#include "canvas/canvas_scene.h"
#include "document/document.h"
#include "forces/balance_dialog.h"
#include "forces/force_rows.h"
#include "forces/forces_overlay.h"
#include "forces/forces_panel.h"
#include "properties/properties_panel.h"
#include "window/main_window.h"
#include "window/plots_feature.h"
#include "window/properties_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

ForcesFeature::ForcesFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w), w_(w) {
  makeDock();
  makeActions();
  // A link's mass and loads and a point's loads, in their Properties forms.
  for (const FormSection& s : forceSections()) w.properties().panel()->addSection(s);
  layout.add(Slot::ViewForces, show);
  layout.add(Slot::ViewForcesDock, dock->toggleViewAction());
  layout.add(Slot::AnalysisForcesDock, showPanel);
  layout.add(Slot::AnalysisForces, show);
  layout.add(Slot::AnalysisBalance, balance);
  layout.add(Slot::ExportForcesTable, exportTable);
  layout.add(Slot::ExportForcesFigure, exportFigure);
}

void ForcesFeature::makeDock() {
  panel_ = new ForcesPanel(w_.document());
  dock = addDock(&w_, "forces", tr("Forces"), panel_, Qt::BottomDockWidgetArea);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  w_.tabifyDockWidget(w_.plots().dock, dock);
  // Hidden until asked for: its curves are computed while it is shown.
  dock->hide();
  showPanel = raisingToggle(dock, "showForcesPanel", QKeySequence(tr("Shift+G")),
                            tr("The driver's torque, the shaking force and its polar diagram, "
                               "and a joint's reaction over a turn"));
  Animator* animator = w_.animator();
  Document* doc = w_.document();
  connect(panel_, &ForcesPanel::crankAngleRequested, this, [animator, doc](double deg) {
    animator->setPlaying(false);
    if (doc->solved()) doc->setCrankDeg(deg);
  });
}

void ForcesFeature::makeActions() {
  show =
      // Not "Forces": the dock of force plots (Shift+G) is; these are the arrows on the canvas.
      makeToggle(&w_, "showForces", tr("Joint &Reactions"), QKeySequence(tr("Shift+F")),
                 tr("Show each joint's reaction at this angle, on one scale for the whole turn"));
  overlay_ = new ForcesOverlay(w_.scene(), this);
  connect(show, &QAction::toggled, overlay_, &ForcesOverlay::setReactionsVisible);
  balance = makeAction(&w_, "balance", tr("&Balance..."), QKeySequence(),
                       tr("Counterweights on the links pinned to the ground that minimise the "
                          "peak shaking force, found exactly"));
  connect(balance, &QAction::triggered, this, [this] {
    if (!balance_) balance_ = new BalanceDialog(w_.document(), &w_);
    balance_->show();
    balance_->raise();
    balance_->activateWindow();
  });
  exportTable = makeAction(&w_, "exportForcesTable", tr("&Force Table (CSV)..."), QKeySequence(),
                           tr("Write the driver's torque, the shaking force and moment and every "
                              "joint's reaction over a turn as a CSV table"));
  connect(exportTable, &QAction::triggered, panel_, &ForcesPanel::saveTableAs);
  exportFigure = makeAction(&w_, "exportForcesFigure", tr("Force F&igure..."), QKeySequence(),
                            tr("Write the force plots as a PNG, PDF or SVG figure"));
  connect(exportFigure, &QAction::triggered, panel_, &ForcesPanel::saveFigureAs);
}

void ForcesFeature::readSettings(const QSettings& s) {
  show->setChecked(s.value(QStringLiteral("forces"), false).toBool());
}

void ForcesFeature::writeSettings(QSettings& s) const {
  s.setValue(QStringLiteral("forces"), show->isChecked());
}

}  // namespace linkage::ui
