#include "window/mechanisms_feature.h"

#include <QAction>
#include <QDockWidget>

#include "mechanisms/mechanisms_panel.h"
#include "window/edit_feature.h"
#include "window/main_window.h"
#include "window/tools_feature.h"
#include "window/window_layout.h"

namespace linkage::ui {

MechanismsFeature::MechanismsFeature(MainWindow& w, WindowLayout& layout) : WindowFeature(&w) {
  panel = new MechanismsPanel;
  panel->setDocument(w.document(), w.tools().selection());
  dock = addDock(&w, "mechanisms", tr("Mechanisms"), panel, Qt::LeftDockWidgetArea);
  w.tabifyDockWidget(w.edit().historyDock, dock);
  // Hidden until asked for, as the history is.
  dock->hide();
  show = raisingToggle(
      dock, "showMechanisms", QKeySequence(tr("Shift+M")),
      tr("The machine's mechanisms: name them, show or hide them, give each a colour"));
  layout.add(Slot::ViewMechanismsDock, show);
}

}  // namespace linkage::ui
