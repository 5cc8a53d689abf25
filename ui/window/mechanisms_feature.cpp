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
  // Hidden until asked for, as the history is; hidden before it joins the history's tabs (made
  // a tab while shown, the layout kept room for it: a window asked for 1100 px stayed 1159).
  dock->hide();
  w.tabifyDockWidget(w.edit().historyDock, dock);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  show = raisingToggle(
      dock, "showMechanisms", QKeySequence(tr("Shift+M")),
      tr("The machine's mechanisms: name them, show or hide them, give each a colour"));
  layout.add(Slot::ViewMechanismsDock, show);
}

}  // namespace linkage::ui
