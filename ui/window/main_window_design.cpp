// The window's design checks (issue 13): the extreme positions and transmission arcs on the
// canvas (View), the design-checks dock and the parameter study (Analysis).
#include <QAction>
#include <QDockWidget>
#include <QMenuBar>

#include "design/checks_panel.h"
#include "design/design_choices.h"
#include "design/design_overlays.h"
#include "design/study_dialog.h"
#include "window/main_window.h"

namespace linkage::ui {

void MainWindow::createDesignChecks() {
  choices_ = new DesignChoices(this);
  designOverlays_ = new DesignOverlays(scene_, choices_, this);
  designOverlays_->setDocument(doc_);
  QAction* extremes =
      makeAction("showExtremes", tr("&Extreme Positions"), QKeySequence(tr("Shift+E")),
                 tr("Draw the mechanism faintly where the chosen point (Design Checks) is at its "
                    "extremes, with the stroke"));
  extremes->setCheckable(true);
  connect(extremes, &QAction::toggled, designOverlays_, &DesignOverlays::setExtremesVisible);
  QAction* mu =
      makeAction("showTransmission", tr("Transmission &Angles"), QKeySequence(tr("Shift+A")),
                 tr("Show each transmission angle at its joint, red outside the band"));
  mu->setCheckable(true);
  connect(mu, &QAction::toggled, designOverlays_, &DesignOverlays::setTransmissionVisible);
  connect(makeAction("parameterStudy", tr("&Parameter Study..."), QKeySequence(),
                     tr("Vary one dimension over a range and compare the designs")),
          &QAction::triggered, this, [this] {
            StudyDialog* d = studyDialog();
            d->show();
            d->raise();
            d->activateWindow();
          });
  checks_ = new ChecksPanel(choices_);
  checks_->setDocument(doc_);
  auto* dock = new QDockWidget(tr("Design Checks"), this);
  dock->setObjectName("designChecks");
  dock->setWidget(checks_);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  // A tab beside the instant centres: under them the right side has no room for its tables.
  tabifyDockWidget(this->dock("centres"), dock);
  dock->hide();
  // Computed only while seen: a dock's visibility, not its widget's, says so (a tab behind
  // another is moved off the window, still "visible"). Queued, as the other docks' are.
  connect(dock, &QDockWidget::visibilityChanged, checks_, &ChecksPanel::setShown,
          Qt::QueuedConnection);
  QAction* show = dock->toggleViewAction();
  show->setObjectName("showDesignChecks");
  show->setShortcut(QKeySequence(tr("Shift+D")));
  show->setStatusTip(
      tr("Grashof's class of each four-bar loop, the transmission angles, the "
         "limit positions and stroke"));
  // Asked for, it comes to the front of its tabs (once the layout has taken it back).
  connect(
      show, &QAction::triggered, dock,
      [dock](bool on) {
        if (on) dock->raise();
      },
      Qt::QueuedConnection);
}

QMenu* MainWindow::addAnalysisMenu() {
  QMenu* analysis = menuBar()->addMenu(tr("A&nalysis"));
  analysis->addAction(action("showDesignChecks"));
  analysis->addAction(action("parameterStudy"));
  analysis->addSeparator();
  analysis->addAction(action("showExtremes"));
  analysis->addAction(action("showTransmission"));
  return analysis;
}

StudyDialog* MainWindow::studyDialog() {
  if (!study_) study_ = new StudyDialog(doc_, this);
  return study_;
}

}  // namespace linkage::ui
