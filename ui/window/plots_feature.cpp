#include "window/plots_feature.h"

#include <QAction>
#include <QDockWidget>

#include "animation/animator.h"
#include "document/document.h"
#include "plots/plots_panel.h"
#include "window/main_window.h"
#include "window/window_layout.h"

namespace linkage::ui {

PlotsFeature::PlotsFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  panel_ = new PlotsPanel;
  dock = addDock(&w, "plots", tr("Plots"), panel_, Qt::BottomDockWidgetArea);
  show = dock->toggleViewAction();
  show->setObjectName("showPlots");
  show->setStatusTip(tr("Position, velocity and acceleration of a point against the crank angle"));
  Document* doc = w.document();
  panel_->setDocument(doc);
  Animator* animator = w.animator();
  connect(panel_, &PlotsPanel::crankAngleRequested, this, [animator, doc](double deg) {
    animator->setPlaying(false);
    if (doc->solved()) doc->setCrankDeg(deg);
  });
  layout.add(Slot::ViewPlotsDock, show);
}

}  // namespace linkage::ui
