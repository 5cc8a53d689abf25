// The window's Mechanisms dock (issue 18): the machine's mechanisms, each named, shown or
// hidden and coloured (ui/mechanisms/mechanisms_panel.h), tabbed with the history on the left.
#include <QAction>
#include <QDockWidget>

#include "document/document.h"
#include "mechanisms/mechanisms_panel.h"
#include "window/main_window.h"

namespace linkage::ui {

void MainWindow::createMechanisms() {
  mechanisms_ = new MechanismsPanel;
  mechanisms_->setDocument(doc_, selection_);
  auto* dock = new QDockWidget(tr("Mechanisms"), this);
  dock->setObjectName("mechanisms");
  dock->setWidget(mechanisms_);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  addDockWidget(Qt::LeftDockWidgetArea, dock);
  tabifyDockWidget(this->dock("history"), dock);
  // Hidden until asked for (View > Mechanisms), as the history is.
  dock->hide();
  QAction* show = dock->toggleViewAction();
  show->setObjectName("showMechanisms");
  show->setShortcut(QKeySequence(tr("Shift+M")));
  show->setStatusTip(
      tr("The machine's mechanisms: name them, show or hide them, give each a colour"));
}

}  // namespace linkage::ui
