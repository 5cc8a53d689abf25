#include "window/sensitivity_feature.h"

#include <QAction>
#include <QDockWidget>

#include "design/optimize_dialog.h"
#include "design/sensitivity_panel.h"
#include "window/main_window.h"
#include "window/plots_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

SensitivityFeature::SensitivityFeature(MainWindow& w, WindowLayout& layout)
    : WindowFeature(&w), w_(w) {
  panel_ = new SensitivityPanel(w.document());
  dock = addDock(&w, "sensitivity", tr("Sensitivity"), panel_, Qt::BottomDockWidgetArea);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  dock->hide();
  w.tabifyDockWidget(w.plots().dock, dock);
  showPanel = raisingToggle(dock, "showSensitivity", QKeySequence(tr("Shift+S")),
                            tr("Which dimensions move the chosen output most: their exact "
                               "derivatives at this crank angle and over a turn, ranked"));
  showPanel->setText(tr("&Sensitivities"));
  layout.add(Slot::ViewSensitivityDock, dock->toggleViewAction());
  layout.add(Slot::AnalysisSensitivityDock, showPanel);
  findDimensions = makeAction(
      &w, "findDimensions", tr("Find &Dimensions..."), QKeySequence(tr("Ctrl+Shift+F")),
      tr("Find the dimensions or counterweights that meet targets (a stroke, a place, a path, a "
         "transmission angle, the shaking force, a clearance, a window's end): a search fed by "
         "the exact sensitivities, the result applied as one undo step"));
  connect(findDimensions, &QAction::triggered, this, [this] {
    OptimizeDialog* d = optimizeDialog();
    d->show();
    d->raise();
  });
  layout.add(Slot::AnalysisFindDimensions, findDimensions);
}

OptimizeDialog* SensitivityFeature::optimizeDialog() {
  if (!optimize_) optimize_ = new OptimizeDialog(w_.document(), &w_);
  return optimize_;
}

}  // namespace linkage::ui
