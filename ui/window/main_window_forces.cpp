// The window's forces (issue 17): the Forces dock (force curves over a turn, tabbed with the
// plots), the Balance dialog (Analysis) and the force exports (File > Export). The reactions on
// the canvas are View > Forces (main_window_actions.cpp).
#include <QAction>
#include <QDockWidget>
#include <QMenu>

#include "animation/animator.h"
#include "document/document.h"
#include "forces/balance_dialog.h"
#include "forces/forces_panel.h"
#include "window/main_window.h"

namespace linkage::ui {

void MainWindow::createForces() {
  forces_ = new ForcesPanel(doc_);
  auto* dock = new QDockWidget(tr("Forces"), this);
  dock->setObjectName("forces");
  dock->setWidget(forces_);
  dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
  addDockWidget(Qt::BottomDockWidgetArea, dock);
  tabifyDockWidget(this->dock("plots"), dock);
  // Hidden until asked for: its curves are computed while it is shown.
  dock->hide();
  QAction* show = dock->toggleViewAction();
  show->setObjectName("showForcesPanel");
  show->setShortcut(QKeySequence(tr("Shift+G")));
  show->setStatusTip(
      tr("The driver's torque, the shaking force and its polar diagram, and a "
         "joint's reaction over a turn"));
  connect(
      show, &QAction::triggered, dock,
      [dock](bool on) {
        if (on) dock->raise();
      },
      Qt::QueuedConnection);
  connect(forces_, &ForcesPanel::crankAngleRequested, this, [this](double deg) {
    animator_->setPlaying(false);
    if (doc_->solved()) doc_->setCrankDeg(deg);
  });
  connect(makeAction("balance", tr("&Balance..."), QKeySequence(),
                     tr("Counterweights on the links pinned to the ground that minimise the "
                        "peak shaking force, found exactly")),
          &QAction::triggered, this, [this] {
            if (!balance_) balance_ = new BalanceDialog(doc_, this);
            balance_->show();
            balance_->raise();
            balance_->activateWindow();
          });
  connect(makeAction("exportForcesTable", tr("&Force Table (CSV)..."), QKeySequence(),
                     tr("Write the driver's torque, the shaking force and moment and every "
                        "joint's reaction over a turn as a CSV table")),
          &QAction::triggered, forces_, &ForcesPanel::saveTableAs);
  connect(makeAction("exportForcesFigure", tr("Force F&igure..."), QKeySequence(),
                     tr("Write the force plots as a PNG, PDF or SVG figure")),
          &QAction::triggered, forces_, &ForcesPanel::saveFigureAs);
}

void MainWindow::addForcesMenuEntries(QMenu* analysis, QMenu* exports) {
  analysis->addSeparator();
  analysis->addAction(action("showForcesPanel"));
  analysis->addAction(action("showForces"));
  analysis->addAction(action("balance"));
  exports->addAction(action("exportForcesTable"));
  exports->addAction(action("exportForcesFigure"));
}

}  // namespace linkage::ui
